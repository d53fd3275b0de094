// A baked base-colour atlas for one proxy (issue 19, docs/architecture.md): the proxy's own
// triangles get UV charts (Charts.h) packed into one image (PackCharts.h) at about one texel
// per screen pixel at the node's switch distance, every texel filled from the original
// surfaces the proxy stands for (SampleTexels.h), the rest dilated (DilateAtlas.h) and the
// image encoded as JPEG when opaque, PNG when it carries a cut-out.
//
// Input: the final proxy geometry (positions, normals, indices in the node's frame), the
// sources in the same frame (SourceSurfaces.h), the node's error budget e (metres: the proxy
// deviates by at most e, so the cast reaches 1.5 e) and the texel size (metres, node diameter
// / S for one texel per pixel at the switch).
// Output: the proxy with vertices split at chart seams (positions, normals and colours copied,
// one uv per vertex) and its ProxyAtlas. A proxy without triangles, sources without
// triangles, or (skipUntextured) sources without any texture: returned unchanged (no atlas).
// Deterministic for any thread count (each stage is); the image depends on the proxy, the
// sources (geometry, uvs, vertex colours, materials and texture texels) and the options.
#pragma once

#include "pipeline/proxy/ProxyMesh.h"
#include "pipeline/proxy/atlas/SourceSurfaces.h"
#include "pipeline/proxy/atlas/TextureMips.h"

namespace hlod {

struct AtlasOptions {
    bool enabled = true; // false: vertex colours only (`--proxy-textures off`)
    int maxSize = 2048;  // atlas side cap, texels (power of two)
    int padding = 2;     // gutter texels around every chart
    int jpegQuality = 90;
    float maxNormalDegrees = 60.0f; // chart normal cone (Charts.h)
    // Sources without any texture: keep the vertex colours (they already carry factor x
    // vertex colour; an atlas would add bake time and bytes for little: godot-room measures the
    // same with and without).
    bool skipUntextured = true;
};

ProxyMesh bakeAtlas(const ProxyMesh& proxy, const SourceSurfaces& sources, double errorBudget,
                    double texelSize, const AtlasOptions& options, TextureMips& mips);

} // namespace hlod
