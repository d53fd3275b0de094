// LDR-FLIP after Andersson et al. 2020 (Flip.h says what and why).
#include "pipeline/eval/Flip.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "pipeline/core/Error.h"

namespace hlod {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The paper's constants (section 3).
constexpr float kQc = 0.7f;  // colour difference exponent
constexpr float kPc = 0.4f;  // share of cmax mapped to [0, pt]
constexpr float kPt = 0.95f; // FLIP value at pc * cmax
constexpr float kQf = 0.5f;  // feature difference exponent
constexpr double kW = 0.082; // peak-to-trough of the edge detector, degrees

struct Csf {
    double a1, b1, a2, b2;
};
constexpr Csf kCsfAchromatic{1.0, 0.0047, 0.0, 0.0};
constexpr Csf kCsfRedGreen{1.0, 0.0053, 0.0, 0.0};
constexpr Csf kCsfBlueYellow{34.1, 0.04, 13.5, 0.025};
constexpr double kCsfLargestB = 0.04;

struct V3 {
    float x, y, z;
};

// Linear sRGB primaries, D65 (the matrices of the reference implementation).
V3 linearRgbToXyz(V3 c) {
    return {(10135552.0f / 24577794.0f) * c.x + (8788810.0f / 24577794.0f) * c.y +
                (4435075.0f / 24577794.0f) * c.z,
            (2613072.0f / 12288897.0f) * c.x + (8788810.0f / 12288897.0f) * c.y +
                (887015.0f / 12288897.0f) * c.z,
            (1425312.0f / 73733382.0f) * c.x + (8788810.0f / 73733382.0f) * c.y +
                (70074185.0f / 73733382.0f) * c.z};
}

V3 xyzToLinearRgb(V3 c) {
    return {3.241003275f * c.x - 1.537398934f * c.y - 0.498615861f * c.z,
            -0.969224334f * c.x + 1.875930071f * c.y + 0.041554224f * c.z,
            0.055639423f * c.x - 0.204011202f * c.y + 1.057148933f * c.z};
}

const V3 kWhite = linearRgbToXyz({1.0f, 1.0f, 1.0f});

V3 xyzToYcxcz(V3 c) {
    const float x = c.x / kWhite.x, y = c.y / kWhite.y, z = c.z / kWhite.z;
    return {116.0f * y - 16.0f, 500.0f * (x - y), 200.0f * (y - z)};
}

V3 ycxczToXyz(V3 c) {
    const float y = (c.x + 16.0f) / 116.0f;
    return {(y + c.y / 500.0f) * kWhite.x, y * kWhite.y, (y - c.z / 200.0f) * kWhite.z};
}

float labF(float t) {
    constexpr float delta = 6.0f / 29.0f;
    constexpr float deltaCube = delta * delta * delta;
    return t > deltaCube ? std::cbrt(t) : t / (3.0f * delta * delta) + 4.0f / 29.0f;
}

// CIELAB with the Hunt adjustment: a and b scaled by 0.01 L (colours look less colourful dark).
V3 xyzToHuntLab(V3 c) {
    const float fx = labF(c.x / kWhite.x), fy = labF(c.y / kWhite.y), fz = labF(c.z / kWhite.z);
    const float l = 116.0f * fy - 16.0f;
    return {l, 0.01f * l * 500.0f * (fx - fy), 0.01f * l * 200.0f * (fy - fz)};
}

float hyab(V3 a, V3 b) {
    const float da = a.y - b.y, db = a.z - b.z;
    return std::abs(a.x - b.x) + std::sqrt(da * da + db * db);
}

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

using Plane = std::vector<float>;

struct Ycxcz {
    Plane y, cx, cz;
};

Ycxcz toYcxcz(const RgbImage& image) {
    std::array<float, 256> lut{};
    for (int i = 0; i < 256; ++i)
        lut[static_cast<std::size_t>(i)] = srgbToLinear(static_cast<float>(i) / 255.0f);
    const std::size_t n = static_cast<std::size_t>(image.width) * image.height;
    Ycxcz out{Plane(n), Plane(n), Plane(n)};
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t* p = &image.pixels[3 * i];
        const V3 c = xyzToYcxcz(linearRgbToXyz({lut[p[0]], lut[p[1]], lut[p[2]]}));
        out.y[i] = c.x;
        out.cx[i] = c.y;
        out.cz[i] = c.z;
    }
    return out;
}

// Correlates every row (`alongX`) or column with `kernel` (odd length, centred), repeating the
// border pixels.
Plane filter1d(const Plane& in, int w, int h, const std::vector<float>& kernel, bool alongX) {
    Plane out(in.size());
    const int r = static_cast<int>(kernel.size() / 2);
    tbb::parallel_for(tbb::blocked_range<int>(0, h, 16), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y) {
            for (int x = 0; x < w; ++x) {
                float sum = 0.0f;
                for (int k = -r; k <= r; ++k) {
                    const int xx = alongX ? std::clamp(x + k, 0, w - 1) : x;
                    const int yy = alongX ? y : std::clamp(y + k, 0, h - 1);
                    sum += kernel[static_cast<std::size_t>(k + r)] *
                           in[static_cast<std::size_t>(yy) * w + xx];
                }
                out[static_cast<std::size_t>(y) * w + x] = sum;
            }
        }
    });
    return out;
}

