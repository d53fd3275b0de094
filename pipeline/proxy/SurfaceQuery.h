// Distance queries against a triangle surface, shared by the deviation check (DeviationCheck.h)
// and the covered-part test (CoveredParts.h). Internal to pipeline/proxy.
//
// Based on: closest point on a triangle after Ericson, Real-Time Collision Detection 5.1.5; a
// uniform grid of cells at least 2 * limit wide (a query reads at most 2 x 2 x 2 cells);
// triangles rejected first by their plane and edge planes (lower bounds of the distance).
// Coverage certifies a whole triangle lies within the limit of the surface: by convexity of
// the distance to one triangle (three corners within the limit of the same triangle), by the
// 1-Lipschitz distance (within d(centroid) + circumradius), else by bisecting its longest edge.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace hlod::surface {


[[gnu::noinline]] inline float distanceSquared(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                                        const glm::vec3& c) {
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    glm::vec3 q;
    if (d1 <= 0 && d2 <= 0) {
        q = a;
    } else {
        const glm::vec3 bp = p - b;
        const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
        const glm::vec3 cp = p - c;
        const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
        const float vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
        if (d3 >= 0 && d4 <= d3)
            q = b;
        else if (d6 >= 0 && d5 <= d6)
            q = c;
        else if (vc <= 0 && d1 >= 0 && d3 <= 0)
            q = a + ab * (d1 / (d1 - d3));
        else if (vb <= 0 && d2 >= 0 && d6 <= 0)
            q = a + ac * (d2 / (d2 - d6));
        else if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
            q = b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
        else {
            const float denom = va + vb + vc;
            q = denom != 0.0f ? a + ab * (vb / denom) + ac * (vc / denom) : a;
        }
    }
    const glm::vec3 d = p - q;
    return glm::dot(d, d);
}

constexpr std::uint32_t kNoTriangle = 0xffffffffu;
// Share of the limit left to the pieces Coverage accepts without a common triangle.
constexpr float kSlackFraction = 1.0f / 32.0f;

// Corners and bounding planes of a triangle, stored together so a test reads two cache lines:
// its plane and the three planes through its edges perpendicular to it, facing out, each as
// an unnormalised normal n and offset n.x0, with n.n kept for the test. The triangle lies on
// its plane and behind each edge plane, so a point's distance to any of them is a lower bound
// of its distance to the triangle. Degenerate triangles get zero planes (which never reject).
struct Plane {
    glm::vec3 n;
    float offset, n2;
};

struct Triangle {
    glm::vec3 a, b, c;
    Plane plane, edge[3];
};

inline Plane planeThrough(const glm::vec3& normal, const glm::vec3& point) {
    return Plane{normal, glm::dot(normal, point), glm::dot(normal, normal)};
}

inline Triangle makeTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 n = glm::cross(b - a, c - a);
    Triangle tri{a, b, c, planeThrough(n, a), {}};
    tri.edge[0] = planeThrough(glm::cross(b - a, n), a);
    tri.edge[1] = planeThrough(glm::cross(c - b, n), b);
    tri.edge[2] = planeThrough(glm::cross(a - c, n), c);
    return tri;
}

// Whether `tri` lies within sqrt(limit2) of p. Most candidates are rejected by one of their
// planes (distance s / |n| beyond the limit, compared squared to avoid square roots); the
// 1e-4 slack leaves points near the limit to the exact test, so the answer is the exact one.
// Inlined into the query loops: most calls end at a plane test.
[[gnu::always_inline]] inline bool within(const Triangle& tri, const glm::vec3& p, float limit2) {
    const float reach2 = limit2 * 1.0002f;
    const float s = glm::dot(tri.plane.n, p) - tri.plane.offset;
    if (s * s > reach2 * tri.plane.n2) return false;
    for (const Plane& e : tri.edge) {
        const float d = glm::dot(e.n, p) - e.offset;
        if (d > 0.0f && d * d > reach2 * e.n2) return false;
    }
    return distanceSquared(p, tri.a, tri.b, tri.c) <= limit2;
}

struct GridFrame {
    glm::vec3 lo;
    float cell;
    glm::ivec3 dims;
};

