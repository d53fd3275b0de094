// Voxel remeshing with hidden-interior removal (OpenVDB level sets, Museth 2013; thesis 5.3's
// remesher), see RemeshProxy.h for the steps and the error budget.
#include "pipeline/proxy/RemeshProxy.h"

#include <algorithm>
#include <cmath>

#include "pipeline/core/Error.h"
#include "pipeline/core/OnDemand.h"
#include "pipeline/proxy/DecimateProxy.h"
#include "pipeline/proxy/DeviationCheck.h"
#include "pipeline/proxy/ProxyFinish.h"
#include "pipeline/proxy/SmallParts.h"
#include "pipeline/proxy/VoxelShell.h"
#include "pipeline/proxy/Weld.h"

namespace hlod {

namespace {

// meshoptimizer's RMS error (DeviationCheck.h) at falling fractions of the budget, until every
// sample of the simplified shell lies within the budget of the unsimplified shell. Only that
// direction is checked: the simplifier rightly removes the thin spikes pulling back can leave
// (their area, and so their RMS error, is tiny), which a two-way check would refuse.
// Whether some edge of the triangle list is not shared by exactly two triangles (an open border
// or a fold where sheets meet).
bool hasOpenEdge(const std::vector<std::uint32_t>& indices) {
    std::vector<std::uint64_t> edges;
    edges.reserve(indices.size());
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        for (int e = 0; e < 3; ++e) {
            const std::uint64_t a = indices[t + e], b = indices[t + (e + 1) % 3];
            edges.push_back(std::min(a, b) << 32 | std::max(a, b));
        }
    }
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j] == edges[i])
            ++j;
        if (j - i != 2) return true;
        i = j;
    }
    return false;
}

// Signed volume enclosed by a closed triangle list (divergence theorem).
double enclosedVolume(const std::vector<glm::vec3>& positions,
                      const std::vector<std::uint32_t>& indices) {
    double v = 0.0;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::dvec3 a(positions[indices[t]]), b(positions[indices[t + 1]]),
            c(positions[indices[t + 2]]);
        v += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return v;
}

// The shell is closed; a simplification that opens it (a slab thinner than the budget folded
// flat, leaving a border) is refused like one that strays too far.
std::vector<std::uint32_t> simplifyShell(const ProxyMesh& shell, double maxError) {
    for (const double fraction : {0.6, 0.4, 0.25, 0.15}) {
        std::vector<std::uint32_t> out = simplifyToError(shell, maxError * fraction);
        if (out.empty() || hasOpenEdge(out) || enclosedVolume(shell.positions, out) <= 0.0) {
            continue;
        }
        if (withinDistanceOf(shell.positions, out, shell.positions, shell.indices, maxError)) {
            return out;
        }
    }
    return shell.indices;
}

} // namespace

ProxyMesh remeshProxy(ProxyMesh input, double maxError, const Progress& progress,
                      const RemeshOptions& options) {
    weldVertices(input, 0.0f);
    dropSmallParts(input, static_cast<float>(maxError));
    if (input.indices.empty()) return input;

    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : input.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    double h = maxError * options.voxelFraction;
    h = std::max(h, extent / options.maxVoxelsPerAxis);
    const double d = h * options.shellVoxels;

    ProxyMesh shell = HLOD_ON_DEMAND(VdbModule, vdb, "remesh (OpenVDB)")
                          .voxelShell(input, h, d, options, progress);
    progress.throwIfCancelled();

    weldVertices(shell, 0.0f);
    shell.indices = simplifyShell(shell, maxError);
    compactMesh(shell);
    dropSmallParts(shell, static_cast<float>(maxError));
    finishProxy(shell);
    return shell;
}

} // namespace hlod
