// The voxel part of the `remesh` method (RemeshProxy.h steps 2-5): OpenVDB's distance field,
// the exterior fill and the iso-surface pulled back towards the input, built as the on-demand
// module libhlod-vdb.so (core/OnDemand.h) so that processes which never remesh do not load
// OpenVDB (26 MB resident).
#pragma once

#include "pipeline/core/Progress.h"
#include "pipeline/proxy/ProxyMesh.h"
#include "pipeline/proxy/RemeshProxy.h"

namespace hlod {

struct VdbModule {
    // The shell around `input` (welded, small parts dropped) at voxel size h and offset d:
    // unsimplified, its vertices pulled back to options.keepVoxels * h from the input, with the
    // colour of the closest input triangle. Throws Error(Cancelled) when `progress` says so.
    ProxyMesh (*voxelShell)(const ProxyMesh& input, double h, double d,
                            const RemeshOptions& options, const Progress& progress);
};

ProxyMesh voxelShellHere(const ProxyMesh& input, double h, double d, const RemeshOptions& options,
                         const Progress& progress);

} // namespace hlod

extern "C" const hlod::VdbModule* hlod_module_vdb();
