// OpenVDB voxelisation, exterior fill and iso-surface of the remesh method, see VoxelShell.h
// and RemeshProxy.h (Museth 2013).
#include "pipeline/proxy/VoxelShell.h"

#include <algorithm>
#include <array>
#include <mutex>

#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include "pipeline/core/OnDemand.h"
#include "pipeline/proxy/ExteriorFill.h"
#include "pipeline/proxy/SurfaceQuery.h"

namespace hlod {

namespace {

struct CancelInterrupter : openvdb::util::NullInterrupter {
    explicit CancelInterrupter(const Progress& p) : progress(p) {}
    bool wasInterrupted(int percent = -1) override {
        (void)percent;
        return progress.cancelled();
    }
    const Progress& progress;
};

struct Voxelised {
    openvdb::FloatGrid::Ptr distance;
    openvdb::Int32Grid::Ptr closest; // index of the closest input triangle per voxel
};

Voxelised voxelise(const ProxyMesh& m, double h, double d, const Progress& progress) {
    std::vector<openvdb::Vec3s> points;
    points.reserve(m.positions.size());
    const double inv = 1.0 / h;
    for (const glm::vec3& p : m.positions) {
        points.emplace_back(static_cast<float>(p.x * inv), static_cast<float>(p.y * inv),
                            static_cast<float>(p.z * inv));
    }
    std::vector<openvdb::Vec3I> triangles;
    triangles.reserve(m.indices.size() / 3);
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        triangles.emplace_back(m.indices[t], m.indices[t + 1], m.indices[t + 2]);
    }
    const openvdb::math::Transform::Ptr xform = openvdb::math::Transform::createLinearTransform(h);
    openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> adapter(points,
                                                                                       triangles);
    // Two voxels: exact distances up to d + 1.4 h around the shell, enough for the exterior
    // voxels next to it; wider bands make OpenVDB dilate and recompute (3x slower).
    const auto band = static_cast<float>(std::max(2.0, d / h + 1.0));
    Voxelised out;
    out.closest = openvdb::Int32Grid::create(0);
    CancelInterrupter interrupter(progress);
    out.distance = openvdb::tools::meshToVolume<openvdb::FloatGrid>(
        interrupter, adapter, *xform, band, band, openvdb::tools::UNSIGNED_DISTANCE_FIELD,
        out.closest.get());
    out.distance->setTransform(xform);
    progress.throwIfCancelled();
    return out;
}

// The field meshed at 0: distance - d outside, negative in the shell and in everything the
// exterior fill did not reach (so no surface appears around hidden parts).
openvdb::FloatGrid::Ptr solidField(const openvdb::FloatGrid& distance, const ExteriorFill& fill,
                                   float d, float h) {
    openvdb::FloatGrid::Ptr phi = distance.deepCopy();
    const float background = distance.background();
    phi->tree().root().setBackground(background - d, /*updateChildNodes=*/true);
    for (auto leaf = phi->tree().beginLeaf(); leaf; ++leaf) {
        const std::array<std::uint64_t, 8> exterior = fill.exteriorMask(leaf->origin());
        for (openvdb::Index n = 0; n < openvdb::FloatTree::LeafNodeType::SIZE; ++n) {
            const float u = leaf->isValueOn(n) ? leaf->getValue(n) : background;
            float value = u - d;
            const bool outside = (exterior[n >> 6] >> (n & 63)) & 1u;
            if (!outside && value >= 0.0f) value = -h;
            leaf->setValueOnly(n, value);
        }
    }
    for (const openvdb::Coord& origin : fill.enclosedEmptyBlocksNearSurface()) {
        phi->tree().touchLeaf(origin)->fill(-h, /*active=*/false);
    }
    return phi;
}

// Iso-surface of phi at 0. Each vertex is pulled from the offset d back towards the closest
// input triangle (OpenVDB's closest-polygon grid) until it is `keep` away from it, and takes
// that triangle's colour: the shell hugs the visible surface again, and sheets keep a
// thickness of 2 * keep so their two sides never coincide.
ProxyMesh extractSurface(const openvdb::FloatGrid& phi, const openvdb::Int32Grid& closest,
                         const ProxyMesh& input, double adaptivity, float keep) {
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(phi, points, triangles, quads, 0.0, adaptivity);
    ProxyMesh out;
    out.origin = input.origin;
    out.positions.reserve(points.size());
    out.colors.reserve(points.size());
    auto acc = closest.getConstAccessor();
    const std::size_t inputTriangles = input.indices.size() / 3;
    for (const openvdb::Vec3s& v : points) {
        glm::vec3 p(v.x(), v.y(), v.z());
        const openvdb::Coord c = phi.transform().worldToIndexNodeCentered(openvdb::Vec3d(v));
        const openvdb::Int32 tri = acc.getValue(c);
        if (tri >= 0 && static_cast<std::size_t>(tri) < inputTriangles) {
            const std::uint32_t* t = &input.indices[static_cast<std::size_t>(tri) * 3];
            const glm::vec3 q = surface::closestPoint(p, input.positions[t[0]],
                                                      input.positions[t[1]], input.positions[t[2]]);
            const float len = glm::length(p - q);
            if (len > keep) p = q + (p - q) * (keep / len);
            out.colors.push_back(input.colors[t[0]]);
        } else {
            out.colors.emplace_back(204, 204, 204, 255);
        }
        out.positions.push_back(p);
    }
    // volumeToMesh already winds polygons counter-clockwise seen from the positive side.
    out.indices.reserve(triangles.size() * 3 + quads.size() * 6);
    for (const openvdb::Vec3I& t : triangles)
        out.indices.insert(out.indices.end(), {t[0], t[1], t[2]});
    for (const openvdb::Vec4I& q : quads) {
        out.indices.insert(out.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    }
    return out;
}

void initialiseOpenVdb() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

} // namespace

ProxyMesh voxelShellHere(const ProxyMesh& input, double h, double d, const RemeshOptions& options,
                         const Progress& progress) {
    initialiseOpenVdb();
    Voxelised vox = voxelise(input, h, d, progress);
    const ExteriorFill fill(*vox.distance, static_cast<float>(d));
    progress.throwIfCancelled();
    openvdb::FloatGrid::Ptr phi =
        solidField(*vox.distance, fill, static_cast<float>(d), static_cast<float>(h));
    vox.distance.reset();
    const auto keep = static_cast<float>(h * options.keepVoxels);
    return extractSurface(*phi, *vox.closest, input, options.adaptivity, keep);
}

} // namespace hlod

HLOD_MODULE_ENTRY(hlod::VdbModule, vdb, &hlod::voxelShellHere)
