// `remesh` proxies: a watertight shell around the children with hidden interior removed, the
// open-source stand-in for Simplygon's remesher used by the thesis (5.3: "a new watertight mesh
// with no redundant triangles, i.e. triangles hidden beneath the surface").
//
// Method (OpenVDB, Museth 2013):
//  1. parts smaller than the budget are dropped (as in `decimate`);
//  2. unsigned distance field of the triangles on a sparse grid of voxel size h ~ budget
//     (meshToVolume, exact point-triangle distances in a narrow band), which works for the
//     open, non-manifold, self-intersecting meshes games and CAD exports are made of;
//  3. the voxels closer than d (> h/2) form a shell with no 6-connected leaks, whatever the
//     orientation of the surface: thin walls and gaps narrower than 2d are sealed;
//  4. exterior flood fill from outside the bounding box (ExteriorFill): everything the fill
//     does not reach - the inside of closed objects, boxes inside boxes, cavities - is solid;
//  5. iso-surface of that solid at offset d (volumeToMesh), quads split into triangles; each
//     vertex is pulled back towards the closest input triangle (OpenVDB's closest-polygon
//     grid) to a distance `keep`, and takes that triangle's colour;
//  6. quadric simplification within the budget of the shell (checked one way: every point of
//     the result lies within the budget of the shell, DeviationCheck.h), then normals.
// Error, as the issue defines the method ("a watertight shell at voxel size ~e, then
// simplified within e"): the shell deviates from the visible input by about a voxel (keep
// outside flat parts, up to ~1.4 h where pulling back chamfers concave corners), the result
// deviates at most the budget from the shell, so at most about twice the budget from the
// input; `decimate` is the method with the strict single-budget bound. Hidden parts are gone
// by design; a part thinner than 2 keep becomes a closed slab 2 keep thick; gaps narrower
// than 2d are closed.
// Cancellation: checks `progress` during voxelisation and between steps; throws
// Error(Cancelled). Deterministic for any number of threads (OpenVDB's parallel kernels write
// disjoint voxels and order their output by leaf).
#pragma once

#include "pipeline/core/Progress.h"
#include "pipeline/proxy/ProxyMesh.h"

namespace hlod {

struct RemeshOptions {
    float voxelFraction = 1.0f; // h = voxelFraction * budget
    float shellVoxels = 0.6f;   // d = shellVoxels * h (must exceed 0.5 to seal, see above)
    float keepVoxels = 0.2f;    // keep = keepVoxels * h, offset left after pulling back
    // OpenVDB volumeToMesh adaptivity. 0: adaptive meshes merge cells into polygons that
    // meshoptimizer then cannot simplify within the budget (measured: no reduction at all).
    float adaptivity = 0.0f;
    // Voxel count guard: above this many voxels along the largest axis h grows instead.
    int maxVoxelsPerAxis = 1024;
    // Baker policy (ProxyBaker.cpp makeProxy): a node whose `decimate` proxy has at most this
    // many triangles keeps it without remeshing; a shell never beats it and costs a voxel grid.
    int decimateBelowTriangles = 128;
};

ProxyMesh remeshProxy(ProxyMesh input, double maxError, const Progress& progress = {},
                      const RemeshOptions& options = {});

} // namespace hlod