// Cells at least 2 * limit wide (see header), at most 128 per axis over the box of `a`, and
// about as many cells as the grid holds triangles (more cells only cost memory to clear and
// prefix-sum: measured, a 128^3 grid per check was 40% of a bake).
inline GridFrame frameFor(std::span<const glm::vec3> positions, std::span<const std::uint32_t> a,
                   float limit, std::size_t triangles) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (std::uint32_t v : a) {
        lo = glm::min(lo, positions[v]);
        hi = glm::max(hi, positions[v]);
    }
    const glm::vec3 size = glm::max(hi - lo, glm::vec3(limit));
    const float extent = std::max({size.x, size.y, size.z});
    float cell = std::max(2.0f * limit, extent / 128.0f) * 1.0001f;
    const double maxCells = 512.0 + 2.0 * static_cast<double>(triangles);
    auto cellCount = [&](float c) {
        const glm::dvec3 n = glm::floor(glm::dvec3(size) / static_cast<double>(c)) + 3.0;
        return n.x * n.y * n.z;
    };
    while (cellCount(cell) > maxCells)
        cell *= 1.25f;
    lo -= glm::vec3(cell);
    return GridFrame{lo, cell, glm::ivec3(glm::floor((hi - lo) / cell)) + 2};
}

// Triangles per cell (CSR). Cells are at least 2 * limit wide, so the cells a query needs are
// at most two per axis. A triangle goes into every cell of its bounding box that its plane
// passes within half a cell diagonal of; triangles spanning too many cells stay in `big_`
// and are tested by every query. build() reuses the arrays of the previous build.
class TriangleGrid {
public:
    void build(std::span<const Triangle> tris, const GridFrame& frame) {
        tris_ = tris;
        lo_ = frame.lo;
        cell_ = frame.cell;
        inverseCell_ = 1.0f / frame.cell;
        dims_ = frame.dims;
        maxCell_ = glm::vec3(dims_ - 1);
        const std::size_t cells = static_cast<std::size_t>(dims_.x) * dims_.y * dims_.z;
        offsets_.assign(cells + 1, 0);
        big_.clear();
        boxes_.resize(tris.size());
        for (std::uint32_t t = 0; t < tris.size(); ++t) {
            const Triangle& tri = tris[t];
            CellBox& box = boxes_[t];
            box.c0 = cellOf(glm::min(tri.a, glm::min(tri.b, tri.c)));
            box.c1 = cellOf(glm::max(tri.a, glm::max(tri.b, tri.c)));
            const glm::ivec3 span = box.c1 - box.c0 + 1;
            box.count = static_cast<std::size_t>(span.x) * span.y * span.z;
            if (box.count > kMaxCellsPerTriangle) {
                big_.push_back(t);
                box.count = 0; // not filed in cells
                continue;
            }
            forEachCell(tri, box, [&](std::size_t cellId) { ++offsets_[cellId + 1]; });
        }
        for (std::size_t i = 1; i < offsets_.size(); ++i)
            offsets_[i] += offsets_[i - 1];
        items_.resize(offsets_.back());
        fill_.assign(offsets_.begin(), offsets_.end() - 1);
        for (std::uint32_t t = 0; t < tris.size(); ++t) {
            if (boxes_[t].count == 0) continue;
            forEachCell(tris[t], boxes_[t],
                        [&](std::size_t cellId) { items_[fill_[cellId]++] = t; });
        }
    }

    // Whether some triangle lies within `limit` of p; sets `found` to it.
    bool anyWithin(const glm::vec3& p, float limit, float limit2, std::uint32_t& found) const {
        const glm::ivec3 c0 = cellOf(p - glm::vec3(limit));
        const glm::ivec3 c1 = cellOf(p + glm::vec3(limit));
        for (int x = c0.x; x <= c1.x; ++x) {
            for (int y = c0.y; y <= c1.y; ++y) {
                for (int z = c0.z; z <= c1.z; ++z) {
                    const std::size_t c = (static_cast<std::size_t>(x) * dims_.y + y) * dims_.z + z;
                    for (std::uint32_t k = offsets_[c]; k < offsets_[c + 1]; ++k) {
                        if (isActive(items_[k]) && within(tris_[items_[k]], p, limit2)) {
                            found = items_[k];
                            return true;
                        }
                    }
                }
            }
        }
        for (std::uint32_t t : big_) {
            if (isActive(t) && within(tris_[t], p, limit2)) {
                found = t;
                return true;
            }
        }
        return false;
    }

