// Normal-ray texel sampling with a closest-point fallback, see SampleTexels.h.
#include "pipeline/proxy/atlas/SampleTexels.h"

#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

namespace hlod {

namespace {

struct SourceLookup {
    const SourceSurfaces& s;
    std::vector<MipLevels> mips;       // per material (empty levels: untextured)
    std::vector<float> texelsPerMetre; // per triangle: density of its texture's texels

    SourceLookup(const SourceSurfaces& sources, TextureMips& pyramids) : s(sources) {
        for (const SourceMaterial& m : s.materials)
            mips.push_back(m.texture ? pyramids.levelsOf(*m.texture) : MipLevels{});
        texelsPerMetre.assign(s.triangleCount(), 0.0f);
        for (std::size_t t = 0; t < s.triangleCount(); ++t) {
            const SourceMaterial& mat = s.materials[s.triangleMaterial[t]];
            if (!mat.texture) continue;
            const std::uint32_t a = s.indices[3 * t], b = s.indices[3 * t + 1],
                                c = s.indices[3 * t + 2];
            const float world =
                glm::length(glm::cross(s.positions[b] - s.positions[a], s.positions[c] - s.positions[a]));
            const glm::vec2 du = s.uvs[b] - s.uvs[a], dv = s.uvs[c] - s.uvs[a];
            const float uv = std::abs(du.x * dv.y - du.y * dv.x) *
                             static_cast<float>(mat.texture->width) *
                             static_cast<float>(mat.texture->height);
            texelsPerMetre[t] = world > 0.0f ? std::sqrt(uv / world) : 0.0f;
        }
    }

    // Linear RGBA of triangle t at barycentrics (w0, w1, w2).
    glm::vec4 colour(std::uint32_t t, const glm::vec3& w, float texelSize) const {
        const SourceMaterial& mat = s.materials[s.triangleMaterial[t]];
        const std::uint32_t a = s.indices[3 * t], b = s.indices[3 * t + 1], c = s.indices[3 * t + 2];
        glm::vec4 out = mat.factor * (w.x * s.colors[a] + w.y * s.colors[b] + w.z * s.colors[c]);
        if (mat.texture) {
            const glm::vec2 uv = w.x * s.uvs[a] + w.y * s.uvs[b] + w.z * s.uvs[c];
            out *= mips[s.triangleMaterial[t]].sample(uv, texelSize * texelsPerMetre[t]);
        }
        return out;
    }

    bool masked(std::uint32_t t) const {
        return s.materials[s.triangleMaterial[t]].alphaMode == AlphaMode::Mask;
    }

    bool cutOut(std::uint32_t t, const glm::vec4& c) const {
        const SourceMaterial& mat = s.materials[s.triangleMaterial[t]];
        return mat.alphaMode == AlphaMode::Mask && c.a < mat.alphaCutoff;
    }
};

// Linear -> 8-bit sRGB through a 4096-entry table (the curve's steepest step near 0 is below
// half a level at this spacing).
std::uint8_t srgbByte(float v) {
    static const std::vector<std::uint8_t> table = [] {
        std::vector<std::uint8_t> t(4097);
        for (int i = 0; i <= 4096; ++i)
            t[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(
                std::lround(linearToSrgb(static_cast<float>(i) / 4096.0f) * 255.0f));
        return t;
    }();
    const float x = std::clamp(v, 0.0f, 1.0f) * 4096.0f;
    return table[static_cast<std::size_t>(x + 0.5f)];
}

glm::u8vec4 toTexel(const glm::vec4& c) {
    return {srgbByte(c.r), srgbByte(c.g), srgbByte(c.b), 255};
}

} // namespace

void sampleTexels(const ProxySurface& proxy, const TexelCoverage& coverage,
                  const SourceSurfaces& sources, const SurfaceBvh& bvh, TextureMips& mips,
                  float reach, float texelSize, RgbaImage& image, std::vector<TexelState>& state) {
    const int w = coverage.width, h = coverage.height;
    image = RgbaImage(w, h, glm::u8vec4(0, 0, 0, 255));
    state.assign(static_cast<std::size_t>(w) * h, TexelState::Empty);
    const SourceLookup lookup(sources, mips);
    tbb::parallel_for(0, h, [&](int y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            const std::int32_t tri = coverage.triangle[i];
            if (tri < 0) continue;
            const glm::vec3& b = coverage.bary[i];
            const std::uint32_t ia = proxy.indices[3 * tri], ib = proxy.indices[3 * tri + 1],
                                ic = proxy.indices[3 * tri + 2];
            const glm::vec3 p =
                b.x * proxy.positions[ia] + b.y * proxy.positions[ib] + b.z * proxy.positions[ic];
            glm::vec3 n(0.0f);
            if (!proxy.normals.empty())
                n = b.x * proxy.normals[ia] + b.y * proxy.normals[ib] + b.z * proxy.normals[ic];
            if (!(glm::length(n) > 1e-12f))
                n = glm::cross(proxy.positions[ib] - proxy.positions[ia],
                               proxy.positions[ic] - proxy.positions[ia]);
            const float len = glm::length(n);
            n = len > 0.0f ? n / len : glm::vec3(0, 0, 1);
            // Nearest hit that is not cut out; colours are evaluated only for cut-out tests
            // and once for the winner.
            std::uint32_t best = 0xffffffffu;
            float bestT = std::numeric_limits<float>::infinity();
            glm::vec3 bestWeights(0.0f);
            bool crossedCutOut = false;
            bvh.forEachHit(p, n, -reach, reach, [&](const SegmentHit& hit) {
                const float d = std::abs(hit.t);
                if (d > bestT || (d == bestT && hit.triangle > best)) return;
                const glm::vec3 wts(1.0f - hit.bary.x - hit.bary.y, hit.bary.x, hit.bary.y);
                if (lookup.masked(hit.triangle) &&
                    lookup.cutOut(hit.triangle, lookup.colour(hit.triangle, wts, texelSize))) {
                    crossedCutOut = true;
                    return;
                }
                best = hit.triangle;
                bestT = d;
                bestWeights = wts;
            });
            if (best == 0xffffffffu && !crossedCutOut) {
                // Nothing along the normal: the closest surface point, searched within a few
                // budgets only (farther, the texel is left to the dilation).
                const ClosestPoint cp = bvh.closest(p, 16.0f * reach * reach);
                if (cp.triangle != 0xffffffffu) {
                    best = cp.triangle;
                    bestWeights = cp.bary;
                }
            }
            glm::vec4 bestColour(0.0f);
            if (best != 0xffffffffu) {
                bestColour = lookup.colour(best, bestWeights, texelSize);
                if (lookup.cutOut(best, bestColour)) {
                    crossedCutOut = true;
                    best = 0xffffffffu;
                }
            }
            if (best == 0xffffffffu) {
                state[i] = crossedCutOut ? TexelState::CutOut : TexelState::Empty;
                if (crossedCutOut) image.set(x, y, glm::u8vec4(0, 0, 0, 0));
                continue;
            }
            state[i] = TexelState::Opaque;
            image.set(x, y, toTexel(bestColour));
        }
    });
}

} // namespace hlod
