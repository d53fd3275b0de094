// `decimate` proxies: the aggregated children welded, then split into connected parts; parts
// smaller than the error budget are dropped and the others simplified one by one with quadric
// edge collapse (Garland & Heckbert 1997, as implemented by meshoptimizer's meshopt_simplify)
// until the next collapse would exceed the target (PartwiseSimplify.h).
//
// Error: meshoptimizer's own measure is an area-weighted RMS distance to the planes of the
// collapsed triangles, which real deviations exceed 1.5-3x on curved surfaces, so it is not
// used as the bound. Every simplified part is checked with a sampled two-sided Hausdorff test
// (DeviationCheck.h) against the part's welded input at the full check limit, and a failing
// part is redone with a smaller meshoptimizer target or kept as it is; so the proxy stays within
// `maxError` metres of its input (check limit simplifyFraction * maxError plus at most the weld
// displacement, a cell diagonal sqrt(3) * weldFraction * maxError). The one exception is the
// dropped parts: their bounding-box diagonal is below maxError, so each covers less than a
// pixel at the switch point (SmallParts.h), but nothing of the proxy needs to be near them.
// Topology is kept: holes and thin parts larger than the budget survive, open borders only
// collapse along themselves.
// Output: finished proxy (normals, render layout), never more triangles than the input.
// Deterministic: single-threaded, depends only on the input.
#pragma once

#include "pipeline/proxy/ProxyMesh.h"

namespace hlod {

struct DecimateOptions {
    // Weld cell size as a fraction of the error budget (see Weld.h).
    float weldFraction = 1.0f / 64.0f;
    // Fraction of the budget left to the simplifier (the rest covers welding: a cell diagonal
    // is sqrt(3) / 64 = 0.027 of the budget).
    float simplifyFraction = 0.97f;
};

ProxyMesh decimateProxy(ProxyMesh input, double maxError, const DecimateOptions& options = {});

// One meshopt_simplify call at meshoptimizer's own (RMS) error measure, no check.
std::vector<std::uint32_t> simplifyToError(const ProxyMesh& mesh, double maxError);

} // namespace hlod
