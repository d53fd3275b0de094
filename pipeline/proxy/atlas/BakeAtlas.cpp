// The atlas bake's stages in order, see BakeAtlas.h.
#include "pipeline/proxy/atlas/BakeAtlas.h"

#include <algorithm>
#include <map>

#include "pipeline/io/ImageDecode.h"
#include "pipeline/io/TextureImage.h"
#include "pipeline/proxy/atlas/Charts.h"
#include "pipeline/proxy/atlas/PackCharts.h"
#include "pipeline/proxy/atlas/SampleTexels.h"

namespace hlod {

namespace {

// The proxy with one vertex per (vertex, chart) pair, uvs from the layout.
ProxyMesh splitAtSeams(const ProxyMesh& proxy, const Charting& charting, const AtlasLayout& layout,
                       std::vector<glm::vec2>& cornerTexels) {
    ProxyMesh out;
    out.origin = proxy.origin;
    out.errorBound = proxy.errorBound;
    const bool normals = proxy.normals.size() == proxy.positions.size();
    const bool colors = proxy.colors.size() == proxy.positions.size();
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> remap;
    const std::size_t n = proxy.indices.size() / 3;
    cornerTexels.resize(n * 3);
    out.indices.reserve(proxy.indices.size());
    for (std::size_t t = 0; t < n; ++t) {
        const std::uint32_t chart = charting.chartOf[t];
        const ChartPlacement& place = layout.placements[chart];
        for (int k = 0; k < 3; ++k) {
            const glm::vec2 texel = glm::vec2(place.offset + layout.padding) +
                                    charting.cornerCoords[3 * t + k] / layout.texelSize;
            cornerTexels[3 * t + k] = texel;
            const std::uint32_t v = proxy.indices[3 * t + k];
            auto [it, added] =
                remap.try_emplace({v, chart}, static_cast<std::uint32_t>(out.positions.size()));
            if (added) {
                out.positions.push_back(proxy.positions[v]);
                if (normals) out.normals.push_back(proxy.normals[v]);
                if (colors) out.colors.push_back(proxy.colors[v]);
                // A vertex shared by triangles of one chart has one place in it.
                out.uvs.push_back(texel / glm::vec2(layout.width, layout.height));
            }
            out.indices.push_back(it->second);
        }
    }
    return out;
}

std::shared_ptr<const ProxyAtlas> encodeAtlas(RgbaImage image, bool mask, int quality) {
    auto atlas = std::make_shared<ProxyAtlas>();
    atlas->mask = mask;
    if (!mask)
        for (std::size_t i = 3; i < image.pixels.size(); i += 4)
            image.pixels[i] = 255;
    const EncodedImage encoded = mask ? encodePng(image) : encodeJpeg(image, quality);
    atlas->encoded = encoded.bytes;
    atlas->mimeType = encoded.mimeType;
    std::string why;
    auto decoded = decodeImage(atlas->encoded, why);
    atlas->image =
        std::make_shared<const RgbaImage>(decoded ? std::move(*decoded) : std::move(image));
    return atlas;
}

} // namespace

ProxyMesh bakeAtlas(const ProxyMesh& proxy, const SourceSurfaces& sources, double errorBudget,
                    double texelSize, const AtlasOptions& options, TextureMips& mips) {
    if (!options.enabled || proxy.empty() || sources.triangleCount() == 0 || !(texelSize > 0.0))
        return proxy;
    const bool textured = std::any_of(sources.materials.begin(), sources.materials.end(),
                                      [](const SourceMaterial& m) { return m.texture != nullptr; });
    if (options.skipUntextured && !textured) return proxy;
    const Charting charting = buildCharts(proxy.positions, proxy.indices, options.maxNormalDegrees);
    const AtlasLayout layout = packCharts(charting.charts, static_cast<float>(texelSize),
                                          options.maxSize, options.padding);
    if (layout.width == 0) return proxy;
    std::vector<glm::vec2> cornerTexels;
    ProxyMesh out = splitAtSeams(proxy, charting, layout, cornerTexels);
    std::vector<std::vector<std::uint32_t>> chartTriangles;
    for (const Chart& c : charting.charts)
        chartTriangles.push_back(c.triangles);
    const TexelCoverage coverage =
        rasterizeCharts(layout.width, layout.height, cornerTexels, chartTriangles);
    const SurfaceBvh bvh(sources.positions, sources.indices);
    RgbaImage image;
    std::vector<TexelState> state;
    const ProxySurface surface{proxy.positions, proxy.normals, proxy.indices};
    sampleTexels(surface, coverage, sources, bvh, mips, static_cast<float>(1.5 * errorBudget),
                 layout.texelSize, image, state);
    const bool mask = std::any_of(state.begin(), state.end(),
                                  [](TexelState s) { return s == TexelState::CutOut; });
    dilateAtlas(image, state, 2 * options.padding + 2);
    out.atlas = encodeAtlas(std::move(image), mask, options.jpegQuality);
    return out;
}

} // namespace hlod