    // The squared distance from p to the nearest triangle, if below limit2 (else limit2).
    float nearestDistance2(const glm::vec3& p, float limit, float limit2) const {
        float best = limit2;
        auto test = [&](std::uint32_t t) {
            if (!isActive(t)) return;
            const Triangle& tri = tris_[t];
            const float s = glm::dot(tri.plane.n, p) - tri.plane.offset;
            if (s * s >= best * tri.plane.n2) return;
            best = std::min(best, distanceSquared(p, tri.a, tri.b, tri.c));
        };
        const glm::ivec3 c0 = cellOf(p - glm::vec3(limit));
        const glm::ivec3 c1 = cellOf(p + glm::vec3(limit));
        for (int x = c0.x; x <= c1.x; ++x) {
            for (int y = c0.y; y <= c1.y; ++y) {
                for (int z = c0.z; z <= c1.z; ++z) {
                    const std::size_t c = (static_cast<std::size_t>(x) * dims_.y + y) * dims_.z + z;
                    for (std::uint32_t k = offsets_[c]; k < offsets_[c + 1]; ++k)
                        test(items_[k]);
                }
            }
        }
        for (std::uint32_t t : big_)
            test(t);
        return best;
    }

    // Whether some triangle lies within `limit` of all three points; sets `found` to it. Every
    // such triangle is within the limit of p0, so the cells around p0 hold them all.
    bool anyWithinAll(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, float limit,
                      float limit2, std::uint32_t& found) const {
        auto test = [&](std::uint32_t t) {
            if (!isActive(t)) return false;
            const Triangle& tri = tris_[t];
            // p0's cells hold triangles near p0: the other corners decide first.
            return within(tri, p1, limit2) && within(tri, p2, limit2) && within(tri, p0, limit2);
        };
        const glm::ivec3 c0 = cellOf(p0 - glm::vec3(limit));
        const glm::ivec3 c1 = cellOf(p0 + glm::vec3(limit));
        for (int x = c0.x; x <= c1.x; ++x) {
            for (int y = c0.y; y <= c1.y; ++y) {
                for (int z = c0.z; z <= c1.z; ++z) {
                    const std::size_t c = (static_cast<std::size_t>(x) * dims_.y + y) * dims_.z + z;
                    for (std::uint32_t k = offsets_[c]; k < offsets_[c + 1]; ++k) {
                        if (test(items_[k])) {
                            found = items_[k];
                            return true;
                        }
                    }
                }
            }
        }
        for (std::uint32_t t : big_) {
            if (test(t)) {
                found = t;
                return true;
            }
        }
        return false;
    }

    // Only triangles whose flag is set take part in queries (null: all).
    void setActive(const std::uint8_t* active) { active_ = active; }
    bool isActive(std::uint32_t t) const { return active_ == nullptr || active_[t] != 0; }

private:
    static constexpr std::size_t kMaxCellsPerTriangle = 4096;
    const std::uint8_t* active_ = nullptr;

    struct CellBox {
        glm::ivec3 c0, c1;
        std::size_t count; // cells of the box; 0 when in big_
    };

    // Cell of a point, clamped to the grid. Clamping the float to [0, dims - 1] first makes
    // truncation equal to floor (and cannot overflow), which is cheaper than std::floor.
    glm::ivec3 cellOf(const glm::vec3& p) const {
        return glm::ivec3(glm::clamp((p - lo_) * inverseCell_, glm::vec3(0.0f), maxCell_));
    }

