// Quadric decimation proxy (Garland & Heckbert 1997 via meshoptimizer), see DecimateProxy.h.
#include "pipeline/proxy/DecimateProxy.h"

#include <meshoptimizer.h>

#include "pipeline/proxy/PartwiseSimplify.h"
#include "pipeline/proxy/ProxyFinish.h"
#include "pipeline/proxy/Weld.h"

namespace hlod {

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
    weldVertices(input, e * options.weldFraction);
    // Parts below e are dropped (SmallParts.h) in the same pass over the connected parts.
    input.indices = simplifyPartsWithinError(input, maxError * options.simplifyFraction, e);
    compactMesh(input);
    finishProxy(input);
    return input;
}

} // namespace hlod
