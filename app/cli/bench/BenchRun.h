// `hlod bench`: the thesis' evaluation (chapter 6) reproduced on one scene. Builds every
// requested configuration (Original, DLOD chain, HLOD sphere / AABB k=0,1,2 / octree), flies
// the camera path, renders each frame of each configuration offscreen with VTK and measures
// draw calls, triangles, render time and image error against the Original frame.
//
// Per frame and configuration:
// - Original: every instance whose bounding sphere touches the frustum is drawn.
// - DLOD chain: the same instances, each at the coarsest level of its chain (4 reductions
//   keeping 40 % each, DlodChain.h) whose measured deviation from the original (two-sided
//   Hausdorff, dlodDeviations) covers at most the pixel error of the 1080 px reference
//   viewport at the instance's distance: the rule the proxies follow at their switch. (The
//   thesis' projected-size thresholds showed count-driven reductions that had torn a mesh.)
// - HLOD, drawn as its package (--draw package, the default): the tiles `hlod build` exports
//   (PackageLayout.h), selected as a 3D Tiles runtime selects them (REPLACE refinement, a tile
//   culled by its box, refined when its screen-space error at the distance to its box exceeds
//   the pixel error scaled to the render height, as 3d-tiles-renderer and CesiumJS do). A proxy
//   tile is one draw; a leaf-group tile draws its instanced leaves one by one and its other
//   leaves merged into one mesh per look, as the GLB stores them. Draw calls, triangles and
//   image are what a runtime gets from the package (a group is drawn whole, also its leaves
//   outside the frustum).
// - HLOD, one draw per node (--draw nodes, the thesis' count): the draw list of the front
//   cache selection (LodSelection.h, thesis Algorithm 5), every leaf mesh its own draw.
// S in render pixels is the bake's screen size (--screen-size, default 300 px at the bake's
// reference viewport of 1080 px) scaled to the render height: S * height / 1080, so nodes
// switch at the distances their proxies were baked for (the proxy error there stays <= 1 px
// of the reference viewport).
// Frame time is the wall time of vtkRenderWindow::Render() plus glFinish (selection and pixel
// read-back excluded); before timing, each configuration is rendered once with all its
// drawables visible so every buffer is on the GPU. Frames are rendered frame-major (all
// configurations of frame 0, then of frame 1, ...), so slow drift of the machine hits every
// configuration alike.
// Image error per frame against the Original frame: PSNR, differing pixels, mean FLIP at the
// camera's own pixels per degree (Flip.h), and popping where the selection switches a level of
// detail (Popping.h; FrameMetrics.h).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "OffscreenRenderer.h"
#include "pipeline/graph/PipelineGraph.h"

namespace hlod::cli {

enum class HlodDraw { Package, Nodes };

struct BenchOptions {
    std::filesystem::path out;
    int frames = 300;
    int width = 640;
    int height = 360;
    std::vector<std::string> configs; // keys: original dlod sphere aabb0 aabb1 aabb2 octree
    // The Cluster and Bake parameters of every HLOD configuration (their declarations' defaults
    // and the flags given; each configuration sets its own volume and k). The bake's S is meant
    // for the 1080 px reference viewport.
    ParamValues cluster = defaultValues(NodeKind::Cluster);
    ParamValues bake = defaultValues(NodeKind::Bake);
    std::optional<std::filesystem::path> pathFile;
    Shading shading = Shading::Geometry;
    HlodDraw draw = HlodDraw::Package;
    // Also write frames/NNNNN-KEY.png for every frame and configuration, and each frame's
    // camera as frames/NNNNN-camera.json ({eye, target, up, fovDeg, near, far, width, height}).
    bool frameImages = false;
};

inline const std::vector<std::string> kBenchConfigs{"original", "dlod",  "sphere", "aabb0",
                                                    "aabb1",    "aabb2", "octree"};

// Benchmarks the scene `importNode` of `graph` produced (it must have run): every HLOD
// configuration is a Cluster -> Bake branch added to `graph` and run by it. Throws hlod::Error;
// writes summary.json last (and removes an old one first).
void runBench(PipelineGraph& graph, NodeId importNode, const BenchOptions& options);

} // namespace hlod::cli
