// The thesis' baseline, configuration (b) of chapter 6: a per-mesh discrete LOD chain of four
// consecutive reductions, each keeping 40% of the previous level (Simplygon's reduction
// processor in the thesis; meshoptimizer's quadric simplifier here, driven by triangle count
// with no error limit). meshoptimizer may stop short of a target when the topology allows no
// further collapse (tiny closed parts); the level then keeps what it reached, and a level that
// would not remove anything ends the chain.
//
// Counted per mesh instance (what a renderer holds and draws), like SceneStats::triangles.
// Deterministic; parallel over unique meshes.
#pragma once

#include <cstddef>
#include <vector>

#include "pipeline/scene/Scene.h"

namespace hlod {

struct DlodParams {
    int levels = 4;    // reductions after the original
    double keep = 0.4; // fraction of the previous level's triangles each reduction keeps
};

// The reduced meshes of one chain (original excluded), attributes carried over.
std::vector<Mesh> buildDlodChain(const Mesh& mesh, const DlodParams& params = {});

// How far each level of `chain` deviates from `original` (two-sided Hausdorff distance, in the
// mesh's own units), measured to within 1 % by bisection on the certificate of
// DeviationCheck.h (withinDistanceOf both ways). A renderer shows a level only where this
// deviation projects to at most its pixel error, as HLOD proxies are shown (the thesis' screen
// size thresholds alone showed torn, spiky far levels: a count-driven reduction can move a
// surface by metres).
std::vector<double> dlodDeviations(const Mesh& original, const std::vector<Mesh>& chain);

struct DlodSummary {
    std::size_t triangles = 0; // instanced, original levels included
    std::size_t vertices = 0;
    std::size_t meshes = 0; // one per level per instance
    std::size_t bytes = 0;  // geometry bytes as glTF buffers (BakeStats.h meshBytes)
    double seconds = 0.0;
};

// Throws Error(InvalidArgument) for levels outside [0, 16] or keep outside (0, 1).
DlodSummary summarizeDlodChains(const Scene& scene, const DlodParams& params = {}, int threads = 0);

} // namespace hlod
