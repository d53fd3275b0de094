// Sampled two-sided Hausdorff test on a uniform triangle grid (Metro, Cignoni et al. 1998;
// closest point on triangle after Ericson, Real-Time Collision Detection 5.1.5), see
// DeviationCheck.h.
#include "pipeline/proxy/DeviationCheck.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace hlod {

namespace {

[[gnu::noinline]] float distanceSquared(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
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

Plane planeThrough(const glm::vec3& normal, const glm::vec3& point) {
    return Plane{normal, glm::dot(normal, point), glm::dot(normal, normal)};
}

Triangle makeTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
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
GridFrame frameFor(std::span<const glm::vec3> positions, std::span<const std::uint32_t> a,
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
                        if (within(tris_[items_[k]], p, limit2)) {
                            found = items_[k];
                            return true;
                        }
                    }
                }
            }
        }
        for (std::uint32_t t : big_) {
            if (within(tris_[t], p, limit2)) {
                found = t;
                return true;
            }
        }
        return false;
    }

private:
    static constexpr std::size_t kMaxCellsPerTriangle = 4096;

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

    bool near(const glm::vec3& p) {
        if (hint_ != kNoTriangle && within(tris_[hint_], p, limit2_)) return true;
        return grid_.anyWithin(p, limit_, limit2_, hint_);
    }
    // The triangle that answered the last successful near().
    std::uint32_t lastFound() const { return hint_; }

private:
    float limit_ = 0.0f, limit2_ = 0.0f;
    std::vector<Triangle> tris_;
    std::uint32_t hint_ = kNoTriangle;
    TriangleGrid grid_;
};

} // namespace

bool withinDistanceOf(std::span<const glm::vec3> meshPositions, std::span<const std::uint32_t> mesh,
                      std::span<const glm::vec3> referencePositions,
                      std::span<const std::uint32_t> reference, double limitMetres) {
    if (mesh.empty()) return true;
    if (reference.empty()) return false;
    NearSurface surface;
    surface.reset(referencePositions, reference, static_cast<float>(limitMetres));
    for (std::size_t t = 0; t + 2 < mesh.size(); t += 3) {
        const glm::vec3 &a = meshPositions[mesh[t]], &b = meshPositions[mesh[t + 1]],
                        &c = meshPositions[mesh[t + 2]];
        for (const glm::vec3& p :
             {a, (a + b) * 0.5f, (b + c) * 0.5f, (c + a) * 0.5f, (a + b + c) / 3.0f}) {
            if (!surface.near(p)) return false;
        }
    }
    return true;
}

struct DeviationChecker::Surfaces {
    NearSurface original, simplified;
    bool originalReady = false;         // `original` matches the current mesh
    std::vector<std::uint32_t> nearest; // per vertex, scratch of accepts()
};

DeviationChecker::DeviationChecker() : surfaces_(std::make_unique<Surfaces>()) {}

DeviationChecker::DeviationChecker(std::span<const glm::vec3> positions,
                                   std::span<const std::uint32_t> original, double limitMetres)
    : DeviationChecker() {
    reset(positions, original, limitMetres);
}

DeviationChecker::~DeviationChecker() = default;

void DeviationChecker::reset(std::span<const glm::vec3> positions,
                             std::span<const std::uint32_t> original, double limitMetres) {
    positions_ = positions;
    original_ = original;
    limit_ = static_cast<float>(limitMetres);
    surfaces_->originalReady = false; // set up by the first accepts(): unchanged parts need none
}

bool DeviationChecker::accepts(std::span<const std::uint32_t> simplified) {
    if (original_.empty()) return true;
    if (simplified.empty()) return false;
    Surfaces& s = *surfaces_;
    if (!s.originalReady) {
        s.original.reset(positions_, original_, limit_);
        s.originalReady = true;
    }
    // Simplified -> original: edge midpoints and centroids (corners are original vertices).
    // The centroid is the mean of the midpoints, so when one original triangle answered all
    // three midpoints it is within the limit of the centroid too (convexity, as below).
    for (std::size_t t = 0; t + 2 < simplified.size(); t += 3) {
        const glm::vec3 &a = positions_[simplified[t]], &b = positions_[simplified[t + 1]],
                        &c = positions_[simplified[t + 2]];
        std::uint32_t found[3];
        int k = 0;
        for (const glm::vec3& p : {(a + b) * 0.5f, (b + c) * 0.5f, (c + a) * 0.5f}) {
            if (!s.original.near(p)) return false;
            found[k++] = s.original.lastFound();
        }
        if (found[0] == found[1] && found[0] == found[2]) continue;
        if (!s.original.near((a + b + c) / 3.0f)) return false;
    }
    // Original -> simplified: vertices that did not survive, and triangle centroids. Each
    // vertex notes a simplified triangle within the limit of it (for a surviving vertex, one
    // it is a corner of). The distance to a triangle is a convex function, so a centroid is
    // within the limit of a triangle that all three of its corners are within the limit of:
    // such centroids need no query (an exact consequence, not a skipped sample).
    constexpr std::uint32_t kUnknown = 0xffffffffu;
    s.nearest.assign(positions_.size(), kUnknown);
    for (std::size_t i = 0; i < simplified.size(); ++i) {
        std::uint32_t& t = s.nearest[simplified[i]];
        if (t == kUnknown) t = static_cast<std::uint32_t>(i / 3);
    }
    s.simplified.reset(positions_, simplified, limit_);
    for (std::uint32_t v : original_) {
        if (s.nearest[v] != kUnknown) continue;
        if (!s.simplified.near(positions_[v])) return false;
        s.nearest[v] = s.simplified.lastFound();
    }
    for (std::size_t t = 0; t + 2 < original_.size(); t += 3) {
        const std::uint32_t a = original_[t], b = original_[t + 1], c = original_[t + 2];
        const std::uint32_t shared = s.nearest[a];
        if (shared == s.nearest[b] && shared == s.nearest[c]) continue;
        const glm::vec3 p = (positions_[a] + positions_[b] + positions_[c]) / 3.0f;
        if (!s.simplified.near(p)) return false;
    }
    return true;
}

bool withinDeviation(std::span<const glm::vec3> positions, std::span<const std::uint32_t> original,
                     std::span<const std::uint32_t> simplified, double limitMetres) {
    return DeviationChecker(positions, original, limitMetres).accepts(simplified);
}

} // namespace hlod
