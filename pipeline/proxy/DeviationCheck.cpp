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

float distanceSquared(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
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

// Triangles per cell (CSR). Cells are at least 2 * limit wide, so the cells a query needs are
// at most two per axis. A triangle goes into every cell of its bounding box that its plane
// passes within half a cell diagonal of; triangles spanning too many cells stay in `big_`
// and are tested by every query.
class TriangleGrid {
public:
    TriangleGrid(std::span<const glm::vec3> pos, std::span<const std::uint32_t> idx,
                 const glm::vec3& lo, float cell, const glm::ivec3& dims)
        : pos_(pos), idx_(idx), lo_(lo), cell_(cell), dims_(dims) {
        const std::size_t cells = static_cast<std::size_t>(dims.x) * dims.y * dims.z;
        offsets_.assign(cells + 1, 0);
        forEachCell([&](std::uint32_t, std::size_t c) { ++offsets_[c + 1]; });
        for (std::size_t i = 1; i < offsets_.size(); ++i)
            offsets_[i] += offsets_[i - 1];
        items_.resize(offsets_.back());
        std::vector<std::uint32_t> fill(offsets_.begin(), offsets_.end() - 1);
        forEachCell([&](std::uint32_t t, std::size_t c) { items_[fill[c]++] = t; });
    }

    bool anyWithin(const glm::vec3& p, float limit) const {
        const float limit2 = limit * limit;
        const glm::ivec3 c0 = clampCell((p - glm::vec3(limit) - lo_) / cell_);
        const glm::ivec3 c1 = clampCell((p + glm::vec3(limit) - lo_) / cell_);
        for (int x = c0.x; x <= c1.x; ++x) {
            for (int y = c0.y; y <= c1.y; ++y) {
                for (int z = c0.z; z <= c1.z; ++z) {
                    const std::size_t c = (static_cast<std::size_t>(x) * dims_.y + y) * dims_.z + z;
                    for (std::uint32_t k = offsets_[c]; k < offsets_[c + 1]; ++k) {
                        if (triangleDistance2(items_[k], p) <= limit2) return true;
                    }
                }
            }
        }
        for (std::uint32_t t : big_) {
            if (triangleDistance2(t, p) <= limit2) return true;
        }
        return false;
    }

private:
    static constexpr std::size_t kMaxCellsPerTriangle = 4096;

    float triangleDistance2(std::uint32_t t, const glm::vec3& p) const {
        return distanceSquared(p, pos_[idx_[3 * t]], pos_[idx_[3 * t + 1]], pos_[idx_[3 * t + 2]]);
    }
    glm::ivec3 clampCell(const glm::vec3& f) const {
        return glm::clamp(glm::ivec3(glm::floor(f)), glm::ivec3(0), dims_ - 1);
    }

    // Calls visit(triangle, cell) for every cell a triangle is filed under; a triangle whose
    // box spans too many cells goes to big_ instead (on the first pass only).
    template <class F> void forEachCell(F&& visit) {
        const bool firstPass = !counted_;
        counted_ = true;
        for (std::uint32_t t = 0; t < idx_.size() / 3; ++t) {
            const glm::vec3 &a = pos_[idx_[3 * t]], &b = pos_[idx_[3 * t + 1]],
                            &c = pos_[idx_[3 * t + 2]];
            const glm::ivec3 c0 = clampCell((glm::min(a, glm::min(b, c)) - lo_) / cell_);
            const glm::ivec3 c1 = clampCell((glm::max(a, glm::max(b, c)) - lo_) / cell_);
            const glm::ivec3 span = c1 - c0 + 1;
            const std::size_t count = static_cast<std::size_t>(span.x) * span.y * span.z;
            if (count > kMaxCellsPerTriangle) {
                if (firstPass) big_.push_back(t);
                continue;
            }
            glm::vec3 n = glm::cross(b - a, c - a);
            const float len = glm::length(n);
            n = len > 0.0f ? n / len : glm::vec3(0.0f);
            const float reach = cell_ * 0.8661f; // half the cell diagonal
            for (int x = c0.x; x <= c1.x; ++x) {
                for (int y = c0.y; y <= c1.y; ++y) {
                    for (int z = c0.z; z <= c1.z; ++z) {
                        const glm::vec3 centre = lo_ + (glm::vec3(x, y, z) + 0.5f) * cell_;
                        if (count > 8 && len > 0.0f && std::abs(glm::dot(n, centre - a)) > reach) {
                            continue;
                        }
                        visit(t, (static_cast<std::size_t>(x) * dims_.y + y) * dims_.z + z);
                    }
                }
            }
        }
    }

    std::span<const glm::vec3> pos_;
    std::span<const std::uint32_t> idx_;
    glm::vec3 lo_;
    float cell_;
    glm::ivec3 dims_;
    std::vector<std::uint32_t> offsets_, items_, big_;
    bool counted_ = false;
};

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

} // namespace

