// Distance queries against a triangle surface, shared by the deviation check (DeviationCheck.h)
// and the covered-part test (CoveredParts.h). Internal to pipeline/proxy.
//
// Based on: closest point on a triangle after Ericson, Real-Time Collision Detection 5.1.5; a
// uniform grid of cells at least 2 * limit wide (a query reads at most 2 x 2 x 2 cells);
// triangles rejected first by their plane and edge planes (lower bounds of the distance).
// Coverage certifies a whole triangle lies within the limit of the surface: by convexity of
// the distance to one triangle (three corners within the limit of the same triangle), by the
// 1-Lipschitz distance (within d(centroid) + circumradius), else by bisecting an edge (the
// longest whose ends share no such triangle).
// Speed without changing an answer: the grid keeps each filed triangle's plane by component,
// so a query rejects four candidates per step, and withinMask4 tests four points against one
// triangle; both run the scalar tests' float operations in the same order (SSE2, no
// contraction), so they answer bit for bit as within() does, and every query returns the
// same triangle it would one at a time (the hint NearSurface carries between queries steers
// later answers, so the order of queries and their answers is part of the result).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace hlod::surface {

// The point of triangle abc closest to p.
[[gnu::always_inline]] inline glm::vec3 closestPoint(const glm::vec3& p, const glm::vec3& a,
                                                     const glm::vec3& b, const glm::vec3& c) {
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
    return q;
}

