// `decimate` proxies: the aggregated children welded, simplified within the error budget,
// and cleared of parts the rest already stands for.
//
// Steps:
// 1. Weld (Weld.h weldCorners): corners within weldFraction * maxError merge whatever their
//    colour, but the two sides of a two-sided sheet stay apart (faces more than 120 degrees
//    apart), so that back-to-back faces do not form zero-volume pillows the simplifier could
//    slide anywhere at no cost. Moves a vertex by at most sqrt(3) * weldFraction * maxError.
// 2. Parts whose bounding-box diagonal is below maxError go (SmallParts.h: less than a pixel at
//    the switch point).
// 3. Simplification within the rest of the budget, (1 - sqrt(3) * weldFraction) * maxError,
//    certified both ways (BoundedSimplify.h: quadric edge collapses, Garland & Heckbert 1997,
//    each checked against the input, repaired by locks until the Hausdorff certificate holds).
// 4. Parts within that limit of the parts kept before them go (CoveredParts.h: the back face of
//    a sheet, a kerb along a road).
// Guarantee: the proxy lies within maxError of its input and every point of the input lies
// within maxError of the proxy, except the parts of step 2.
// Output: finished proxy (normals, render layout), never more triangles than the input.
// Deterministic: single-threaded, depends only on the input.
#pragma once

#include "pipeline/proxy/ProxyMesh.h"

namespace hlod {

struct DecimateOptions {
    // Weld tolerance as a fraction of the error budget (see Weld.h); the simplifier gets the
    // rest of the budget, 1 - sqrt(3) * weldFraction (0.973 at 1/64).
    float weldFraction = 1.0f / 64.0f;
};

ProxyMesh decimateProxy(ProxyMesh input, double maxError, const DecimateOptions& options = {});

// One meshopt_simplify call at meshoptimizer's own (RMS) error measure, no check (the remesh
// method's quick pass).
std::vector<std::uint32_t> simplifyToError(const ProxyMesh& mesh, double maxError);

} // namespace hlod
