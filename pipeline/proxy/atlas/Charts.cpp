// Region-growing charts with planar projection, see Charts.h.
#include "pipeline/proxy/atlas/Charts.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <numeric>
#include <unordered_map>

namespace hlod {

namespace {

struct Tri2 {
    glm::vec2 p[3];
};

// Interiors overlap: no separating axis among the six edge normals, with a tolerance so that
// triangles sharing an edge or a corner (they touch) do not count.
bool overlap2d(const Tri2& a, const Tri2& b, float eps) {
    for (const Tri2* t : {&a, &b}) {
        for (int e = 0; e < 3; ++e) {
            const glm::vec2 d = t->p[(e + 1) % 3] - t->p[e];
            const glm::vec2 n(-d.y, d.x);
            const float len = glm::length(n);
            if (!(len > 0.0f)) continue;
            float amin = 1e30f, amax = -1e30f, bmin = 1e30f, bmax = -1e30f;
            for (int k = 0; k < 3; ++k) {
                const float pa = glm::dot(a.p[k], n) / len, pb = glm::dot(b.p[k], n) / len;
                amin = std::min(amin, pa);
                amax = std::max(amax, pa);
                bmin = std::min(bmin, pb);
                bmax = std::max(bmax, pb);
            }
            if (amax <= bmin + eps || bmax <= amin + eps) return false;
        }
    }
    return true;
}

// Cells of a 2D grid hashed to the triangles whose bounding boxes touch them.
class Grid2 {
public:
    explicit Grid2(float cell) : inv_(1.0f / cell) {}
    template <class F> bool anyNear(const Tri2& t, F&& test) const {
        bool found = false;
        forCells(t, [&](std::int64_t key) {
            if (found) return;
            auto it = cells_.find(key);
            if (it == cells_.end()) return;
            for (std::uint32_t other : it->second)
                if (test(other)) {
                    found = true;
                    return;
                }
        });
        return found;
    }
    void insert(const Tri2& t, std::uint32_t id) {
        forCells(t, [&](std::int64_t key) { cells_[key].push_back(id); });
    }

private:
    template <class F> void forCells(const Tri2& t, F&& f) const {
        glm::vec2 lo = glm::min(glm::min(t.p[0], t.p[1]), t.p[2]);
        glm::vec2 hi = glm::max(glm::max(t.p[0], t.p[1]), t.p[2]);
        const auto x0 = static_cast<std::int64_t>(std::floor(lo.x * inv_));
        const auto x1 = static_cast<std::int64_t>(std::floor(hi.x * inv_));
        const auto y0 = static_cast<std::int64_t>(std::floor(lo.y * inv_));
        const auto y1 = static_cast<std::int64_t>(std::floor(hi.y * inv_));
        if ((x1 - x0 + 1) * (y1 - y0 + 1) > 4096) { // a huge triangle: one shared cell
            f(std::numeric_limits<std::int64_t>::min());
            return;
        }
        for (auto y = y0; y <= y1; ++y)
            for (auto x = x0; x <= x1; ++x)
                f((y << 32) ^ (x & 0xffffffffll));
    }
    float inv_;
    std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
};

// Triangles sharing an edge, with corners welded by position (proxies split vertices at
// creases; a chart may still cross such an edge).
std::vector<std::vector<std::uint32_t>> edgeNeighbours(std::span<const glm::vec3> positions,
                                                       std::span<const std::uint32_t> indices) {
    std::map<std::tuple<float, float, float>, std::uint32_t> weld;
    std::vector<std::uint32_t> welded(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const glm::vec3& p = positions[i];
        welded[i] = weld.emplace(std::make_tuple(p.x, p.y, p.z), weld.size()).first->second;
    }
    const std::size_t n = indices.size() / 3;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> edges;
    for (std::size_t t = 0; t < n; ++t)
        for (int k = 0; k < 3; ++k) {
            std::uint32_t a = welded[indices[3 * t + k]], b = welded[indices[3 * t + (k + 1) % 3]];
            if (a == b) continue;
            edges[{std::min(a, b), std::max(a, b)}].push_back(static_cast<std::uint32_t>(t));
        }
    std::vector<std::vector<std::uint32_t>> out(n);
    for (const auto& [edge, tris] : edges)
        for (std::uint32_t a : tris)
            for (std::uint32_t b : tris)
                if (a != b) out[a].push_back(b);
    for (auto& list : out) {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    return out;
}

// An orthonormal basis of the plane orthogonal to `n` (Frisvad-style, deterministic).
void planeBasis(const glm::vec3& n, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    u = glm::normalize(glm::cross(helper, n));
    v = glm::cross(n, u);
}

// Rotates the chart's coordinates to the smallest bounding rectangle and moves them to start
// at (0, 0); returns the rectangle's size.
glm::vec2 fitRectangle(std::vector<glm::vec2*>& points) {
    float bestArea = std::numeric_limits<float>::max(), bestAngle = 0.0f;
    for (int step = 0; step < 16; ++step) {
        const float a = static_cast<float>(step) * 3.14159265f / 32.0f;
        const float c = std::cos(a), s = std::sin(a);
        glm::vec2 lo(1e30f), hi(-1e30f);
        for (const glm::vec2* p : points) {
            const glm::vec2 r(c * p->x - s * p->y, s * p->x + c * p->y);
            lo = glm::min(lo, r);
            hi = glm::max(hi, r);
        }
        const float area = (hi.x - lo.x) * (hi.y - lo.y);
        if (area < bestArea * 0.999f) {
            bestArea = area;
            bestAngle = a;
        }
    }
    const float c = std::cos(bestAngle), s = std::sin(bestAngle);
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (glm::vec2* p : points) {
        *p = glm::vec2(c * p->x - s * p->y, s * p->x + c * p->y);
        lo = glm::min(lo, *p);
        hi = glm::max(hi, *p);
    }
    for (glm::vec2* p : points)
        *p -= lo;
    return points.empty() ? glm::vec2(0.0f) : hi - lo;
}

} // namespace

Charting buildCharts(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                     float maxNormalDegrees) {
    const std::size_t n = indices.size() / 3;
    Charting out;
    out.chartOf.assign(n, 0xffffffffu);
    out.cornerCoords.assign(n * 3, glm::vec2(0.0f));
    if (n == 0) return out;
    std::vector<glm::vec3> normal(n);
    std::vector<float> area(n);
    double edgeSum = 0.0;
    for (std::size_t t = 0; t < n; ++t) {
        const glm::vec3 a = positions[indices[3 * t]], b = positions[indices[3 * t + 1]],
                        c = positions[indices[3 * t + 2]];
        const glm::vec3 cr = glm::cross(b - a, c - a);
        const float len = glm::length(cr);
        area[t] = 0.5f * len;
        normal[t] = len > 0.0f ? cr / len : glm::vec3(0.0f);
        edgeSum += glm::length(b - a) + glm::length(c - b) + glm::length(a - c);
    }
    const float cell = std::max(static_cast<float>(edgeSum / (3.0 * n)) * 2.0f, 1e-6f);
    const std::vector<std::vector<std::uint32_t>> neighbours = edgeNeighbours(positions, indices);
    std::vector<std::uint32_t> seeds(n);
    std::iota(seeds.begin(), seeds.end(), 0u);
    std::stable_sort(seeds.begin(), seeds.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return area[a] > area[b]; });
    const float minDot = std::cos(glm::radians(maxNormalDegrees));
    std::vector<Tri2> flat(n);
    for (std::uint32_t seed : seeds) {
        if (out.chartOf[seed] != 0xffffffffu) continue;
        const auto id = static_cast<std::uint32_t>(out.charts.size());
        out.charts.emplace_back();
        Chart& chart = out.charts.back();
        const glm::vec3 axis = normal[seed] != glm::vec3(0.0f) ? normal[seed] : glm::vec3(0, 0, 1);
        glm::vec3 u, v;
        planeBasis(axis, u, v);
        const glm::vec3 o = positions[indices[3 * seed]];
        Grid2 grid(cell);
        const float eps = cell * 1e-4f;
        std::deque<std::uint32_t> queue{seed};
        while (!queue.empty()) {
            const std::uint32_t t = queue.front();
            queue.pop_front();
            if (out.chartOf[t] != 0xffffffffu) continue;
            if (t != seed && area[t] > 0.0f && glm::dot(normal[t], axis) < minDot) continue;
            Tri2 tri;
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 d = positions[indices[3 * t + k]] - o;
                tri.p[k] = glm::vec2(glm::dot(d, u), glm::dot(d, v));
            }
            if (t != seed && area[t] > 0.0f &&
                grid.anyNear(tri, [&](std::uint32_t other) {
                    return overlap2d(tri, flat[other], eps);
                }))
                continue;
            out.chartOf[t] = id;
            flat[t] = tri;
            chart.triangles.push_back(t);
            if (area[t] > 0.0f) grid.insert(tri, t);
            for (std::uint32_t nb : neighbours[t])
                if (out.chartOf[nb] == 0xffffffffu) queue.push_back(nb);
        }
        std::vector<glm::vec2*> points;
        for (std::uint32_t t : chart.triangles)
            for (int k = 0; k < 3; ++k) {
                out.cornerCoords[3 * t + k] = flat[t].p[k];
                points.push_back(&out.cornerCoords[3 * t + k]);
            }
        chart.size = fitRectangle(points);
    }
    return out;
}

} // namespace hlod
