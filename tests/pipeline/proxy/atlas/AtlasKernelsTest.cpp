// The atlas bake's inner kernels against plain reference versions written the obvious way: the
// BVH's segment hits against every triangle tried in turn (axis-aligned segments on box faces
// included, where the slab test meets 0 * inf), the dilation against a pass over every texel,
// and bilinear sampling at wrapped, negative and huge uvs against the modulo wrap.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <tuple>

#include "pipeline/proxy/atlas/DilateAtlas.h"
#include "pipeline/proxy/atlas/SurfaceBvh.h"
#include "pipeline/scene/RgbaImage.h"

using namespace hlod;

namespace {

// Moeller-Trumbore as the BVH documents it (both faces, t in [tMin, tMax]).
bool referenceHit(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                  const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax,
                  float& tOut) {
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 pv = glm::cross(dir, e2);
    const float det = glm::dot(e1, pv);
    if (!(std::abs(det) > 1e-20f)) return false;
    const float inv = 1.0f / det;
    const glm::vec3 tv = origin - a;
    const float u = glm::dot(tv, pv) * inv;
    if (u < 0.0f || u > 1.0f) return false;
    const glm::vec3 qv = glm::cross(tv, e1);
    const float v = glm::dot(dir, qv) * inv;
    if (v < 0.0f || u + v > 1.0f) return false;
    tOut = glm::dot(e2, qv) * inv;
    return tOut >= tMin && tOut <= tMax;
}

// A grid of axis-aligned unit cubes (12 triangles each) plus random triangles: box faces make
// segments that run exactly in a slab plane.
void buildSoup(std::vector<glm::vec3>& positions, std::vector<std::uint32_t>& indices,
               std::mt19937& rng) {
    for (int x = 0; x < 4; ++x)
        for (int z = 0; z < 4; ++z) {
            const auto base = static_cast<std::uint32_t>(positions.size());
            for (int k = 0; k < 8; ++k)
                positions.push_back(glm::vec3(2 * x + (k & 1), (k >> 1) & 1, 2 * z + (k >> 2)));
            const std::uint32_t faces[12][3] = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5},
                                                {0, 4, 5}, {0, 5, 1}, {2, 3, 7}, {2, 7, 6},
                                                {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
            for (const auto& f : faces)
                for (std::uint32_t v : f)
                    indices.push_back(base + v);
        }
    std::uniform_real_distribution<float> at(-1.0f, 9.0f), size(-0.7f, 0.7f);
    for (int t = 0; t < 400; ++t) {
        const glm::vec3 centre(at(rng), at(rng) * 0.2f, at(rng));
        for (int k = 0; k < 3; ++k) {
            indices.push_back(static_cast<std::uint32_t>(positions.size()));
            positions.push_back(centre + glm::vec3(size(rng), size(rng), size(rng)));
        }
    }
}

} // namespace

TEST(AtlasKernels, BvhSegmentHitsAreExactlyTheTrianglesTriedOneByOne) {
    std::mt19937 rng(7);
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
    buildSoup(positions, indices, rng);
    const SurfaceBvh bvh(positions, indices);
    std::uniform_real_distribution<float> at(-1.0f, 9.0f), unit(-1.0f, 1.0f);
    std::uniform_int_distribution<int> pick(0, 3);
    std::size_t hits = 0, axisAligned = 0;
    for (int q = 0; q < 3000; ++q) {
        glm::vec3 origin(at(rng), at(rng) * 0.2f, at(rng));
        glm::vec3 dir(unit(rng), unit(rng), unit(rng));
        if (q % 2 == 0) { // along an axis, often exactly on a cube face's plane
            const int axis = pick(rng) % 3;
            dir = glm::vec3(0.0f);
            dir[axis] = q % 4 == 0 ? 1.0f : -1.0f;
            for (int k = 0; k < 3; ++k)
                if (k != axis && pick(rng) < 2) origin[k] = std::round(origin[k]);
            ++axisAligned;
        }
        if (!(glm::length(dir) > 0.0f)) continue;
        const float reach = 0.05f + 2.0f * std::abs(unit(rng));
        std::set<std::pair<std::uint32_t, float>> found, expected;
        bvh.forEachHit(origin, dir, -reach, reach, [&](const SegmentHit& hit) {
            EXPECT_TRUE(found.emplace(hit.triangle, hit.t).second) << "triangle visited twice";
        });
        for (std::uint32_t t = 0; t < indices.size() / 3; ++t) {
            float tHit = 0.0f;
            if (referenceHit(positions[indices[3 * t]], positions[indices[3 * t + 1]],
                             positions[indices[3 * t + 2]], origin, dir, -reach, reach, tHit))
                expected.emplace(t, tHit);
        }
        ASSERT_EQ(found, expected) << "segment " << q;
        hits += expected.size();
    }
    EXPECT_GT(hits, 1000u); // the segments do cross the soup, on box faces as elsewhere
    EXPECT_GT(axisAligned, 1000u);
}

