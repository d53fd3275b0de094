// `decimate` proxies: the aggregated children welded, parts smaller than the error budget
// dropped, then quadric edge-collapse simplification (Garland & Heckbert 1997, as implemented
// by meshoptimizer's meshopt_simplify) until the next collapse would exceed the budget.
//
// Error: meshoptimizer's own measure is an area-weighted RMS distance to the planes of the
// collapsed triangles, which real deviations exceed 1.5-3x on curved surfaces; each result is
// therefore checked with a sampled two-sided Hausdorff test (DeviationCheck.h) part by part and
// a failing part is redone with a smaller meshoptimizer target (PartwiseSimplify.h), so the proxy
// stays within `maxError` metres of its input (weld displacement included). Topology is kept: holes
// and thin parts larger than the budget survive, open borders only collapse along themselves.
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