Plane separable(const Plane& in, int w, int h, const std::vector<float>& kx,
                const std::vector<float>& ky) {
    return filter1d(filter1d(in, w, h, kx, true), w, h, ky, false);
}

// One CSF term as a 1D factor: sqrt(a sqrt(pi / b)) exp(-pi^2 x^2 / b), so that the product of
// the x and y factors is the paper's 2D term a sqrt(pi / b) exp(-pi^2 (x^2 + y^2) / b).
std::vector<double> csfTerm(double a, double b, int radius, double ppd) {
    std::vector<double> k(static_cast<std::size_t>(2 * radius + 1), 0.0);
    if (a == 0.0) return k;
    for (int i = -radius; i <= radius; ++i) {
        const double x = i / ppd; // degrees
        k[static_cast<std::size_t>(i + radius)] =
            std::sqrt(a * std::sqrt(kPi / b)) * std::exp(-kPi * kPi * x * x / b);
    }
    return k;
}

// The 1D factors of a CSF's two terms, scaled so that the 2D filter (sum of the two outer
// products) sums to 1: each divided by sqrt(S1^2 + S2^2), S the factors' sums.
std::pair<std::vector<float>, std::vector<float>> csfFilters(const Csf& csf, int radius,
                                                             double ppd) {
    const std::vector<double> t1 = csfTerm(csf.a1, csf.b1, radius, ppd);
    const std::vector<double> t2 = csfTerm(csf.a2, csf.b2, radius, ppd);
    double s1 = 0.0, s2 = 0.0;
    for (std::size_t i = 0; i < t1.size(); ++i) {
        s1 += t1[i];
        s2 += t2[i];
    }
    const double norm = 1.0 / std::sqrt(s1 * s1 + s2 * s2);
    std::vector<float> f1(t1.size()), f2(t2.size());
    for (std::size_t i = 0; i < t1.size(); ++i) {
        f1[i] = static_cast<float>(t1[i] * norm);
        f2[i] = static_cast<float>(t2[i] * norm);
    }
    return {f1, f2};
}

Plane csfFiltered(const Plane& channel, int w, int h, const Csf& csf, int radius, double ppd) {
    const auto [f1, f2] = csfFilters(csf, radius, ppd);
    Plane out = separable(channel, w, h, f1, f1);
    if (csf.a2 != 0.0) {
        const Plane second = separable(channel, w, h, f2, f2);
        for (std::size_t i = 0; i < out.size(); ++i)
            out[i] += second[i];
    }
    return out;
}

// Gaussian (sum 1), its first and second derivative (positive weights sum to 1, negative to
// -1), sigma = 0.5 w ppd. In double so narrow kernels do not underflow before normalising.
struct FeatureKernels {
    std::vector<float> g, dg, ddg;
};

FeatureKernels featureKernels(double ppd) {
    const double sigma = 0.5 * kW * ppd;
    const int radius = static_cast<int>(std::ceil(3.0 * sigma));
    const std::size_t n = static_cast<std::size_t>(2 * radius + 1);
    std::vector<double> g(n), dg(n), ddg(n);
    double gSum = 0.0, dPos = 0.0, dNeg = 0.0, ddPos = 0.0, ddNeg = 0.0;
    for (int i = -radius; i <= radius; ++i) {
        const std::size_t k = static_cast<std::size_t>(i + radius);
        const double x = i;
        g[k] = std::exp(-x * x / (2.0 * sigma * sigma));
        dg[k] = -x * g[k];
        ddg[k] = (x * x / (sigma * sigma) - 1.0) * g[k];
        gSum += g[k];
        (dg[k] > 0.0 ? dPos : dNeg) += std::abs(dg[k]);
        (ddg[k] > 0.0 ? ddPos : ddNeg) += std::abs(ddg[k]);
    }
    FeatureKernels out{std::vector<float>(n), std::vector<float>(n), std::vector<float>(n)};
    auto scaled = [](double v, double pos, double neg) {
        const double s = v > 0.0 ? pos : neg;
        return s > 0.0 ? static_cast<float>(v / s) : 0.0f;
    };
    for (std::size_t k = 0; k < n; ++k) {
        out.g[k] = static_cast<float>(g[k] / gSum);
        out.dg[k] = scaled(dg[k], dPos, dNeg);
        out.ddg[k] = scaled(ddg[k], ddPos, ddNeg);
    }
    return out;
}

struct Features {
    Plane edge, point; // gradient magnitudes of the first and second derivative filters
};

