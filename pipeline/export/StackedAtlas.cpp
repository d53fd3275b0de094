// Textures stacked in V into shared pages (see StackedAtlas.h).
#include "pipeline/export/StackedAtlas.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <map>
#include <numeric>

#include "pipeline/cluster/Morton.h"

namespace hlod {

namespace {

// uvs this close to a period's edge count as on it (float uvs of authored 0 and 1).
constexpr double kPeriodSlack = 1e-5;

// The whole periods a triangle may be moved by so its v lies in [0, periods]: [lo, hi] (lo > hi
// when its v spans more than `periods` or a coordinate is not finite). u is left as it is: it
// repeats in the page as in the texture, and a vertex shared by triangles moved alike is not
// split.
struct Shifts {
    double lo = 1.0, hi = 0.0;
    bool any() const { return lo <= hi; }
    bool has(double k) const { return k >= lo && k <= hi; }
};

// The v range of triangle t; false when a coordinate is not finite.
bool vRange(const Mesh& mesh, std::size_t t, double& minV, double& maxV) {
    minV = INFINITY;
    maxV = -INFINITY;
    for (int c = 0; c < 3; ++c) {
        const glm::vec2 uv = mesh.uvs[mesh.indices[t * 3 + c]];
        if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return false;
        minV = std::min(minV, double(uv.y));
        maxV = std::max(maxV, double(uv.y));
    }
    return true;
}

Shifts shiftsOf(const Mesh& mesh, std::size_t t, int periods) {
    double minV, maxV;
    if (!vRange(mesh, t, minV, maxV)) return {};
    return {std::ceil(maxV - periods - kPeriodSlack), std::floor(minV + kPeriodSlack)};
}

// Rows above and below a band of `rows`: kAtlasPadRows, more for short textures so that every
// band with its padding spans kAtlasMinSlotRows (StackedAtlas.h "Filtering").
int padOf(int rows) { return std::max(kAtlasPadRows, (kAtlasMinSlotRows - rows + 1) / 2); }

bool isJpegFile(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".jpg" || ext == ".jpeg";
}

// Whether `m`'s texture can move into a page (StackedAtlas.h "Which textures").
bool stackableMaterial(const Scene& scene, const Material& m) {
    if (m.texture == kNoId || m.texture >= scene.textures.size()) return false;
    const Texture& tex = scene.textures[m.texture];
    if (!tex.image || tex.image->empty() || tex.file.empty() || isJpegFile(tex.file)) return false;
    if (m.emissiveTexture != kNoId && m.emissiveTexture != m.texture) return false;
    if (m.alphaMode == AlphaMode::Blend) return false; // see StackedAtlas.h "Which textures"
    return tex.image->height + 2 * padOf(tex.image->height) <= kAtlasPageRows &&
           tex.image->width <= kAtlasPageRows;
}

// The most periods a band of a texture `rows` high may hold: kAtlasMaxPeriods, fewer where the
// band would not fit a page.
int maxPeriods(int rows) {
    int k = kAtlasMaxPeriods;
    while (k > 1 && rows * k + 2 * padOf(rows * k) > kAtlasPageRows)
        --k;
    return k;
}

int pageWidthOf(int w) {
    return w < kAtlasMinWidth && kAtlasMinWidth % w == 0 ? kAtlasMinWidth : w;
}

// Copies `tex` into rows [band.top - pad, band.top + rows * periods + pad) of `page`
// (StackedAtlas.h "Filtering"): columns repeated, rows repeated `periods` times, the
// kAtlasWrapRows rows next to the band wrapped, the rest of the padding the texture's mean.
void fillBand(const RgbaImage& tex, const glm::vec4& mean, const AtlasBand& band, RgbaImage& page) {
    const std::size_t rowBytes = static_cast<std::size_t>(tex.width) * 4;
    auto byte = [](float v) {
        return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    };
    const glm::u8vec4 meanTexel(byte(linearToSrgb(mean.r)), byte(linearToSrgb(mean.g)),
                                byte(linearToSrgb(mean.b)), byte(mean.a));
    const int span = band.rows * band.periods, pad = padOf(span);
    for (int r = -pad; r < span + pad; ++r) {
        std::uint8_t* to = &page.pixels[static_cast<std::size_t>(band.top + r) * page.width * 4];
        if (r < -kAtlasWrapRows || r >= span + kAtlasWrapRows) {
            for (int x = 0; x < page.width; ++x)
                std::memcpy(to + x * 4, &meanTexel[0], 4);
            continue;
        }
        const int src = ((r % band.rows) + band.rows) % band.rows;
        const std::uint8_t* from = &tex.pixels[static_cast<std::size_t>(src) * rowBytes];
        for (int k = 0; k < band.repeat; ++k)
            std::memcpy(to + k * rowBytes, from, rowBytes);
    }
}

} // namespace

int periodsNeeded(const Mesh& mesh) {
    if (mesh.uvs.size() != mesh.positions.size() || mesh.indices.empty()) return 0;
    double need = 1.0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        double minV, maxV;
        if (!vRange(mesh, t, minV, maxV)) return 0;
        need = std::max(need, std::ceil(maxV - std::floor(minV + kPeriodSlack) - kPeriodSlack));
        if (need > kAtlasPageRows) return 0; // no band is that tall
    }
    return static_cast<int>(need);
}

