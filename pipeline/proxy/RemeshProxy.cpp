// Voxel remeshing with hidden-interior removal (OpenVDB level sets, Museth 2013; thesis 5.3's
// remesher), see RemeshProxy.h for the steps and the error budget.
#include "pipeline/proxy/RemeshProxy.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include "pipeline/core/Error.h"
#include "pipeline/proxy/DecimateProxy.h"
#include "pipeline/proxy/ExteriorFill.h"
#include "pipeline/proxy/ProxyFinish.h"
#include "pipeline/proxy/SmallParts.h"
#include "pipeline/proxy/Weld.h"

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
    // The band must hold distances up to d plus two voxels, so the shell boundary and the
    // exterior voxels next to it carry exact values for the iso-surface.
    const auto band = static_cast<float>(d / h + 2.5);
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
        for (openvdb::Index n = 0; n < openvdb::FloatTree::LeafNodeType::SIZE; ++n) {
            const openvdb::Coord c = leaf->offsetToGlobalCoord(n);
            const float u = leaf->isValueOn(n) ? leaf->getValue(n) : background;
            float value = u - d;
            if (!fill.isExterior(c) && value >= 0.0f) value = -h;
            leaf->setValueOnly(n, value);
        }
    }
    for (const openvdb::Coord& origin : fill.enclosedEmptyBlocksNearSurface()) {
        phi->tree().touchLeaf(origin)->fill(-h, /*active=*/false);
    }
    return phi;
}

ProxyMesh extractSurface(const openvdb::FloatGrid& phi, const openvdb::Int32Grid& closest,
                         const ProxyMesh& input, double adaptivity) {
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(phi, points, triangles, quads, 0.0, adaptivity);
    ProxyMesh out;
    out.origin = input.origin;
    out.positions.reserve(points.size());
    out.colors.reserve(points.size());
    auto acc = closest.getConstAccessor();
    for (const openvdb::Vec3s& p : points) {
        out.positions.emplace_back(p.x(), p.y(), p.z());
        // Colour of the input triangle nearest to the voxel the vertex lies in.
        const openvdb::Coord c = phi.transform().worldToIndexNodeCentered(openvdb::Vec3d(p));
        const openvdb::Int32 tri = acc.getValue(c);
        if (tri >= 0 && static_cast<std::size_t>(tri) * 3 < input.indices.size()) {
            out.colors.push_back(input.colors[input.indices[static_cast<std::size_t>(tri) * 3]]);
        } else {
            out.colors.emplace_back(204, 204, 204, 255);
        }
    }
    // OpenVDB winds polygons clockwise seen from the positive (outer) side; flip to CCW.
    out.indices.reserve(triangles.size() * 3 + quads.size() * 6);
    for (const openvdb::Vec3I& t : triangles) out.indices.insert(out.indices.end(), {t[0], t[2], t[1]});
    for (const openvdb::Vec4I& q : quads) {
        out.indices.insert(out.indices.end(), {q[0], q[2], q[1], q[0], q[3], q[2]});
    }
    return out;
}

void initialiseOpenVdb() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

} // namespace

ProxyMesh remeshProxy(ProxyMesh input, double maxError, const Progress& progress,
                      const RemeshOptions& options) {
    initialiseOpenVdb();
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

    Voxelised vox = voxelise(input, h, d, progress);
    const ExteriorFill fill(*vox.distance, static_cast<float>(d));
    progress.throwIfCancelled();
    openvdb::FloatGrid::Ptr phi =
        solidField(*vox.distance, fill, static_cast<float>(d), static_cast<float>(h));
    vox.distance.reset();
    ProxyMesh shell = extractSurface(*phi, *vox.closest, input, options.adaptivity);
    phi.reset();
    vox.closest.reset();
    progress.throwIfCancelled();

    // What the offset and the sampling have not used of the budget goes to the simplifier.
    const double remaining = std::max(maxError - d - 0.25 * h, 0.1 * maxError);
    weldVertices(shell, 0.0f);
    shell.indices = simplifyWithinError(shell, remaining);
    compactMesh(shell);
    dropSmallParts(shell, static_cast<float>(maxError));
    finishProxy(shell);
    return shell;
}

} // namespace hlod