namespace {

// One dilation pass over every texel (the definition in DilateAtlas.h), colour from opaque
// texels, alpha from covered ones, then the mean of the known texels for the rest.
void referenceSpread(RgbaImage& image, std::vector<std::uint8_t> known, int first, int count,
                     int passes) {
    const int w = image.width, h = image.height;
    for (int pass = 0; pass < passes; ++pass) {
        std::vector<std::uint8_t> nextKnown = known;
        RgbaImage next = image;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * w + x;
                if (known[i]) continue;
                int sum[4] = {0, 0, 0, 0}, n = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= w || ny >= h)
                            continue;
                        const std::size_t j = static_cast<std::size_t>(ny) * w + nx;
                        if (!known[j]) continue;
                        for (int c = 0; c < count; ++c)
                            sum[c] += image.pixels[j * 4 + static_cast<std::size_t>(first + c)];
                        ++n;
                    }
                if (n == 0) continue;
                for (int c = 0; c < count; ++c)
                    next.pixels[i * 4 + static_cast<std::size_t>(first + c)] =
                        static_cast<std::uint8_t>((sum[c] + n / 2) / n);
                nextKnown[i] = 1;
            }
        image = std::move(next);
        known = std::move(nextKnown);
    }
    long long sum[4] = {0, 0, 0, 0}, n = 0;
    for (std::size_t i = 0; i < known.size(); ++i) {
        if (!known[i]) continue;
        for (int c = 0; c < count; ++c)
            sum[c] += image.pixels[i * 4 + static_cast<std::size_t>(first + c)];
        ++n;
    }
    for (std::size_t i = 0; i < known.size(); ++i) {
        if (known[i]) continue;
        for (int c = 0; c < count; ++c)
            image.pixels[i * 4 + static_cast<std::size_t>(first + c)] =
                static_cast<std::uint8_t>(n > 0 ? (sum[c] + n / 2) / n : (first == 3 ? 255 : 128));
    }
}

void referenceDilate(RgbaImage& image, const std::vector<TexelState>& state, int passes) {
    std::vector<std::uint8_t> colourKnown(state.size()), alphaKnown(state.size());
    bool cutOut = false;
    for (std::size_t i = 0; i < state.size(); ++i) {
        colourKnown[i] = state[i] == TexelState::Opaque;
        alphaKnown[i] = state[i] != TexelState::Empty;
        cutOut = cutOut || state[i] == TexelState::CutOut;
    }
    referenceSpread(image, colourKnown, 0, 3, passes);
    if (cutOut)
        referenceSpread(image, alphaKnown, 3, 1, passes);
    else
        for (std::size_t i = 3; i < image.pixels.size(); i += 4)
            image.pixels[i] = 255;
}

} // namespace

TEST(AtlasKernels, DilationMatchesAPassOverEveryTexel) {
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> byte(0, 255), side(1, 40), kind(0, 99);
    int images = 0;
    for (int round = 0; round < 60; ++round) {
        const int w = round < 4 ? 1 + round % 2 : side(rng),
                  h = round < 4 ? 1 + round / 2 : side(rng);
        RgbaImage image(w, h);
        std::vector<TexelState> state(static_cast<std::size_t>(w) * h, TexelState::Empty);
        const int covered = round % 5 == 0 ? 0 : round % 5 == 1 ? 3 : 40; // percent
        for (std::size_t i = 0; i < state.size(); ++i) {
            for (int c = 0; c < 4; ++c)
                image.pixels[4 * i + static_cast<std::size_t>(c)] =
                    static_cast<std::uint8_t>(byte(rng));
            const int k = kind(rng);
            if (k < covered)
                state[i] = k % 4 == 0 && round % 2 ? TexelState::CutOut : TexelState::Opaque;
        }
        const int passes = round % 3 == 0 ? 1 : round % 3 == 1 ? 4 : 16;
        RgbaImage expected = image;
        referenceDilate(expected, state, passes);
        dilateAtlas(image, state, passes);
        ASSERT_EQ(image.pixels, expected.pixels) << w << " x " << h << ", round " << round;
        ++images;
    }
    EXPECT_EQ(images, 60);
}

TEST(AtlasKernels, BilinearSamplingWrapsAsTheModuloDoes) {
    RgbaImage image(5, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            image.set(x, y,
                      glm::u8vec4(static_cast<std::uint8_t>(40 * x + 7),
                                  static_cast<std::uint8_t>(80 * y + 3), 200, 255));
    auto reference = [&](glm::vec2 uv) {
        auto wrap = [](int i, int n) { return ((i % n) + n) % n; };
        auto texel = [&](int x, int y) {
            const glm::u8vec4 c = image.at(x, y);
            return glm::vec4(srgbByteToLinear(c.r), srgbByteToLinear(c.g), srgbByteToLinear(c.b),
                             static_cast<float>(c.a) * (1.0f / 255.0f));
        };
        const float u = uv.x - std::floor(uv.x), v = uv.y - std::floor(uv.y);
        const float x = u * 5.0f - 0.5f, y = v * 3.0f - 0.5f;
        const float fx = std::floor(x), fy = std::floor(y);
        const int x0 = wrap(static_cast<int>(fx), 5), y0 = wrap(static_cast<int>(fy), 3);
        const int x1 = wrap(x0 + 1, 5), y1 = wrap(y0 + 1, 3);
        const glm::vec4 top = glm::mix(texel(x0, y0), texel(x1, y0), x - fx);
        const glm::vec4 bottom = glm::mix(texel(x0, y1), texel(x1, y1), x - fx);
        return glm::mix(top, bottom, y - fy);
    };
    std::vector<glm::vec2> uvs = {{0.0f, 0.0f},        {1.0f, 1.0f},   {-1e-10f, -1e-10f},
                                  {0.99999994f, 0.5f}, {-3.25f, 7.9f}, {412.03f, -211.7f},
                                  {0.1f, 0.16666667f}, {0.9f, 0.999f}, {1e7f, -1e7f}};
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> any(-50.0f, 50.0f);
    for (int i = 0; i < 2000; ++i)
        uvs.emplace_back(any(rng), any(rng));
    for (const glm::vec2& uv : uvs) {
        const glm::vec4 got = sampleBilinear(image, uv), want = reference(uv);
        ASSERT_EQ(got, want) << uv.x << ", " << uv.y;
    }
}
