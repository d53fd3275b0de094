// Part-by-part quadric simplification with a per-part deviation check, see PartwiseSimplify.h.
#include "pipeline/proxy/PartwiseSimplify.h"

#include <memory>

#include <meshoptimizer.h>

#include "pipeline/proxy/DeviationCheck.h"
#include "pipeline/proxy/SmallParts.h"

namespace hlod {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

// Triangles of every connected part (CSR), parts in the order of their first triangle.
struct Parts {
    std::vector<std::uint32_t> offsets; // per part, into triangles
    std::vector<std::uint32_t> triangles;
};

Parts splitParts(const ProxyMesh& mesh) {
    const std::vector<std::uint32_t> root = componentRoots(mesh);
    std::vector<std::uint32_t> partOfRoot(root.size(), kNone);
    const std::size_t triangleCount = mesh.indices.size() / 3;
    std::vector<std::uint32_t> partOfTriangle(triangleCount);
    std::vector<std::uint32_t> counts;
    for (std::size_t t = 0; t < triangleCount; ++t) {
        std::uint32_t& part = partOfRoot[root[mesh.indices[3 * t]]];
        if (part == kNone) {
            part = static_cast<std::uint32_t>(counts.size());
            counts.push_back(0);
        }
        partOfTriangle[t] = part;
        ++counts[part];
    }
    Parts parts;
    parts.offsets.assign(counts.size() + 1, 0);
    for (std::size_t p = 0; p < counts.size(); ++p)
        parts.offsets[p + 1] = parts.offsets[p] + counts[p];
    parts.triangles.resize(triangleCount);
    std::vector<std::uint32_t> fill(parts.offsets.begin(), parts.offsets.end() - 1);
    for (std::size_t t = 0; t < triangleCount; ++t)
        parts.triangles[fill[partOfTriangle[t]]++] = static_cast<std::uint32_t>(t);
    return parts;
}

// One part with its own compact vertex array; `global` maps local vertices back.
struct LocalPart {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices, global;
};

// `localOf` is a scratch map (all kNone on entry and on return) the size of mesh.positions.
void gatherPart(const ProxyMesh& mesh, std::span<const std::uint32_t> triangles,
                std::vector<std::uint32_t>& localOf, LocalPart& part) {
    part.positions.clear();
    part.indices.clear();
    part.global.clear();
    for (std::uint32_t t : triangles) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh.indices[3 * t + k];
            if (localOf[v] == kNone) {
                localOf[v] = static_cast<std::uint32_t>(part.global.size());
                part.global.push_back(v);
                part.positions.push_back(mesh.positions[v]);
            }
            part.indices.push_back(localOf[v]);
        }
    }
    for (std::uint32_t v : part.global)
        localOf[v] = kNone;
}

// The first simplification of `part`, from fractions[first] on, that passes the deviation
// check (its fraction index in `passed`), or the part's input (`passed` = fractions.size()).
std::vector<std::uint32_t> simplifyPart(const LocalPart& part, double maxError,
                                        std::span<const double> fractions, std::size_t first,
                                        std::size_t& passed) {
    passed = fractions.size();
    const float* positions = &part.positions[0].x;
    const std::size_t vertexCount = part.positions.size();
    // meshoptimizer measures error relative to the part's largest extent.
    const double scale = meshopt_simplifyScale(positions, vertexCount, sizeof(glm::vec3));
    if (!(scale > 0.0)) return part.indices;
    std::unique_ptr<DeviationChecker> checker;
    std::vector<std::uint32_t> out(part.indices.size());
    for (std::size_t i = first; i < fractions.size(); ++i) {
        const auto relative = static_cast<float>(maxError * fractions[i] / scale);
        out.resize(part.indices.size());
        const std::size_t count =
            meshopt_simplify(out.data(), part.indices.data(), part.indices.size(), positions,
                             vertexCount, sizeof(glm::vec3), 0, relative, 0, nullptr);
        if (count == part.indices.size()) break; // nothing collapses, smaller targets neither
        out.resize(count);
        if (!checker)
            checker = std::make_unique<DeviationChecker>(part.positions, part.indices, maxError);
        if (checker->accepts(out)) {
            passed = i;
            return out;
        }
    }
    return part.indices;
}

} // namespace

std::vector<std::uint32_t> simplifyPartsWithinError(const ProxyMesh& mesh, double maxError,
                                                    std::span<const double> fractions) {
    if (mesh.indices.empty()) return {};
    const Parts parts = splitParts(mesh);
    std::vector<std::uint32_t> localOf(mesh.positions.size(), kNone);
    std::vector<std::uint32_t> result;
    result.reserve(mesh.indices.size());
    LocalPart part;
    // Parts of one node tend to need similar targets: each part starts one step coarser than
    // where the previous one passed (saves most failing attempts; depends only on the input).
    std::size_t first = 0;
    for (std::size_t p = 0; p + 1 < parts.offsets.size(); ++p) {
        const std::span<const std::uint32_t> triangles(parts.triangles.data() + parts.offsets[p],
                                                       parts.offsets[p + 1] - parts.offsets[p]);
        gatherPart(mesh, triangles, localOf, part);
        std::size_t passed = 0;
        for (std::uint32_t v : simplifyPart(part, maxError, fractions, first, passed))
            result.push_back(part.global[v]);
        if (passed < fractions.size()) first = passed > 0 ? passed - 1 : 0;
    }
    return result;
}

} // namespace hlod