    // Calls visit(cell) for every cell a triangle is filed under: all cells of its box when
    // there are at most 8, else those its plane passes within half a cell diagonal of.
    template <class F> void forEachCell(const Triangle& tri, const CellBox& box, F&& visit) const {
        const bool cull = box.count > 8 && tri.plane.n2 > 0.0f;
        const glm::vec3 unit = cull ? tri.plane.n / std::sqrt(tri.plane.n2) : glm::vec3(0.0f);
        const float offset = glm::dot(unit, tri.a);
        const float reach = cell_ * 0.8661f; // half the cell diagonal
        for (int x = box.c0.x; x <= box.c1.x; ++x) {
            for (int y = box.c0.y; y <= box.c1.y; ++y) {
                for (int z = box.c0.z; z <= box.c1.z; ++z) {
                    if (cull) {
                        const glm::vec3 centre = lo_ + (glm::vec3(x, y, z) + 0.5f) * cell_;
                        const float d = glm::dot(unit, centre) - offset;
                        if (std::abs(d) > reach) continue;
                    }
                    visit((static_cast<std::size_t>(x) * dims_.y + y) * dims_.z + z);
                }
            }
        }
    }

    std::span<const Triangle> tris_;
    glm::vec3 lo_{0.0f};
    float cell_ = 1.0f, inverseCell_ = 1.0f;
    glm::ivec3 dims_{1};
    glm::vec3 maxCell_{0.0f};
    std::vector<std::uint32_t> offsets_, items_, big_, fill_;
    std::vector<CellBox> boxes_;
};

// "Is p within `limit` of this mesh?" for a stream of nearby points: the triangle that
// answered the previous query is tried first (consecutive samples are usually on the same
// triangle), then the grid. Every answer is exact: the grid yields every triangle that can be
// within the limit. reset() reuses the arrays of the previous mesh.
class NearSurface {
public:
    void reset(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
               float limit) {
        limit_ = limit;
        limit2_ = limit * limit;
        hint_ = kNoTriangle;
        const std::size_t triangles = indices.size() / 3;
        tris_.resize(triangles);
        for (std::size_t t = 0; t < triangles; ++t) {
            tris_[t] = makeTriangle(positions[indices[3 * t]], positions[indices[3 * t + 1]],
                                    positions[indices[3 * t + 2]]);
        }
        grid_.build(tris_, frameFor(positions, indices, limit, triangles));
    }

    void setActive(const std::uint8_t* active) {
        grid_.setActive(active);
        hint_ = kNoTriangle;
    }

    bool near(const glm::vec3& p) {
        if (hint_ != kNoTriangle && grid_.isActive(hint_) && within(tris_[hint_], p, limit2_))
            return true;
        return grid_.anyWithin(p, limit_, limit2_, hint_);
    }
    // The triangle that answered the last successful near().
    std::uint32_t lastFound() const { return hint_; }
    // Whether one triangle lies within the limit of all three points (the last answer first).
    bool nearAll(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
        if (hint_ != kNoTriangle && grid_.isActive(hint_) && within(tris_[hint_], a, limit2_) &&
            within(tris_[hint_], b, limit2_) && within(tris_[hint_], c, limit2_))
            return true;
        return grid_.anyWithinAll(a, b, c, limit_, limit2_, hint_);
    }
    // Distance from p to the surface when below the limit (else the limit).
    float distance(const glm::vec3& p) const {
        return std::sqrt(grid_.nearestDistance2(p, limit_, limit2_));
    }
    float limit() const { return limit_; }
    // Distance from p to triangle t.
    float distanceTo(std::uint32_t t, const glm::vec3& p) const {
        const Triangle& tri = tris_[t];
        return std::sqrt(distanceSquared(p, tri.a, tri.b, tri.c));
    }
    // Whether triangle t lies within the limit of p (and takes part in queries).
    bool nearTriangle(std::uint32_t t, const glm::vec3& p) const {
        return grid_.isActive(t) && within(tris_[t], p, limit2_);
    }

private:
    float limit_ = 0.0f, limit2_ = 0.0f;
    std::vector<Triangle> tris_;
    std::uint32_t hint_ = kNoTriangle;
    TriangleGrid grid_;
};