std::optional<StackedUvs> stackUvs(const Mesh& mesh, const AtlasBand& band, int pageRows) {
    if (mesh.uvs.size() != mesh.positions.size()) return std::nullopt;
    StackedUvs out;
    out.indices.reserve(mesh.indices.size());
    // A vertex is split for every distinct shift of the triangles using it; the first shift
    // seen keeps the common case (one shift per vertex) off the map.
    struct First {
        double shift = 0.0;
        std::uint32_t index = ~0u;
    };
    std::vector<First> first(mesh.positions.size());
    std::map<std::pair<std::uint32_t, double>, std::uint32_t> more;
    const double rows = band.rows, top = band.top, repeat = band.repeat, periods = band.periods;
    auto emit = [&](std::uint32_t v, double shift) {
        out.source.push_back(v);
        const glm::vec2 uv = mesh.uvs[v];
        const double t = std::clamp(uv.y - shift, 0.0, periods);
        out.uvs.emplace_back(static_cast<float>(uv.x / repeat),
                             static_cast<float>((top + t * rows) / pageRows));
        return static_cast<std::uint32_t>(out.source.size() - 1);
    };
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Shifts shifts = shiftsOf(mesh, t, band.periods);
        if (!shifts.any()) return std::nullopt;
        // Where a triangle on a period's edge may move by two amounts, the one its vertices
        // already have (no split).
        double shift = shifts.hi;
        for (int c = 0; c < 3; ++c) {
            const First& f = first[mesh.indices[t * 3 + c]];
            if (f.index != ~0u && shifts.has(f.shift)) {
                shift = f.shift;
                break;
            }
        }
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t v = mesh.indices[t * 3 + c];
            First& f = first[v];
            if (f.index == ~0u) {
                f = {shift, emit(v, shift)};
                out.indices.push_back(f.index);
            } else if (f.shift == shift) {
                out.indices.push_back(f.index);
            } else {
                auto [it, added] = more.try_emplace({v, shift}, 0u);
                if (added) it->second = emit(v, shift);
                out.indices.push_back(it->second);
            }
        }
    }
    return out;
}

Mesh stackedMesh(const Mesh& mesh, const StackedUvs& stacked) {
    Mesh out;
    out.name = mesh.name;
    out.material = mesh.material;
    auto gather = [&](const auto& from, auto& to) {
        if (from.empty()) return;
        to.reserve(stacked.source.size());
        for (std::uint32_t v : stacked.source)
            to.push_back(from[v]);
    };
    gather(mesh.positions, out.positions);
    gather(mesh.normals, out.normals);
    gather(mesh.colors, out.colors);
    out.uvs = stacked.uvs;
    out.indices = stacked.indices;
    return out;
}

