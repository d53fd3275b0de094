// `decimate` proxies: the aggregated children welded, simplified within what is left of the
// error budget, and cleared of parts the rest already stands for.
//
// Steps:
// 1. Weld (Weld.h weldCorners): corners within weldFraction * maxError merge whatever their
//    colour, but the two sides of a two-sided sheet stay apart (faces more than 120 degrees
//    apart), so that back-to-back faces do not form zero-volume pillows the simplifier could
//    slide anywhere at no cost. Moves a vertex by at most sqrt(3) * weldFraction * maxError.
// 2. Parts whose bounding-box diagonal is below maxError go (SmallParts.h: less than a pixel at
//    the switch point).
// 3. Simplification within the rest of the budget: maxError less the input's own error bound
//    (the children's proxies lie within their budgets of the originals, ProxyMesh.h) less the
//    weld's move. Errors compose: a child within e_c and a step within e - e_c keep the proxy
//    within e of the original meshes, exactly (before, each level was certified against its
//    children's proxies with its whole budget, so a parent could stray up to e + e_c from the
//    originals: 5 points of 101,849 on the engine sample's package, the worst 1.066 e). Two
//    certified simplifiers run one after the other: collapses certified by successive mapping
//    (CertifiedSimplify.h, local and cheap) as far as they go, then quadric collapses certified
//    by the distance test against the input (BoundedSimplify.h), which continues where the
//    mapping's accumulated moves stop it (they stop it at 60-70 % of the triangles the distance
//    test reaches on curved CAD parts; the distance test costs 3-8 times as much per collapse).
// 4. Parts within the limit of the parts kept before them go (CoveredParts.h: the back face of
//    a sheet, a kerb along a road).
// Early finish: a node whose proxy keeps more than 60 % of its input triangles is dissolved by
// any useful proxy ratio (ProxyBaker.h); when meshoptimizer's quick pass at the same error
// keeps more than that, the certified steps are skipped and the node is dissolved. The
// prediction is not exact: on torcs-spring it skips 37 clusters of 528 dissolved that a full
// run would have kept (share 31.5 -> 31.1 %) and saves 13 % of the bake's CPU; on the engine
// and the cruiser none. The result is still certified.
// Guarantee: the proxy lies within maxError of the original meshes and every point of them
// within maxError of the proxy, except the parts of step 2; its errorBound says so.
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
