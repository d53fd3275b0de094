// Grid vertex clustering proxy (Rossignac & Borrel 1993 via meshopt_simplifySloppy), see
// SloppyProxy.h.
#include "pipeline/proxy/SloppyProxy.h"

#include <cmath>

#include <meshoptimizer.h>

#include "pipeline/proxy/DecimateProxy.h"
#include "pipeline/proxy/ProxyFinish.h"
#include "pipeline/proxy/SmallParts.h"
#include "pipeline/proxy/Weld.h"

namespace hlod {

namespace {

// meshoptimizer 0.18 clamps its error-limited grid to 1 / 1e-3 cells per axis.
constexpr double kMaxGrid = 1000.0;

} // namespace

ProxyMesh sloppyProxy(ProxyMesh input, double maxError) {
    weldVertices(input, 0.0f);
    dropSmallParts(input, static_cast<float>(maxError));
    if (input.indices.empty()) return input;
    const float* positions = &input.positions[0].x;
    const double scale =
        meshopt_simplifyScale(positions, input.positions.size(), sizeof(glm::vec3));
    if (!(scale > 0.0)) return input;
    // meshoptimizer snaps vertices to a lattice of spacing extent / (grid - 1); a cell's
    // diagonal stays within the budget when grid - 1 >= sqrt(3) * extent / maxError.
    const double grid = std::ceil(std::sqrt(3.0) * scale / maxError) + 2.0;
    if (grid > kMaxGrid) return decimateProxy(std::move(input), maxError);
    // meshoptimizer truncates 1 / error to the grid size: aim half a cell above it.
    const auto relative = static_cast<float>(1.0 / (grid + 0.5));
    std::vector<std::uint32_t> out(input.indices.size());
    const std::size_t count = meshopt_simplifySloppy(
        out.data(), input.indices.data(), input.indices.size(), positions, input.positions.size(),
        sizeof(glm::vec3), /*target_index_count=*/0, relative, nullptr);
    out.resize(count);
    input.indices = std::move(out);
    compactMesh(input);
    finishProxy(input);
    return input;
}

} // namespace hlod
