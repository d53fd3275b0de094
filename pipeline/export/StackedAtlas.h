// Leaf textures stacked in V into shared pages (issue 27: a leaf group costs one draw per page,
// not one per texture).
//
// Why: at eye level a runtime draws the nearby leaf groups whole, and a group's merged leaves
// cost one draw per look (TileContent.h). On a textured level most looks differ only in their
// texture, so a group of 30 objects with 20 textures costs 20 draws. Put those textures into
// one image and the leaves share one material: one draw.
//
// How, exactly (no resampling, no change of what any texel shows):
// - A page is an image of width W with textures stacked one above the other ("bands"). A
//   texture of width w sits in a page with W = w, or, when w < kAtlasMinWidth divides it, with
//   W = kAtlasMinWidth, its columns repeated W / w times. U keeps repeating: u' = u * w / W
//   samples column u * w mod w of the texture, also across the seam (the page wraps at W, a
//   multiple of w).
// - V: each triangle is moved by whole periods so its v lies in [0, k] (the texture repeats,
//   so that shows the same texels), then v' = (top + v * h) / H, where the band holds the
//   texture's h rows k times over: k is the most periods any triangle of the texture's meshes
//   spans from a period's start (a kerb strip running v 0.2..2.7 needs 3), at most
//   kAtlasMaxPeriods (a mesh whose triangles span more keeps its own texture: terrain tiled
//   over dozens of periods would multiply the page's texels). Vertices that two triangles
//   move differently are split (a triangle on a period's edge takes the move its vertices
//   already have).
// - Filtering: each band is padded above and below. The kAtlasWrapRows rows next to it hold
//   the texture's rows wrapped (its last rows above, its first below), so bilinear filtering
//   at a band's edge reads what the repeating texture holds there, exactly at mip level 0 and
//   up to level log2(kAtlasWrapRows); the rest hold the texture's mean colour, which is what
//   its own distant mip levels converge to, so a band's edge blends towards its own mean, not
//   its neighbour's, up to the level where one texel covers the whole padded band
//   (kAtlasPadRows rows each side at least, more for short textures so that every band spans
//   kAtlasMinSlotRows: thin kerbs of 64-row textures are seen from far). Beyond, bands blend;
//   they are ordered by luminance so neighbours look alike. Mean rows cost next to nothing in
//   the PNG. torcs-spring automatic path (textured): 8 wrapped rows only 39.5 dB, + mean rows
//   to 32: 39.9 dB, + slots of 256 rows: 40.2 dB (groups whole and no stacking: 41.3 dB).
// - Which textures: those of opaque and cut-out materials whose texture file is written as PNG
//   (a JPEG would be re-encoded lossily or grow as PNG: it keeps its own file), whose emissive
//   texture is none or the base colour texture itself (both then read the page), used by meshes
//   with uvs that fit into a band. A texture some of whose meshes do not fit needs its own file as
//   well: stored twice, so it is stacked only when the meshes that fit hold most of its
//   triangles (cg57's 2048-px hull texture, half its triangles fitting, grew the package 23 %;
//   torcs-spring's grass, mostly fitting, saves 20 draws a frame on the drive for 3 % of bytes).
//   A page that would hold one texture is not made (it merges nothing). Blended materials keep
//   their textures. Textures with translucent texels (cut-outs: coverage is a threshold of
//   alpha, so any blend of a neighbour's alpha at a distant mip level shows) go to pages of
//   their own, next to other cut-outs only (torcs-spring drive with them among opaque
//   textures: 52.6 dB, min 39.6; kept apart: min 45.5). Embedded textures are not written at all
//   (TileContent.h).
// - Which page: textures of one page width, and cut-outs apart from the rest, ordered along a
//   Z-curve of where they are used (the mean of the box centres of their instances), fill
//   pages of at most kAtlasPageRows rows in that order, so the textures of one neighbourhood
//   (one leaf group) share a page.
//   kAtlasPageRows = 8192 stays under the texture size limit of current desktop and mobile
//   GPUs (WebGL 2 runtimes report 8192-16384).
//
// Contract: a pure function of the scene (materials, textures, meshes, instance placement):
// the package writer and `hlod bench` build the same pages and the same uvs. Deterministic.
// Memory: the pages' pixels (about the stacked textures' size times their repeat).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "pipeline/scene/RgbaImage.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

inline constexpr int kAtlasPageRows = 8192;
inline constexpr int kAtlasPadRows = 32;
inline constexpr int kAtlasWrapRows = 8;
inline constexpr int kAtlasMinSlotRows = 256;
inline constexpr int kAtlasMinWidth = 256;
inline constexpr int kAtlasMaxPeriods = 4;

// Where a texture sits: rows [top, top + rows * periods) of `page` (the texture's `rows` rows
// `periods` times over), its columns repeated `repeat` times.
struct AtlasBand {
    int page = -1;
    int top = 0;
    int rows = 0;
    int repeat = 1;
    int periods = 1;
};

// A mesh's uvs moved into a band: vertex i of the result is vertex source[i] of the mesh.
struct StackedUvs {
    std::vector<std::uint32_t> source;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;
};

// The fewest whole periods every triangle's v lies within after moving it by whole periods (1:
// one period); 0 when the mesh has no uvs or a coordinate is not finite.
int periodsNeeded(const Mesh& mesh);

// The mesh's uvs in `band` of a page `pageRows` high; nullopt when a triangle's v spans more
// than band.periods (periodsNeeded(mesh) > band.periods).
std::optional<StackedUvs> stackUvs(const Mesh& mesh, const AtlasBand& band, int pageRows);

// `mesh` with every stream gathered through `stacked` (uvs and indices from it).
Mesh stackedMesh(const Mesh& mesh, const StackedUvs& stacked);

class StackedAtlases {
public:
    // `pixels` false: the bands only (the pages stay empty images), for layouts.
    explicit StackedAtlases(const Scene& scene, bool pixels = true);

    // The band of `material`'s texture; null when its leaves keep their own texture.
    const AtlasBand* band(Id material) const;
    // Whether `mesh` is drawn from its material's band (its uvs fit the band's periods).
    bool stacks(Id mesh) const { return mesh < meshStacks_.size() && meshStacks_[mesh]; }
    const std::vector<RgbaImage>& pages() const { return pages_; }

private:
    std::vector<AtlasBand> byTexture_; // per scene texture; page -1 = not stacked
    std::vector<Id> textureOf_;        // per material: its texture when stackable, else kNoId
    std::vector<bool> meshStacks_;     // per mesh
    std::vector<RgbaImage> pages_;
};

} // namespace hlod