StackedAtlases::StackedAtlases(const Scene& scene, bool pixels)
    : byTexture_(scene.textures.size()), textureOf_(scene.materials.size(), kNoId),
      meshStacks_(scene.meshes.size(), false) {
    for (std::size_t m = 0; m < scene.materials.size(); ++m)
        if (stackableMaterial(scene, scene.materials[m]))
            textureOf_[m] = scene.materials[m].texture;
    // The periods each mesh's triangles span; a mesh stacks when its texture's band may be
    // that tall (StackedAtlas.h "V").
    std::vector<int> periodsOf(scene.textures.size(), 1), needOf(scene.meshes.size(), 0);
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const Mesh& mesh = scene.meshes[i];
        const Id t = mesh.material < textureOf_.size() ? textureOf_[mesh.material] : kNoId;
        if (t == kNoId) continue;
        needOf[i] = periodsNeeded(mesh);
        meshStacks_[i] = needOf[i] >= 1 && needOf[i] <= maxPeriods(scene.textures[t].image->height);
    }
    // A texture that some mesh must read on its own is stored twice if it is stacked too: only
    // when the meshes that fit hold most of its triangles (StackedAtlas.h "Which textures").
    std::vector<std::size_t> fitting(scene.textures.size(), 0), own(scene.textures.size(), 0);
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const Mesh& mesh = scene.meshes[i];
        const Id t = mesh.material < textureOf_.size() ? textureOf_[mesh.material] : kNoId;
        if (t != kNoId && !mesh.uvs.empty())
            (meshStacks_[i] ? fitting : own)[t] += mesh.triangleCount();
    }
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        if (!meshStacks_[i]) continue;
        const Id t = textureOf_[scene.meshes[i].material];
        if (own[t] > fitting[t])
            meshStacks_[i] = false;
        else
            periodsOf[t] = std::max(periodsOf[t], needOf[i]);
    }
    // Where each texture is used: the mean of its instances' box centres.
    std::vector<glm::dvec3> sum(scene.textures.size(), glm::dvec3(0.0));
    std::vector<std::size_t> uses(scene.textures.size(), 0);
    std::vector<std::optional<glm::dvec3>> centre(scene.meshes.size());
    for (const MeshInstance& inst : scene.instances) {
        if (!meshStacks_[inst.mesh]) continue;
        const Mesh& mesh = scene.meshes[inst.mesh];
        if (!centre[inst.mesh]) centre[inst.mesh] = mesh.localBounds().center();
        const Id t = textureOf_[mesh.material];
        sum[t] += glm::dvec3(scene.nodes[inst.node].world * glm::dvec4(*centre[inst.mesh], 1.0));
        ++uses[t];
    }
    std::vector<Id> used;
    for (Id t = 0; t < scene.textures.size(); ++t)
        if (uses[t] > 0) used.push_back(t);
    std::vector<std::uint64_t> codes;
    mortonCodes(
        used.size(), [&](std::size_t i) { return sum[used[i]] / double(uses[used[i]]); }, codes);
    std::vector<std::size_t> order(used.size());
    std::iota(order.begin(), order.end(), 0);
    // A page holds one width, and either cut-outs (textures with translucent texels) or not.
    std::vector<int> classOf(used.size());
    for (std::size_t i = 0; i < used.size(); ++i) {
        const RgbaImage& img = *scene.textures[used[i]].image;
        classOf[i] = pageWidthOf(img.width) * 2 + (img.hasTranslucentTexels() ? 1 : 0);
    }
    auto widthOf = [&](std::size_t i) { return classOf[i]; };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return std::tuple(widthOf(a), codes[a], used[a]) <
               std::tuple(widthOf(b), codes[b], used[b]);
    });
    // Fill pages in that order; a page holds one width.
    std::vector<std::vector<Id>> onPage;
    std::vector<int> pageWidth, pageRows;
    for (std::size_t i : order) {
        const int w = widthOf(i), span = scene.textures[used[i]].image->height * periodsOf[used[i]],
                  need = span + 2 * padOf(span);
        if (pageWidth.empty() || pageWidth.back() != w || pageRows.back() + need > kAtlasPageRows) {
            pageWidth.push_back(w);
            pageRows.push_back(0);
            onPage.emplace_back();
        }
        onPage.back().push_back(used[i]);
        pageRows.back() += need;
    }
    // A page of one texture merges nothing: the texture keeps its own file.
    for (std::size_t p = onPage.size(); p-- > 0;) {
        if (onPage[p].size() > 1) continue;
        for (std::size_t i = 0; i < scene.meshes.size(); ++i)
            if (meshStacks_[i] && textureOf_[scene.meshes[i].material] == onPage[p][0])
                meshStacks_[i] = false;
        onPage.erase(onPage.begin() + static_cast<std::ptrdiff_t>(p));
        pageWidth.erase(pageWidth.begin() + static_cast<std::ptrdiff_t>(p));
        pageRows.erase(pageRows.begin() + static_cast<std::ptrdiff_t>(p));
    }
    // Each texture's mean, as its materials got it on import (Material::textureMean).
    std::vector<glm::vec4> meanOf(scene.textures.size(), glm::vec4(1.0f));
    for (std::size_t m = 0; m < scene.materials.size(); ++m)
        if (textureOf_[m] != kNoId) meanOf[textureOf_[m]] = scene.materials[m].textureMean;
    // Inside a page, bands by mean luminance: where distant mip levels blend a band with its
    // neighbours (StackedAtlas.h "Filtering"), the neighbours look alike.
    for (std::size_t p = 0; p < onPage.size(); ++p) {
        std::vector<std::pair<float, Id>> byLuminance;
        for (Id t : onPage[p]) {
            const glm::vec4& mean = meanOf[t];
            byLuminance.emplace_back(0.2126f * mean.r + 0.7152f * mean.g + 0.0722f * mean.b, t);
        }
        std::sort(byLuminance.begin(), byLuminance.end());
        const int width = pageWidth[p] / 2; // the class: width and cut-out (above)
        RgbaImage& page = pixels ? pages_.emplace_back(width, pageRows[p]) : pages_.emplace_back();
        int top = 0;
        for (const auto& [luminance, t] : byLuminance) {
            const RgbaImage& img = *scene.textures[t].image;
            AtlasBand& b = byTexture_[t];
            b.page = static_cast<int>(p);
            const int span = img.height * periodsOf[t];
            b.top = top + padOf(span);
            b.rows = img.height;
            b.repeat = width / img.width;
            b.periods = periodsOf[t];
            if (pixels) fillBand(img, meanOf[t], b, page);
            top += span + 2 * padOf(span);
        }
    }
}

const AtlasBand* StackedAtlases::band(Id material) const {
    if (material >= textureOf_.size() || textureOf_[material] == kNoId) return nullptr;
    const AtlasBand& b = byTexture_[textureOf_[material]];
    return b.page < 0 ? nullptr : &b;
}

} // namespace hlod
