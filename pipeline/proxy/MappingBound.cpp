// The local two-sided bound of one edge collapse by successive mapping, see MappingBound.h.
#include "pipeline/proxy/MappingBound.h"

#include <algorithm>
#include <cmath>

namespace hlod {

namespace {

// A face before or after must face the projection direction at least this much (cosine of
// the angle between its normal and n): heights over a face seen nearly edge-on are unstable.
constexpr double kMinFacing = 0.02;
constexpr double kTwoPi = 6.283185307179586;

double orient(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Local number of vertex `id`, added when new.
std::uint32_t localOf(MappingScratch& s, std::uint32_t id) {
    for (std::uint32_t i = 0; i < s.ids.size(); ++i)
        if (s.ids[i] == id) return i;
    s.ids.push_back(id);
    return static_cast<std::uint32_t>(s.ids.size() - 1);
}

// Whether a face of the given 3D doubled area and projected (signed, doubled) area faces n
// enough; degenerate faces before the collapse (no area) cover nothing and are let through.
bool facesDirection(double area3, double projected, bool allowDegenerate) {
    if (!(area3 > 0.0)) return allowDegenerate;
    return projected > kMinFacing * area3;
}

} // namespace

double collapseBound(const CollapseRing& ring, MappingScratch& s, double giveUp) {
    s.ids.clear();
    s.beforeLocal.clear();
    s.afterLocal.clear();
    s.ids.push_back(kNewVertex); // local 0
    for (const auto& f : ring.before)
        s.beforeLocal.push_back({localOf(s, f[0]), localOf(s, f[1]), localOf(s, f[2])});
    for (const auto& f : ring.after)
        s.afterLocal.push_back({localOf(s, f[0]), localOf(s, f[1]), localOf(s, f[2])});
    const glm::dvec3 origin(ring.at);
    auto world = [&](std::uint32_t id) {
        if (id == kNewVertex) return glm::dvec3(0.0);
        return glm::dvec3(id == ring.from ? ring.fromAt : ring.positions[id]) - origin;
    };
    // Projection direction: the area-weighted normal of the faces before; when some face does
    // not face it, the mean of their unit normals.
    auto project = [&](bool unitWeights) {
        glm::dvec3 sum(0.0);
        for (const auto& f : s.beforeLocal) {
            const glm::dvec3 a = world(s.ids[f[0]]), b = world(s.ids[f[1]]), c = world(s.ids[f[2]]);
            const glm::dvec3 nf = glm::cross(b - a, c - a);
            const double l = glm::length(nf);
            if (unitWeights) {
                if (l > 0.0) sum += nf / l;
            } else {
                sum += nf;
            }
        }
        const double len = glm::length(sum);
        if (!(len > 0.0) || !std::isfinite(len)) return false;
        const glm::dvec3 n = sum / len;
        s.direction = n;
        const glm::dvec3 e1 = glm::normalize(glm::cross(
            n, std::abs(n.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0)));
        const glm::dvec3 e2 = glm::cross(n, e1);
        s.plane.resize(s.ids.size());
        for (std::uint32_t i = 0; i < s.ids.size(); ++i) {
            const glm::dvec3 q = world(s.ids[i]);
            s.plane[i] = glm::dvec3(glm::dot(q, e1), glm::dot(q, e2), glm::dot(q, n));
        }
        // Both triangulations must project one-to-one onto the same polygon: every face
        // facing n, the same area, and the fan around the new vertex winding once.
        double areaBefore = 0.0, areaAfter = 0.0;
        for (const auto& f : s.beforeLocal) {
            const glm::dvec3 a = world(s.ids[f[0]]), b = world(s.ids[f[1]]), c = world(s.ids[f[2]]);
            const double o = orient(s.plane[f[0]], s.plane[f[1]], s.plane[f[2]]);
            if (!facesDirection(glm::length(glm::cross(b - a, c - a)), o, true)) return false;
            areaBefore += o;
        }
        double angle = 0.0;
        for (const auto& f : s.afterLocal) {
            const glm::dvec3 a = world(s.ids[f[0]]), b = world(s.ids[f[1]]), c = world(s.ids[f[2]]);
            const double o = orient(s.plane[f[0]], s.plane[f[1]], s.plane[f[2]]);
            if (!facesDirection(glm::length(glm::cross(b - a, c - a)), o, false)) return false;
            areaAfter += o;
            for (int k = 0; k < 3; ++k) {
                if (f[k] != 0) continue;
                const glm::dvec3 u = s.plane[f[(k + 1) % 3]] - s.plane[0];
                const glm::dvec3 w = s.plane[f[(k + 2) % 3]] - s.plane[0];
                angle += std::atan2(u.x * w.y - u.y * w.x, u.x * w.x + u.y * w.y);
            }
        }
        if (angle > kTwoPi * (1.0 + 1e-9)) return false;
        return std::abs(areaBefore - areaAfter) <= 1e-6 * std::max(areaBefore, areaAfter);
    };
    if (!project(false) && !project(true)) return INFINITY;

    // The corners of the overlay's cells: the new vertex (over a face before), the removed
    // vertices (under a face after), and the crossings of the edges at the removed vertices
    // with the edges at the new vertex; the link's vertices keep their bounds and f = 0 there.
    // On a cell the bound before (interpolated over its face before) plus |f| is convex and the
    // bound after (interpolated over its face after) linear, so the bound after covers the cell
    // when it covers its corners: each corner asks for a least bound at the new vertex.
    auto bound = [&](std::uint32_t local) {
        const std::uint32_t id = s.ids[local];
        if (id == kNewVertex) return 0.0;
        const double b = ring.vertexBounds.empty() ? 0.0 : double(ring.vertexBounds[id]);
        return id == ring.from ? b + ring.fromExtra : b;
    };
    double need = 0.0;
    // `weightNew` of the new vertex at a point where the rest of the bound after is `fixed`.
    // False when the collapse cannot be certified (or needs more than giveUp).
    auto require = [&](double required, double weightNew, double fixed) {
        if (weightNew > 1e-9) {
            need = std::max(need, (required - fixed) / weightNew);
            return !(need > giveUp);
        }
        return !(required > fixed + 1e-9 * (required + fixed)); // on the link: cannot grow
    };
    // The new vertex over the faces before.
    bool found = false;
    for (const auto& f : s.beforeLocal) {
        const glm::dvec3 &a = s.plane[f[0]], &b = s.plane[f[1]], &c = s.plane[f[2]];
        const double o = orient(a, b, c);
        if (!(o > 0.0)) continue;
        const glm::dvec3& q = s.plane[0];
        const double la = orient(q, b, c) / o, lb = orient(a, q, c) / o, lc = 1.0 - la - lb;
        if (la < -1e-9 || lb < -1e-9 || lc < -1e-9) continue;
        const double before = la * bound(f[0]) + lb * bound(f[1]) + lc * bound(f[2]);
        const double h = la * a.z + lb * b.z + lc * c.z;
        if (!require(before + std::abs(h - q.z), 1.0, 0.0)) return INFINITY;
        found = true;
    }
    if (!found) return INFINITY;
    // The removed vertices over the faces after.
    for (std::uint32_t id : {ring.from, ring.to}) {
        std::uint32_t v = 0;
        while (v < s.ids.size() && s.ids[v] != id)
            ++v;
        if (v == s.ids.size()) return INFINITY;
        const glm::dvec3& q = s.plane[v];
        bool inside = false;
        for (const auto& f : s.afterLocal) {
            const glm::dvec3 &a = s.plane[f[0]], &b = s.plane[f[1]], &c = s.plane[f[2]];
            const double o = orient(a, b, c);
            const double l[3] = {orient(q, b, c) / o, orient(a, q, c) / o, 0.0};
            const double lam[3] = {l[0], l[1], 1.0 - l[0] - l[1]};
            if (lam[0] < -1e-9 || lam[1] < -1e-9 || lam[2] < -1e-9) continue;
            inside = true;
            double h = 0.0, weightNew = 0.0, fixed = 0.0;
            for (int k = 0; k < 3; ++k) {
                h += lam[k] * s.plane[f[k]].z;
                if (f[k] == 0)
                    weightNew = lam[k];
                else
                    fixed += lam[k] * bound(f[k]);
            }
            if (!require(bound(v) + std::abs(q.z - h), weightNew, fixed)) return INFINITY;
        }
        if (!inside) return INFINITY;
    }
    // Crossings of the spokes before (edges at a removed vertex) with the spokes after.
    const std::uint32_t lu = localOf(s, ring.from), lv = localOf(s, ring.to);
    s.oldEdges.clear();
    for (const auto& f : s.beforeLocal)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = std::min(f[k], f[(k + 1) % 3]);
            const std::uint32_t b = std::max(f[k], f[(k + 1) % 3]);
            if (a != lu && a != lv && b != lu && b != lv) continue;
            const std::array<std::uint32_t, 2> e{a, b};
            if (std::find(s.oldEdges.begin(), s.oldEdges.end(), e) == s.oldEdges.end())
                s.oldEdges.push_back(e);
        }
    s.newEnds.clear();
    for (const auto& f : s.afterLocal)
        for (std::uint32_t w : f)
            if (w != 0 && std::find(s.newEnds.begin(), s.newEnds.end(), w) == s.newEnds.end())
                s.newEnds.push_back(w);
    const glm::dvec3& p0 = s.plane[0];
    for (std::uint32_t w : s.newEnds) {
        const glm::dvec3 d = s.plane[w] - p0;
        const double bw = bound(w);
        for (const auto& e : s.oldEdges) {
            if (e[0] == w || e[1] == w) continue; // they meet at the link vertex only
            const glm::dvec3 &q0 = s.plane[e[0]], &q1 = s.plane[e[1]];
            const glm::dvec3 r = q1 - q0;
            const double denom = d.x * r.y - d.y * r.x;
            if (denom == 0.0) continue; // parallel: the overlap's ends are other corners
            const glm::dvec3 q = q0 - p0;
            const double t = (q.x * r.y - q.y * r.x) / denom; // along the spoke after
            const double u = (q.x * d.y - q.y * d.x) / denom; // along the edge before
            if (t < 0.0 || t > 1.0 || u < 0.0 || u > 1.0) continue;
            const double hAfter = p0.z + d.z * t, hBefore = q0.z + r.z * u;
            const double before = (1.0 - u) * bound(e[0]) + u * bound(e[1]);
            if (!require(before + std::abs(hAfter - hBefore), 1.0 - t, t * bw)) return INFINITY;
        }
    }
    return need;
}

} // namespace hlod