// Certifies that the whole triangle abc lies within the surface's limit (plus `slack`):
// by convexity of the distance to one triangle, abc is within the limit of a triangle T when
// its three corners are, so a triangle whose corners share such a T is done; otherwise its
// longest edge is bisected and both halves are certified. A piece whose longest edge is at
// most `slack` is accepted once its corners are near the surface (every point of it is within
// slack of a corner). `hints` are triangles to try first. Returns false with `failAt` set when
// a corner is far from the surface, or when the piece budget runs out (conservative).
class Coverage {
public:
    Coverage(NearSurface& surface, float slack) : surface_(surface), slack2_(slack * slack) {}

    bool covers(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                std::span<const std::uint32_t> hints, glm::vec3& failAt) {
        for (std::uint32_t t : hints) {
            if (t != kNoTriangle && surface_.nearTriangle(t, a) && surface_.nearTriangle(t, b) &&
                surface_.nearTriangle(t, c))
                return true;
        }
        budget_ = kPieceBudget;
        const Corner ca{a, kNoTriangle}, cb{b, kNoTriangle}, cc{c, kNoTriangle};
        return piece(ca, cb, cc, 0, failAt);
    }

private:
    static constexpr int kMaxDepth = 48;
    static constexpr int kPieceBudget = 1 << 14;

    // A piece's corner and a surface triangle within the limit of it (once known), so that
    // the halves of a piece query only their new midpoint.
    struct Corner {
        glm::vec3 p;
        std::uint32_t near;
    };

    bool locate(Corner& c, glm::vec3& failAt) {
        if (c.near != kNoTriangle) return true;
        if (!surface_.near(c.p)) {
            failAt = c.p;
            return false;
        }
        c.near = surface_.lastFound();
        return true;
    }

    bool piece(Corner a, Corner b, Corner c, int depth, glm::vec3& failAt) {
        Corner* corner[3] = {&a, &b, &c};
        for (int k = 0; k < 3; ++k)
            if (!locate(*corner[k], failAt)) return false;
        // One corner's triangle within the limit of the other two: convexity.
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t t = corner[k]->near;
            if (surface_.nearTriangle(t, corner[(k + 1) % 3]->p) &&
                surface_.nearTriangle(t, corner[(k + 2) % 3]->p))
                return true;
        }
        // Distance to a surface is 1-Lipschitz: the piece lies within d(g) + r of it, r the
        // largest distance from its centroid g to a corner, d(g) at most the distance to any
        // one triangle (first the corners', then the nearest).
        const glm::vec3 g = (a.p + b.p + c.p) / 3.0f;
        const float r = std::sqrt(std::max({glm::dot(a.p - g, a.p - g), glm::dot(b.p - g, b.p - g),
                                            glm::dot(c.p - g, c.p - g)}));
        const float limit = surface_.limit();
        if (r < limit) {
            for (int k = 0; k < 3; ++k)
                if (surface_.distanceTo(corner[k]->near, g) + r <= limit) return true;
            if (r < 0.5f * limit && surface_.distance(g) + r <= limit) return true;
        }
        if (r < 2.0f * limit && surface_.nearAll(a.p, b.p, c.p)) return true;
        const float ab = glm::dot(b.p - a.p, b.p - a.p), bc = glm::dot(c.p - b.p, c.p - b.p),
                    ca = glm::dot(a.p - c.p, a.p - c.p);
        const float longest = std::max({ab, bc, ca});
        if (longest <= slack2_) return true;
        if (depth >= kMaxDepth || --budget_ <= 0) {
            failAt = g;
            return false;
        }
        // Bisect the longest edge; the midpoint is located once for both halves.
        Corner m{longest == ab ? (a.p + b.p) * 0.5f
                 : longest == bc ? (b.p + c.p) * 0.5f
                                 : (c.p + a.p) * 0.5f,
                 kNoTriangle};
        if (!locate(m, failAt)) return false;
        if (longest == ab) return piece(a, m, c, depth + 1, failAt) && piece(m, b, c, depth + 1, failAt);
        if (longest == bc) return piece(a, b, m, depth + 1, failAt) && piece(a, m, c, depth + 1, failAt);
        return piece(a, b, m, depth + 1, failAt) && piece(m, b, c, depth + 1, failAt);
    }

    NearSurface& surface_;
    float slack2_;
    int budget_ = 0;
};


} // namespace hlod::surface
