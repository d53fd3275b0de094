// Per-mesh DLOD chain, thesis chapter 6 configuration (b), with meshoptimizer's quadric
// simplifier (Garland & Heckbert 1997), see DlodChain.h.
#include "pipeline/proxy/DlodChain.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <meshoptimizer.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "pipeline/core/Error.h"
#include "pipeline/proxy/BakeStats.h"
#include "pipeline/proxy/DeviationCheck.h"

namespace hlod {

namespace {

// The vertices `indices` use, in first-use order, with every attribute stream.
Mesh extractLevel(const Mesh& source, const std::vector<std::uint32_t>& indices) {
    Mesh out;
    out.name = source.name;
    out.material = source.material;
    std::vector<std::uint32_t> remap(source.positions.size(), 0xffffffffu);
    const bool uvs = source.uvs.size() == source.positions.size();
    const bool colors = source.colors.size() == source.positions.size();
    const bool normals = source.normals.size() == source.positions.size();
    out.indices.reserve(indices.size());
    for (std::uint32_t v : indices) {
        if (remap[v] == 0xffffffffu) {
            remap[v] = static_cast<std::uint32_t>(out.positions.size());
            out.positions.push_back(source.positions[v]);
            if (normals) out.normals.push_back(source.normals[v]);
            if (uvs) out.uvs.push_back(source.uvs[v]);
            if (colors) out.colors.push_back(source.colors[v]);
        }
        out.indices.push_back(remap[v]);
    }
    return out;
}

} // namespace

std::vector<Mesh> buildDlodChain(const Mesh& mesh, const DlodParams& params) {
    std::vector<Mesh> chain;
    if (mesh.positions.empty()) return chain;
    std::vector<std::uint32_t> current = mesh.indices;
    for (int level = 0; level < params.levels && !current.empty(); ++level) {
        const auto target = static_cast<std::size_t>(
                                std::floor(static_cast<double>(current.size() / 3) * params.keep)) *
                            3;
        std::vector<std::uint32_t> next(current.size());
        // No error limit: the chain is defined by triangle counts, as in the thesis.
        const std::size_t count =
            meshopt_simplify(next.data(), current.data(), current.size(), &mesh.positions[0].x,
                             mesh.positions.size(), sizeof(glm::vec3), target, 1.0e3f, 0, nullptr);
        if (count == 0 || count >= current.size()) break;
        next.resize(count);
        current = std::move(next);
        chain.push_back(extractLevel(mesh, current));
    }
    return chain;
}

std::vector<double> dlodDeviations(const Mesh& original, const std::vector<Mesh>& chain) {
    std::vector<double> out;
    const double extent = original.localBounds().diagonal();
    for (const Mesh& level : chain) {
        auto within = [&](double limit) {
            return withinDistanceOf(level.positions, level.indices, original.positions,
                                    original.indices, limit) &&
                   withinDistanceOf(original.positions, original.indices, level.positions,
                                    level.indices, limit);
        };
        // Bisection between a limit that fails and one that holds (the diagonal always does).
        double lo = 0.0, hi = std::max(extent, 1e-9);
        while (!within(hi))
            hi *= 2.0;
        while (hi - lo > 0.01 * hi) {
            const double mid = 0.5 * (lo + hi);
            (within(mid) ? hi : lo) = mid;
        }
        out.push_back(hi);
    }
    return out;
}

DlodSummary summarizeDlodChains(const Scene& scene, const DlodParams& params, int threads) {
    if (params.levels < 0 || params.levels > 16 || !(params.keep > 0.0 && params.keep < 1.0)) {
        throw Error(ErrorCode::InvalidArgument,
                    "DLOD chain needs 0..16 levels and a keep fraction in (0, 1)");
    }
    const auto start = std::chrono::steady_clock::now();
    struct PerMesh {
        std::size_t triangles = 0, vertices = 0, meshes = 0, bytes = 0;
    };
    std::vector<PerMesh> per(scene.meshes.size());
    tbb::task_arena arena(threads > 0 ? threads : tbb::info::default_concurrency());
    arena.execute([&] {
        tbb::parallel_for(std::size_t(0), scene.meshes.size(), [&](std::size_t m) {
            const Mesh& mesh = scene.meshes[m];
            PerMesh& p = per[m];
            p.triangles = mesh.triangleCount();
            p.vertices = mesh.vertexCount();
            p.meshes = 1;
            p.bytes = meshBytes(mesh);
            for (const Mesh& level : buildDlodChain(mesh, params)) {
                p.triangles += level.triangleCount();
                p.vertices += level.vertexCount();
                p.meshes += 1;
                p.bytes += meshBytes(level);
            }
        });
    });
    DlodSummary s;
    for (const MeshInstance& inst : scene.instances) {
        const PerMesh& p = per[inst.mesh];
        s.triangles += p.triangles;
        s.vertices += p.vertices;
        s.meshes += p.meshes;
        s.bytes += p.bytes;
    }
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return s;
}

} // namespace hlod
