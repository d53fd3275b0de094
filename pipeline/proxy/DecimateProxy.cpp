// Error-bounded quadric decimation proxy, see DecimateProxy.h.
#include "pipeline/proxy/DecimateProxy.h"

#include <cmath>

#include <meshoptimizer.h>

#include "pipeline/proxy/BoundedSimplify.h"
#include "pipeline/proxy/CertifiedSimplify.h"
#include "pipeline/proxy/CoveredParts.h"
#include "pipeline/proxy/ProxyFinish.h"
#include "pipeline/proxy/SmallParts.h"
#include "pipeline/proxy/Weld.h"

namespace hlod {

namespace {

// See decimateProxy: a node whose proxy keeps more than this share of its input is left at
// the cheaper steps (proxy ratios above it are accepted, but only 0.35 is the default).
constexpr double kHopeless = 0.6;

// The simplified triangles of the parts CoveredParts.h keeps. `copies` are the input vertices
// that the simplified vertices past the input's copy (BoundedSimplify.h).
std::vector<std::uint32_t> dropCoveredParts(const ProxyMesh& input,
                                            std::span<const glm::vec3> simplifiedPositions,
                                            std::vector<std::uint32_t> simplified,
                                            std::span<const std::uint32_t> copies, double limit) {
    std::vector<std::uint32_t> part = componentRoots(input);
    for (std::uint32_t v : copies)
        part.push_back(part[v]); // a copy belongs to its vertex's part
    std::vector<std::uint32_t> number(part.size(), 0xffffffffu);
    std::size_t parts = 0;
    for (std::uint32_t v : input.indices) {
        std::uint32_t& n = number[part[v]];
        if (n == 0xffffffffu) n = static_cast<std::uint32_t>(parts++);
    }
    for (std::uint32_t v = 0; v < part.size(); ++v)
        part[v] = number[part[v]] == 0xffffffffu ? 0 : number[part[v]];
    const std::vector<std::uint8_t> keep = keepUncoveredParts(
        input.positions, input.indices, simplifiedPositions, simplified, part, parts, limit);
    std::size_t out = 0;
    for (std::size_t t = 0; t + 2 < simplified.size(); t += 3) {
        if (!keep[part[simplified[t]]]) continue;
        for (int k = 0; k < 3; ++k)
            simplified[out++] = simplified[t + k];
    }
    simplified.resize(out);
    return simplified;
}

} // namespace

std::vector<std::uint32_t> simplifyToError(const ProxyMesh& mesh, double maxError) {
    if (mesh.indices.empty()) return {};
    const float* positions = &mesh.positions[0].x;
    // meshoptimizer measures error relative to the mesh's largest extent.
    const float scale = meshopt_simplifyScale(positions, mesh.positions.size(), sizeof(glm::vec3));
    if (!(scale > 0.0f)) return mesh.indices;
    const float relative = static_cast<float>(maxError / static_cast<double>(scale));
    std::vector<std::uint32_t> out(mesh.indices.size());
    const std::size_t count = meshopt_simplify(out.data(), mesh.indices.data(), mesh.indices.size(),
                                               positions, mesh.positions.size(), sizeof(glm::vec3),
                                               /*target_index_count=*/0, relative, 0, nullptr);
    out.resize(count);
    return out;
}

ProxyMesh decimateProxy(ProxyMesh input, double maxError, const DecimateOptions& options) {
    const auto e = static_cast<float>(maxError);
    const float wf = options.weldFraction;
    // The input lies within its own error bound of the original meshes (ProxyMesh.h) and
    // welding moves a vertex by at most sqrt(3) * tolerance more: the simplification gets what
    // is left of the budget.
    const double limit = maxError - double(input.errorBound) - std::sqrt(3.0) * double(e * wf);
    weldCorners(input, WeldOptions{e * wf, false, true});
    dropSmallParts(input, e);
    if (limit > 0.0 && !input.indices.empty()) {
        const std::size_t triangles = input.triangleCount();
        // A proxy that keeps more than kHopeless of its input cannot pay for itself under any
        // useful proxy ratio; it is finished early, still certified (DecimateProxy.h).
        const auto hopeless = [&](std::size_t kept) {
            return static_cast<double>(kept) > kHopeless * static_cast<double>(triangles);
        };
        if (!hopeless(simplifyToError(input, limit).size() / 3)) {
            // Collapses certified by mapping as far as they go, then by the distance test
            // against the input, which goes on where the mapping's added moves stop.
            const CertifiedSimplifyResult mapped =
                simplifyCertified(input.positions, input.indices, {}, limit);
            // Always the second pass: the mapping alone stops early on open strips and small
            // pieces (torcs-spring: 725 of its clusters dissolved with a stop there, 528 without).
            BoundedSimplifyResult simplified = simplifyWithinDeviationFrom(
                input.positions, input.indices,
                QuadricStart{mapped.positions, mapped.indices, mapped.representative}, limit);
            input.indices =
                dropCoveredParts(input, simplified.positions, std::move(simplified.indices),
                                 simplified.copies, limit);
            input.positions = std::move(simplified.positions);
            for (std::uint32_t v : simplified.copies)
                input.colors.push_back(input.colors[v]);
        }
    }
    compactMesh(input);
    finishProxy(input);
    input.errorBound = e; // certified within the whole budget of the originals, both ways
    return input;
}

} // namespace hlod
