// The colour of every covered atlas texel, taken from the original surfaces the proxy stands
// for (issue 19; the "ray casting along the normal" of texture baking: Cignoni et al., "A
// general method for preserving attribute values on simplified meshes", IEEE Visualization
// 1998; Unreal's and Simplygon's material casters do the same).
//
// For a texel's point p on the proxy with interpolated normal n, the segment p + t n,
// |t| <= reach (reach = 1.5 x the node's error budget, the proxy deviates by at most the
// budget) is cast against the sources; the hit nearest to p wins (ties: lower triangle). Its
// colour is the glTF base colour there: factor x texture (trilinear, footprint = the atlas
// texel) x vertex colour. Hits on cut-out (MASK) texels below their cut-off are passed
// through; a segment that only crossed cut-out texels marks the texel CutOut. A segment that
// hits nothing takes the closest source point within 4 x reach instead (its cut-out test
// applies too); a texel with no source that near stays Empty and is dilated.
// Parallel over texel rows, each texel written by one task: deterministic for any thread count.
#pragma once

#include <vector>

#include "pipeline/proxy/atlas/DilateAtlas.h"
#include "pipeline/proxy/atlas/RasterizeCharts.h"
#include "pipeline/proxy/atlas/SourceSurfaces.h"
#include "pipeline/proxy/atlas/SurfaceBvh.h"
#include "pipeline/proxy/atlas/TextureMips.h"

namespace hlod {

struct ProxySurface {
    std::span<const glm::vec3> positions;
    std::span<const glm::vec3> normals; // empty: face normals
    std::span<const std::uint32_t> indices;
};

// Fills `image` (coverage size) with sRGB colour and alpha, and `state` per texel.
void sampleTexels(const ProxySurface& proxy, const TexelCoverage& coverage,
                  const SourceSurfaces& sources, const SurfaceBvh& bvh, TextureMips& mips,
                  float reach, float texelSize, RgbaImage& image, std::vector<TexelState>& state);

} // namespace hlod