Features features(const Plane& y, int w, int h, const FeatureKernels& k) {
    Plane gray(y.size());
    for (std::size_t i = 0; i < y.size(); ++i)
        gray[i] = (y[i] + 16.0f) / 116.0f; // achromatic channel in [0, 1]
    const Plane gx = filter1d(gray, w, h, k.g, true);
    const Plane ex = filter1d(filter1d(gray, w, h, k.dg, true), w, h, k.g, false);
    const Plane ey = filter1d(gx, w, h, k.dg, false);
    const Plane px = filter1d(filter1d(gray, w, h, k.ddg, true), w, h, k.g, false);
    const Plane py = filter1d(gx, w, h, k.ddg, false);
    Features f{Plane(y.size()), Plane(y.size())};
    for (std::size_t i = 0; i < y.size(); ++i) {
        f.edge[i] = std::sqrt(ex[i] * ex[i] + ey[i] * ey[i]);
        f.point[i] = std::sqrt(px[i] * px[i] + py[i] * py[i]);
    }
    return f;
}

// The CSF-filtered image as Hunt-adjusted CIELAB, clamped to the RGB cube on the way.
std::vector<V3> perceived(const Ycxcz& c, int w, int h, double ppd) {
    const int radius =
        static_cast<int>(std::ceil(3.0 * std::sqrt(kCsfLargestB / (2.0 * kPi * kPi)) * ppd));
    const Plane y = csfFiltered(c.y, w, h, kCsfAchromatic, radius, ppd);
    const Plane cx = csfFiltered(c.cx, w, h, kCsfRedGreen, radius, ppd);
    const Plane cz = csfFiltered(c.cz, w, h, kCsfBlueYellow, radius, ppd);
    std::vector<V3> out(y.size());
    for (std::size_t i = 0; i < y.size(); ++i) {
        V3 rgb = xyzToLinearRgb(ycxczToXyz({y[i], cx[i], cz[i]}));
        rgb = {std::clamp(rgb.x, 0.0f, 1.0f), std::clamp(rgb.y, 0.0f, 1.0f),
               std::clamp(rgb.z, 0.0f, 1.0f)};
        out[i] = xyzToHuntLab(linearRgbToXyz(rgb));
    }
    return out;
}

// HyAB^qc between the Hunt-adjusted pure green and pure blue: the largest colour difference.
float maxColourDifference() {
    const V3 green = xyzToHuntLab(linearRgbToXyz({0.0f, 1.0f, 0.0f}));
    const V3 blue = xyzToHuntLab(linearRgbToXyz({0.0f, 0.0f, 1.0f}));
    return std::pow(hyab(green, blue), kQc);
}

} // namespace

double flipPixelsPerDegree(int viewportHeight, double fovYRadians) {
    return 0.5 * viewportHeight / std::tan(0.5 * fovYRadians) * kPi / 180.0;
}

FlipMap flipErrorMap(const RgbImage& reference, const RgbImage& test, double pixelsPerDegree) {
    if (reference.empty() || test.empty())
        throw Error(ErrorCode::InvalidArgument, "FLIP: empty image");
    if (reference.width != test.width || reference.height != test.height)
        throw Error(ErrorCode::InvalidArgument,
                    "FLIP: sizes differ (" + std::to_string(reference.width) + "x" +
                        std::to_string(reference.height) + " vs " + std::to_string(test.width) +
                        "x" + std::to_string(test.height) + ")");
    if (!(pixelsPerDegree > 0.0) || !std::isfinite(pixelsPerDegree))
        throw Error(ErrorCode::InvalidArgument, "FLIP: pixels per degree must be positive");
    const int w = reference.width, h = reference.height;
    const Ycxcz ref = toYcxcz(reference), tst = toYcxcz(test);
    const std::vector<V3> labRef = perceived(ref, w, h, pixelsPerDegree);
    const std::vector<V3> labTest = perceived(tst, w, h, pixelsPerDegree);
    const FeatureKernels kernels = featureKernels(pixelsPerDegree);
    const Features fRef = features(ref.y, w, h, kernels);
    const Features fTest = features(tst.y, w, h, kernels);

    const float cmax = maxColourDifference();
    const float pccmax = kPc * cmax;
    const float invSqrt2 = 1.0f / std::sqrt(2.0f);
    FlipMap map;
    map.width = w;
    map.height = h;
    map.values.resize(labRef.size());
    double sum = 0.0;
    for (std::size_t i = 0; i < labRef.size(); ++i) {
        float colour = std::pow(hyab(labRef[i], labTest[i]), kQc);
        colour = colour < pccmax ? colour * kPt / pccmax
                                 : kPt + (colour - pccmax) / (cmax - pccmax) * (1.0f - kPt);
        const float edge = std::abs(fRef.edge[i] - fTest.edge[i]);
        const float point = std::abs(fRef.point[i] - fTest.point[i]);
        const float feature = std::pow(invSqrt2 * std::max(edge, point), kQf);
        const float v = std::pow(colour, 1.0f - feature);
        map.values[i] = v;
        map.max = std::max(map.max, v);
        sum += v;
    }
    map.mean = sum / static_cast<double>(map.values.size());
    return map;
}

double meanFlip(const RgbImage& reference, const RgbImage& test, double pixelsPerDegree) {
    return flipErrorMap(reference, test, pixelsPerDegree).mean;
}

} // namespace hlod