[[gnu::always_inline]] inline float distanceSquared(const glm::vec3& p, const glm::vec3& a,
                                                    const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 d = p - closestPoint(p, a, b, c);
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
// Inlined into the query loops: most calls end at a plane test. The grid keeps each filed
// triangle's plane next to its number (TriangleGrid), so a query runs the first test
// (rejectedByPlane) on what it reads in order and reads the triangle only when that passes
// (withinPastPlane); the two together are within().
inline float reachSquared(float limit2) { return limit2 * 1.0002f; }

[[gnu::always_inline]] inline bool rejectedByPlane(const Plane& plane, const glm::vec3& p,
                                                   float reach2) {
    const float s = glm::dot(plane.n, p) - plane.offset;
    return s * s > reach2 * plane.n2;
}

[[gnu::always_inline]] inline bool withinPastPlane(const Triangle& tri, const glm::vec3& p,
                                                   float limit2, float reach2) {
    for (const Plane& e : tri.edge) {
        const float d = glm::dot(e.n, p) - e.offset;
        if (d > 0.0f && d * d > reach2 * e.n2) return false;
    }
    return distanceSquared(p, tri.a, tri.b, tri.c) <= limit2;
}

[[gnu::always_inline]] inline bool within(const Triangle& tri, const glm::vec3& p, float limit2) {
    const float reach2 = reachSquared(limit2);
    return !rejectedByPlane(tri.plane, p, reach2) && withinPastPlane(tri, p, limit2, reach2);
}

// Up to four points in lanes (x, y, z arrays of 4; unused lanes hold any finite value).
struct Points4 {
    alignas(16) float x[4], y[4], z[4];
};

// within(tri, p, limit2) for the four points of `p` at once: bit k of the result is lane k's
// answer. The same float operations in the same order as the scalar within() and
// distanceSquared() (SSE2 lanes are IEEE single precision, no contraction), so every answer
// is bit for bit the scalar one; the branches of distanceSquared become per-lane selects in
// the same priority.
inline unsigned withinMask4(const Triangle& tri, const Points4& p, float limit2) {
#if defined(__SSE2__)
    const float reach2 = reachSquared(limit2);
    const __m128 px = _mm_load_ps(p.x), py = _mm_load_ps(p.y), pz = _mm_load_ps(p.z);
    auto dot = [](const glm::vec3& n, __m128 x, __m128 y, __m128 z) {
        return _mm_add_ps(
            _mm_add_ps(_mm_mul_ps(_mm_set1_ps(n.x), x), _mm_mul_ps(_mm_set1_ps(n.y), y)),
            _mm_mul_ps(_mm_set1_ps(n.z), z));
    };
    const __m128 zero = _mm_setzero_ps();
    const __m128 s = _mm_sub_ps(dot(tri.plane.n, px, py, pz), _mm_set1_ps(tri.plane.offset));
    __m128 rejected = _mm_cmpgt_ps(_mm_mul_ps(s, s), _mm_set1_ps(reach2 * tri.plane.n2));
    for (const Plane& e : tri.edge) {
        const __m128 d = _mm_sub_ps(dot(e.n, px, py, pz), _mm_set1_ps(e.offset));
        rejected = _mm_or_ps(
            rejected, _mm_and_ps(_mm_cmpgt_ps(d, zero),
                                 _mm_cmpgt_ps(_mm_mul_ps(d, d), _mm_set1_ps(reach2 * e.n2))));
    }
    if (_mm_movemask_ps(rejected) == 0xf) return 0u;
    // distanceSquared, lane-wise.
    const glm::vec3 a = tri.a, b = tri.b, c = tri.c;
    const glm::vec3 ab = b - a, ac = c - a, cb = c - b;
    auto sub = [](__m128 x, float v) { return _mm_sub_ps(x, _mm_set1_ps(v)); };
    const __m128 apx = sub(px, a.x), apy = sub(py, a.y), apz = sub(pz, a.z);
    const __m128 d1 = dot(ab, apx, apy, apz), d2 = dot(ac, apx, apy, apz);
    const __m128 bpx = sub(px, b.x), bpy = sub(py, b.y), bpz = sub(pz, b.z);
    const __m128 d3 = dot(ab, bpx, bpy, bpz), d4 = dot(ac, bpx, bpy, bpz);
    const __m128 cpx = sub(px, c.x), cpy = sub(py, c.y), cpz = sub(pz, c.z);
    const __m128 d5 = dot(ab, cpx, cpy, cpz), d6 = dot(ac, cpx, cpy, cpz);
    const __m128 vc = _mm_sub_ps(_mm_mul_ps(d1, d4), _mm_mul_ps(d3, d2));
    const __m128 vb = _mm_sub_ps(_mm_mul_ps(d5, d2), _mm_mul_ps(d1, d6));
    const __m128 va = _mm_sub_ps(_mm_mul_ps(d3, d6), _mm_mul_ps(d5, d4));
    const __m128 d43 = _mm_sub_ps(d4, d3), d56 = _mm_sub_ps(d5, d6);
    auto le = [](__m128 x, __m128 y) { return _mm_cmple_ps(x, y); };
    auto ge = [](__m128 x, __m128 y) { return _mm_cmpge_ps(x, y); };
    auto all3 = [](__m128 x, __m128 y, __m128 z) { return _mm_and_ps(_mm_and_ps(x, y), z); };
    const __m128 c1 = _mm_and_ps(le(d1, zero), le(d2, zero));
    const __m128 c2 = _mm_and_ps(ge(d3, zero), le(d4, d3));
    const __m128 c3 = _mm_and_ps(ge(d6, zero), le(d5, d6));
    const __m128 c4 = all3(le(vc, zero), ge(d1, zero), le(d3, zero));
    const __m128 c5 = all3(le(vb, zero), ge(d2, zero), le(d6, zero));
    const __m128 c6 = all3(le(va, zero), ge(d43, zero), ge(d56, zero));
    const __m128 t4 = _mm_div_ps(d1, _mm_sub_ps(d1, d3));
    const __m128 t5 = _mm_div_ps(d2, _mm_sub_ps(d2, d6));
    const __m128 t6 = _mm_div_ps(d43, _mm_add_ps(d43, d56));
    const __m128 denom = _mm_add_ps(_mm_add_ps(va, vb), vc);
    const __m128 v = _mm_div_ps(vb, denom), w = _mm_div_ps(vc, denom);
    const __m128 inside = _mm_cmpneq_ps(denom, zero);
    auto select = [](__m128 m, __m128 x, __m128 y) {
        return _mm_or_ps(_mm_and_ps(m, x), _mm_andnot_ps(m, y));
    };
    __m128 q[3];
    for (int k = 0; k < 3; ++k) {
        const __m128 ak = _mm_set1_ps(a[k]), bk = _mm_set1_ps(b[k]), ck = _mm_set1_ps(c[k]);
        const __m128 abk = _mm_set1_ps(ab[k]), ack = _mm_set1_ps(ac[k]);
        __m128 r =
            select(inside, _mm_add_ps(_mm_add_ps(ak, _mm_mul_ps(abk, v)), _mm_mul_ps(ack, w)), ak);
        r = select(c6, _mm_add_ps(bk, _mm_mul_ps(_mm_set1_ps(cb[k]), t6)), r);
        r = select(c5, _mm_add_ps(ak, _mm_mul_ps(ack, t5)), r);
        r = select(c4, _mm_add_ps(ak, _mm_mul_ps(abk, t4)), r);
        r = select(c3, ck, r);
        r = select(c2, bk, r);
        q[k] = select(c1, ak, r);
    }
    const __m128 dx = _mm_sub_ps(px, q[0]), dy = _mm_sub_ps(py, q[1]), dz = _mm_sub_ps(pz, q[2]);
    const __m128 dist =
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
    const __m128 ok = _mm_andnot_ps(rejected, _mm_cmple_ps(dist, _mm_set1_ps(limit2)));
    return static_cast<unsigned>(_mm_movemask_ps(ok));
#else
    unsigned mask = 0;
    for (int k = 0; k < 4; ++k)
        if (within(tri, glm::vec3(p.x[k], p.y[k], p.z[k]), limit2)) mask |= 1u << k;
    return mask;
#endif
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
        // Plane copies, padded so that a block of four read at any item stays in the arrays.
        for (std::vector<float>* a : {&nx_, &ny_, &nz_, &offset_, &n2_})
            a->assign(offsets_.back() + 3, 0.0f);
        fill_.assign(offsets_.begin(), offsets_.end() - 1);
        for (std::uint32_t t = 0; t < tris.size(); ++t) {
            if (boxes_[t].count == 0) continue;
            forEachCell(tris[t], boxes_[t], [&](std::size_t cellId) {
                const std::uint32_t k = fill_[cellId]++;
                const Plane& plane = tris[t].plane;
                nx_[k] = plane.n.x, ny_[k] = plane.n.y, nz_[k] = plane.n.z;
                offset_[k] = plane.offset, n2_[k] = plane.n2;
                items_[k] = t;
            });
        }
    }

    // Whether some triangle lies within `limit` of p; sets `found` to it.
    bool anyWithin(const glm::vec3& p, float limit, float limit2, std::uint32_t& found) const {
        const float reach2 = reachSquared(limit2);
        const glm::ivec3 c0 = cellOf(p - glm::vec3(limit));
        const glm::ivec3 c1 = cellOf(p + glm::vec3(limit));
        for (int x = c0.x; x <= c1.x; ++x) {
            for (int y = c0.y; y <= c1.y; ++y) {
                for (int z = c0.z; z <= c1.z; ++z) {
                    const std::size_t c = (static_cast<std::size_t>(x) * dims_.y + y) * dims_.z + z;
                    const std::uint32_t end = offsets_[c + 1];
                    for (std::uint32_t k = offsets_[c]; k < end; k += 4) {
                        unsigned pass = planePasses4(k, end, p, reach2);
                        while (pass != 0) {
                            const unsigned lane = static_cast<unsigned>(__builtin_ctz(pass));
                            pass &= pass - 1;
                            const std::uint32_t t = items_[k + lane];
                            if (isActive(t) && withinPastPlane(tris_[t], p, limit2, reach2)) {
                                found = t;
                                return true;
                            }
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
        auto test = [&](std::uint32_t t, const Plane& plane) {
            const float s = glm::dot(plane.n, p) - plane.offset;
            if (s * s >= best * plane.n2) return;
            if (!isActive(t)) return;
            const Triangle& tri = tris_[t];
            best = std::min(best, distanceSquared(p, tri.a, tri.b, tri.c));
        };
        const glm::ivec3 c0 = cellOf(p - glm::vec3(limit));
        const glm::ivec3 c1 = cellOf(p + glm::vec3(limit));
        for (int x = c0.x; x <= c1.x; ++x) {
            for (int y = c0.y; y <= c1.y; ++y) {
                for (int z = c0.z; z <= c1.z; ++z) {
                    const std::size_t c = (static_cast<std::size_t>(x) * dims_.y + y) * dims_.z + z;
                    for (std::uint32_t k = offsets_[c]; k < offsets_[c + 1]; ++k)
                        test(items_[k], Plane{{nx_[k], ny_[k], nz_[k]}, offset_[k], n2_[k]});
                }
            }
        }
        for (std::uint32_t t : big_)
            test(t, tris_[t].plane);
        return best;
    }

    // Whether some triangle lies within `limit` of all three points; sets `found` to it. Every
    // such triangle is within the limit of p0, so the cells around p0 hold them all.
    bool anyWithinAll(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, float limit,
                      float limit2, std::uint32_t& found) const {
        const float reach2 = reachSquared(limit2);
        // The plane tests of all three points first (from the copy of the plane the cell
        // holds), then the rest; the answer is the conjunction, whatever the order.
        auto rest = [&](std::uint32_t t) {
            if (!isActive(t)) return false;
            const Triangle& tri = tris_[t];
            // p0's cells hold triangles near p0: the other corners decide first.
            return withinPastPlane(tri, p1, limit2, reach2) &&
                   withinPastPlane(tri, p2, limit2, reach2) &&
                   withinPastPlane(tri, p0, limit2, reach2);
        };
        auto test = [&](std::uint32_t t, const Plane& plane) {
            return !rejectedByPlane(plane, p1, reach2) && !rejectedByPlane(plane, p2, reach2) &&
                   !rejectedByPlane(plane, p0, reach2) && rest(t);
        };
        const glm::ivec3 c0 = cellOf(p0 - glm::vec3(limit));
        const glm::ivec3 c1 = cellOf(p0 + glm::vec3(limit));
        for (int x = c0.x; x <= c1.x; ++x) {
            for (int y = c0.y; y <= c1.y; ++y) {
                for (int z = c0.z; z <= c1.z; ++z) {
                    const std::size_t c = (static_cast<std::size_t>(x) * dims_.y + y) * dims_.z + z;
                    const std::uint32_t end = offsets_[c + 1];
                    for (std::uint32_t k = offsets_[c]; k < end; k += 4) {
                        unsigned pass = planePasses4(k, end, p1, reach2) &
                                        planePasses4(k, end, p2, reach2) &
                                        planePasses4(k, end, p0, reach2);
                        while (pass != 0) {
                            const unsigned lane = static_cast<unsigned>(__builtin_ctz(pass));
                            pass &= pass - 1;
                            if (rest(items_[k + lane])) {
                                found = items_[k + lane];
                                return true;
                            }
                        }
                    }
                }
            }
        }
        for (std::uint32_t t : big_) {
            if (test(t, tris_[t].plane)) {
                found = t;
                return true;
            }
        }
        return false;
    }

    // Bit k set when item `first + k` (below `end`) is not rejected by its plane for p: the
    // test of rejectedByPlane on four items at once, the same float operations per lane.
    [[gnu::always_inline]] unsigned planePasses4(std::uint32_t first, std::uint32_t end,
                                                 const glm::vec3& p, float reach2) const {
        const unsigned valid = end - first >= 4 ? 0xfu : (1u << (end - first)) - 1u;
#if defined(__SSE2__)
        const __m128 s = _mm_sub_ps(
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_loadu_ps(&nx_[first]), _mm_set1_ps(p.x)),
                                  _mm_mul_ps(_mm_loadu_ps(&ny_[first]), _mm_set1_ps(p.y))),
                       _mm_mul_ps(_mm_loadu_ps(&nz_[first]), _mm_set1_ps(p.z))),
            _mm_loadu_ps(&offset_[first]));
        const __m128 rejected = _mm_cmpgt_ps(
            _mm_mul_ps(s, s), _mm_mul_ps(_mm_set1_ps(reach2), _mm_loadu_ps(&n2_[first])));
        return ~static_cast<unsigned>(_mm_movemask_ps(rejected)) & valid;
#else
        unsigned pass = 0;
        for (unsigned k = 0; k < 4; ++k) {
            const std::uint32_t i = first + k;
            if ((valid >> k & 1u) &&
                !rejectedByPlane(Plane{{nx_[i], ny_[i], nz_[i]}, offset_[i], n2_[i]}, p, reach2))
                pass |= 1u << k;
        }
        return pass;
#endif
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
    // Parallel to items_: the plane of the triangle filed there (rejectedByPlane), by component.
    std::vector<float> nx_, ny_, nz_, offset_, n2_;
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
    // near() for each point in order, up to the first that is not near (false then): the same
    // answers and the same hint afterwards as those calls, with the hint tried on four points
    // at once (withinMask4).
    bool nearEach(std::span<const glm::vec3> points) {
        std::size_t i = 0;
        while (i < points.size()) {
            if (hint_ != kNoTriangle && grid_.isActive(hint_)) {
                const Triangle& tri = tris_[hint_];
                while (i < points.size()) {
                    const std::size_t n = std::min<std::size_t>(4, points.size() - i);
                    Points4 block;
                    for (std::size_t k = 0; k < 4; ++k) {
                        const glm::vec3& q = points[i + std::min(k, n - 1)];
                        block.x[k] = q.x, block.y[k] = q.y, block.z[k] = q.z;
                    }
                    const unsigned all = (1u << n) - 1u;
                    const unsigned missed = ~withinMask4(tri, block, limit2_) & all;
                    if (missed == 0) {
                        i += n;
                        continue;
                    }
                    i += static_cast<std::size_t>(__builtin_ctz(missed));
                    break;
                }
                if (i == points.size()) return true;
            }
            if (!grid_.anyWithin(points[i], limit_, limit2_, hint_)) return false;
            ++i;
        }
        return true;
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
// its three corners are, so a triangle whose corners share such a T is done; otherwise an edge
// is bisected (see piece()) and both halves are certified. A piece whose longest edge is at
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
        budget_ = pieceBudget(a, b, c);
        const Corner ca{a, kNoTriangle}, cb{b, kNoTriangle}, cc{c, kNoTriangle};
        return piece(ca, cb, cc, 0, failAt, Known{});
    }

    // The same, given for each corner a surface triangle within the limit of it (`near[k]`,
    // kNoTriangle when unknown: it is located then and written back). Callers that certify
    // many triangles over the same vertices keep these per vertex (valid until it moves), so
    // a corner is located once, not once per triangle it belongs to.
    bool covers(const glm::vec3 (&p)[3], std::uint32_t (&near)[3], glm::vec3& failAt) {
        Corner corner[3];
        for (int k = 0; k < 3; ++k) {
            corner[k] = Corner{p[k], near[k]};
            if (!locate(corner[k], failAt)) return false;
            near[k] = corner[k].near;
        }
        budget_ = pieceBudget(p[0], p[1], p[2]);
        return piece(corner[0], corner[1], corner[2], 0, failAt, Known{});
    }

private:
    static constexpr int kMaxDepth = 48;
    static constexpr int kPieceBudget = 1 << 14;

    // Pieces a certificate may cut: 2^14, and more for a triangle many limits wide (64 per
    // limit squared of its area), whose certificate must cut it down to about the limit
    // wherever the surface's triangles are that small (a 2 m face of a remeshed box over its
    // 7 mm voxel shell takes 16 k to 30 k pieces).
    int pieceBudget(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) const {
        const float limit = surface_.limit();
        const double area = 0.5 * static_cast<double>(glm::length(glm::cross(b - a, c - a)));
        const double scaled = 64.0 * area / (static_cast<double>(limit) * limit);
        if (!(scaled > 0.0)) return kPieceBudget;
        return kPieceBudget + static_cast<int>(std::min(scaled, double(1 << 24)));
    }

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

    // What a piece knows of its corners' triangles from its parent (see piece()): bit j of
    // asked[k] set when corner k's triangle was tested against corner j, bit j of within[k]
    // the answer.
    struct Known {
        unsigned asked[3] = {0, 0, 0}, within[3] = {0, 0, 0};
    };

    bool piece(Corner a, Corner b, Corner c, int depth, glm::vec3& failAt, const Known& known) {
        Corner* corner[3] = {&a, &b, &c};
        for (int k = 0; k < 3; ++k)
            if (!locate(*corner[k], failAt)) return false;
        // One corner's triangle within the limit of the other two: convexity. Bit j of
        // within[k]: corner k's triangle lies within the limit of corner j (a row stops at
        // its first miss; the split below asks for the rest as it needs them).
        unsigned within[3], asked[3];
        for (int k = 0; k < 3; ++k) {
            within[k] = known.within[k] | 1u << k;
            asked[k] = known.asked[k] | 1u << k;
        }
        auto ask = [&](int k, int j) {
            if (!(asked[k] >> j & 1u)) {
                asked[k] |= 1u << j;
                if (corner[k]->near == corner[j]->near ||
                    surface_.nearTriangle(corner[k]->near, corner[j]->p))
                    within[k] |= 1u << j;
            }
            return (within[k] >> j & 1u) != 0;
        };
        for (int k = 0; k < 3; ++k)
            if (ask(k, (k + 1) % 3) && ask(k, (k + 2) % 3)) return true;
        // Distance to a surface is 1-Lipschitz: the piece lies within d(g) + r of it, r the
        // largest distance from its centroid g to a corner, d(g) at most the distance to any
        // one triangle (first the corners', then the nearest).
        const glm::vec3 g = (a.p + b.p + c.p) / 3.0f;
        const float r = std::sqrt(std::max(
            {glm::dot(a.p - g, a.p - g), glm::dot(b.p - g, b.p - g), glm::dot(c.p - g, c.p - g)}));
        const float limit = surface_.limit();
        if (r < limit) {
            for (int k = 0; k < 3; ++k)
                if (surface_.distanceTo(corner[k]->near, g) + r <= limit) return true;
            if (r < 0.5f * limit && surface_.distance(g) + r <= limit) return true;
            // Some other triangle within the limit of all three corners: searched for only for
            // pieces within the limit of their centroid (larger ones are cut instead; searching
            // up to twice the limit cost the tiled engine 6 % more).
            if (surface_.nearAll(a.p, b.p, c.p)) return true;
        }
        const float ab = glm::dot(b.p - a.p, b.p - a.p), bc = glm::dot(c.p - b.p, c.p - b.p),
                    ca = glm::dot(a.p - c.p, a.p - c.p);
        const float longest = std::max({ab, bc, ca});
        if (longest <= slack2_) return true;
        if (depth >= kMaxDepth || --budget_ <= 0) {
            failAt = g;
            return false;
        }
        // Bisect the longest edge whose ends share no triangle within the limit of both, if
        // it is at least half as long as the longest edge (a piece over long thin surface
        // triangles, the strips of a cylinder, is cut across them, not along; shorter edges
        // would make slivers where the surface's triangles are small every way), else the
        // longest edge (always from kSplitDepth on, so pieces shrink to the slack); the
        // midpoint is located once for both halves.
        const float len[3] = {ab, bc, ca}; // edge e joins corners e and e + 1
        int split = longest == ab ? 0 : longest == bc ? 1 : 2;
        if (depth < kSplitDepth) {
            int best = -1;
            for (int e = 0; e < 3; ++e) {
                const int i = e, j = (e + 1) % 3;
                const bool shared = ask(i, j) || ask(j, i);
                if (!shared && len[e] * 4.0f >= longest && (best < 0 || len[e] > len[best]))
                    best = e;
            }
            if (best >= 0) split = best;
        }
        Corner m{split == 0   ? (a.p + b.p) * 0.5f
                 : split == 1 ? (b.p + c.p) * 0.5f
                              : (c.p + a.p) * 0.5f,
                 kNoTriangle};
        if (!locate(m, failAt)) return false;
        // Each half keeps two corners of this piece, and what was asked about them.
        auto keep = [&](int c0, int c1, int c2) { // this piece's corner per corner (-1: m)
            const int from[3] = {c0, c1, c2};
            Known k;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    if (i != j && from[i] >= 0 && from[j] >= 0) {
                        k.asked[i] |= (asked[from[i]] >> from[j] & 1u) << j;
                        k.within[i] |= (within[from[i]] >> from[j] & 1u) << j;
                    }
            return k;
        };
        if (split == 0)
            return piece(a, m, c, depth + 1, failAt, keep(0, -1, 2)) &&
                   piece(m, b, c, depth + 1, failAt, keep(-1, 1, 2));
        if (split == 1)
            return piece(a, b, m, depth + 1, failAt, keep(0, 1, -1)) &&
                   piece(a, m, c, depth + 1, failAt, keep(0, -1, 2));
        return piece(a, b, m, depth + 1, failAt, keep(0, 1, -1)) &&
               piece(m, b, c, depth + 1, failAt, keep(-1, 1, 2));
    }

    static constexpr int kSplitDepth = 24; // from here on the longest edge is bisected

    NearSurface& surface_;
    float slack2_;
    int budget_ = 0;
};

} // namespace hlod::surface
