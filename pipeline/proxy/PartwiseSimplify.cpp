// Part-by-part quadric simplification with a per-part deviation check, see PartwiseSimplify.h.
#include "pipeline/proxy/PartwiseSimplify.h"

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
    // Reused in turn: component root per vertex, then part per root.
    std::vector<std::uint32_t> partOf = componentRoots(mesh);
    std::vector<std::uint32_t> partOfRoot(partOf.size(), kNone);
    const std::size_t triangleCount = mesh.indices.size() / 3;
    std::vector<std::uint32_t> partOfTriangle(triangleCount);
    std::vector<std::uint32_t> counts;
    for (std::size_t t = 0; t < triangleCount; ++t) {
        std::uint32_t& part = partOfRoot[partOf[mesh.indices[3 * t]]];
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
    std::vector<std::uint32_t>& fill = counts; // reused as the write cursor per part
    for (std::size_t p = 0; p < counts.size(); ++p)
        fill[p] = parts.offsets[p];
    for (std::size_t t = 0; t < triangleCount; ++t)
        parts.triangles[fill[partOfTriangle[t]]++] = static_cast<std::uint32_t>(t);
    return parts;
}

// One part with its own compact vertex array; `global` maps local vertices back.
struct LocalPart {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices, global;
    glm::vec3 lo{0.0f}, hi{0.0f}; // bounding box of the part's vertices
};

// `localOf` is a scratch map (all kNone on entry and on return) the size of mesh.positions.
void gatherPart(const ProxyMesh& mesh, std::span<const std::uint32_t> triangles,
                std::vector<std::uint32_t>& localOf, LocalPart& part) {
    part.positions.clear();
    part.indices.clear();
    part.global.clear();
    part.indices.reserve(3 * triangles.size());
    glm::vec3 lo = mesh.positions[mesh.indices[3 * triangles[0]]], hi = lo;
    for (std::uint32_t t : triangles) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh.indices[3 * t + k];
            if (localOf[v] == kNone) {
                localOf[v] = static_cast<std::uint32_t>(part.global.size());
                part.global.push_back(v);
                const glm::vec3& p = mesh.positions[v];
                part.positions.push_back(p);
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
            part.indices.push_back(localOf[v]);
        }
    }
    for (std::uint32_t v : part.global)
        localOf[v] = kNone;
    part.lo = lo;
    part.hi = hi;
}

// Scratch shared by all parts of a mesh, so the loop allocates only while buffers grow.
struct Workspace {
    std::vector<std::uint32_t> out;
    DeviationChecker checker;
};

// The first simplification of `part` from the fractions that passes the deviation check, or
// the part's input. Returns the local indices to keep (a view into `part` or `ws.out`).
std::span<const std::uint32_t> simplifyPart(const LocalPart& part, double maxError,
                                            std::span<const double> fractions, Workspace& ws) {
    const float* positions = &part.positions[0].x;
    const std::size_t vertexCount = part.positions.size();
    // meshoptimizer measures error relative to the part's largest extent.
    const double scale = meshopt_simplifyScale(positions, vertexCount, sizeof(glm::vec3));
    if (!(scale > 0.0)) return part.indices;
    ws.out.resize(part.indices.size());
    ws.checker.reset(part.positions, part.indices, maxError);
    for (const double fraction : fractions) {
        const auto relative = static_cast<float>(maxError * fraction / scale);
        const std::size_t count =
            meshopt_simplify(ws.out.data(), part.indices.data(), part.indices.size(), positions,
                             vertexCount, sizeof(glm::vec3), 0, relative, 0, nullptr);
        // Nothing collapses: the part is unchanged (no check needed), smaller targets neither.
        if (count == part.indices.size()) break;
        const std::span<const std::uint32_t> result(ws.out.data(), count);
        if (ws.checker.accepts(result)) return result;
    }
    return part.indices;
}

} // namespace

std::vector<std::uint32_t> simplifyPartsWithinError(const ProxyMesh& mesh, double maxError,
                                                    float minPartDiagonal,
                                                    std::span<const double> fractions) {
    if (mesh.indices.empty()) return {};
    const Parts parts = splitParts(mesh);
    std::vector<std::uint32_t> localOf(mesh.positions.size(), kNone);
    std::vector<std::uint32_t> result;
    result.reserve(mesh.indices.size());
    LocalPart part;
    Workspace ws;
    for (std::size_t p = 0; p + 1 < parts.offsets.size(); ++p) {
        const std::span<const std::uint32_t> triangles(parts.triangles.data() + parts.offsets[p],
                                                       parts.offsets[p + 1] - parts.offsets[p]);
        gatherPart(mesh, triangles, localOf, part);
        // SmallParts.h's rule, on the same components (dropSmallParts would find them again).
        if (glm::length(part.hi - part.lo) < minPartDiagonal) continue;
        for (std::uint32_t v : simplifyPart(part, maxError, fractions, ws))
            result.push_back(part.global[v]);
    }
    return result;
}

} // namespace hlod