bool withinDistanceOf(std::span<const glm::vec3> meshPositions, std::span<const std::uint32_t> mesh,
                      std::span<const glm::vec3> referencePositions,
                      std::span<const std::uint32_t> reference, double limitMetres) {
    if (mesh.empty()) return true;
    if (reference.empty()) return false;
    const auto limit = static_cast<float>(limitMetres);
    const GridFrame f = frameFor(referencePositions, reference, limit, reference.size() / 3);
    const TriangleGrid grid(referencePositions, reference, f.lo, f.cell, f.dims);
    for (std::size_t t = 0; t + 2 < mesh.size(); t += 3) {
        const glm::vec3 &a = meshPositions[mesh[t]], &b = meshPositions[mesh[t + 1]],
                        &c = meshPositions[mesh[t + 2]];
        for (const glm::vec3& p :
             {a, (a + b) * 0.5f, (b + c) * 0.5f, (c + a) * 0.5f, (a + b + c) / 3.0f}) {
            if (!grid.anyWithin(p, limit)) return false;
        }
    }
    return true;
}

struct DeviationChecker::Grid {
    GridFrame frame;
    TriangleGrid original;
};

DeviationChecker::DeviationChecker(std::span<const glm::vec3> positions,
                                   std::span<const std::uint32_t> original, double limitMetres)
    : positions_(positions), original_(original), limit_(static_cast<float>(limitMetres)) {
    if (original.empty()) return;
    const GridFrame f = frameFor(positions, original, limit_, original.size() / 3);
    grid_ =
        std::make_unique<Grid>(Grid{f, TriangleGrid(positions, original, f.lo, f.cell, f.dims)});
}

DeviationChecker::~DeviationChecker() = default;

bool DeviationChecker::accepts(std::span<const std::uint32_t> simplified) const {
    if (original_.empty()) return true;
    if (simplified.empty()) return false;
    const float limit = limit_;
    // Simplified -> original: edge midpoints and centroids (corners are original vertices).
    for (std::size_t t = 0; t + 2 < simplified.size(); t += 3) {
        const glm::vec3 &a = positions_[simplified[t]], &b = positions_[simplified[t + 1]],
                        &c = positions_[simplified[t + 2]];
        for (const glm::vec3& p :
             {(a + b) * 0.5f, (b + c) * 0.5f, (c + a) * 0.5f, (a + b + c) / 3.0f}) {
            if (!grid_->original.anyWithin(p, limit)) return false;
        }
    }
    // Original -> simplified: vertices that did not survive, and triangle centroids.
    std::vector<std::uint8_t> kept(positions_.size(), 0);
    for (std::uint32_t v : simplified)
        kept[v] = 1;
    const GridFrame& f = grid_->frame;
    const TriangleGrid simplifiedGrid(positions_, simplified, f.lo, f.cell, f.dims);
    for (std::uint32_t v : original_) {
        if (kept[v] == 1) continue;
        if (!simplifiedGrid.anyWithin(positions_[v], limit)) return false;
        kept[v] = 1; // checked once
    }
    for (std::size_t t = 0; t + 2 < original_.size(); t += 3) {
        const glm::vec3 p = (positions_[original_[t]] + positions_[original_[t + 1]] +
                             positions_[original_[t + 2]]) /
                            3.0f;
        if (!simplifiedGrid.anyWithin(p, limit)) return false;
    }
    return true;
}

bool withinDeviation(std::span<const glm::vec3> positions, std::span<const std::uint32_t> original,
                     std::span<const std::uint32_t> simplified, double limitMetres) {
    return DeviationChecker(positions, original, limitMetres).accepts(simplified);
}

} // namespace hlod
