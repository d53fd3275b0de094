// FLIP, the perceptual difference of two LDR images shown one after the other (Andersson,
// Nilsson, Akenine-Möller, Oskarsson, Åström, Fairchild 2020, "FLIP: A Difference Evaluator for
// Alternating Images", HPG 2020; the LDR-FLIP of its section 3). Per pixel, a value in [0, 1]:
// 0 for identical images, 1 for the largest difference (e.g. pure green against pure blue).
//
// What is computed (all from the paper; constants as published):
// - Colour pipeline: sRGB -> linear RGB -> XYZ (D65) -> YCxCz (opponent space, linear in XYZ);
//   each channel filtered by its contrast sensitivity function (CSF) as a spatial filter
//   a1 sqrt(pi/b1) exp(-pi^2 x^2 / b1) + a2 sqrt(pi/b2) exp(-pi^2 x^2 / b2), x in degrees of
//   visual angle (achromatic a1 = 1, b1 = 0.0047; red-green a1 = 1, b1 = 0.0053; blue-yellow
//   a1 = 34.1, b1 = 0.04, a2 = 13.5, b2 = 0.025), normalised to unit sum, radius
//   ceil(3 sqrt(0.04 / (2 pi^2)) ppd); back to linear RGB clamped to [0, 1]; then CIELAB with the
//   Hunt adjustment (a, b scaled by 0.01 L); the HyAB distance |dL| + sqrt(da^2 + db^2) raised to
//   qc = 0.7 and redistributed to [0, 1] with pc = 0.4, pt = 0.95 against cmax, the HyAB^qc of
//   pure green and pure blue.
// - Feature pipeline: on the achromatic channel normalised to [0, 1] ((Y + 16) / 116), edges by
//   the first and points by the second derivative of a Gaussian with sigma = 0.5 w ppd, w =
//   0.082 degrees, radius ceil(3 sigma), positive and negative weights normalised to sum to 1 and
//   -1; feature difference (max(|edge_r - edge_t|, |point_r - point_t|) / sqrt 2)^qf, qf = 0.5.
// - Combination: FLIP = colour difference ^ (1 - feature difference).
// The 2D filters are sums of products of 1D filters, applied separably (the same result as
// the 2D convolution up to rounding); borders repeat the edge pixels. Arithmetic in float, as
// the reference implementation. Deterministic: rows run in parallel, the mean sums in order.
//
// Pixels per degree: the paper's default (67 ppd) is a 0.7 m wide 4K monitor seen from 0.7 m.
// `hlod bench` instead takes the viewer at the camera's centre of projection, where the image
// covers exactly the camera's field of view (flipPixelsPerDegree below): one degree at the
// image centre spans H / (2 tan(fovY / 2)) * pi / 180 pixels (640x360 at 60 degrees: 5.44).
#pragma once

#include <vector>

#include "pipeline/eval/Image.h"

namespace hlod {

// Pixels per degree at the centre of a perspective image `viewportHeight` pixels high that
// covers the vertical field of view `fovYRadians`, seen from its centre of projection.
double flipPixelsPerDegree(int viewportHeight, double fovYRadians);

struct FlipMap {
    int width = 0;
    int height = 0;
    std::vector<float> values; // row-major, top row first, each in [0, 1]
    double mean = 0.0;         // mean over all pixels
    float max = 0.0f;
};

// The per-pixel FLIP of `test` against `reference` (8-bit sRGB). Throws Error(InvalidArgument)
// when the sizes differ, an image is empty, or pixelsPerDegree is not a positive finite number.
FlipMap flipErrorMap(const RgbImage& reference, const RgbImage& test, double pixelsPerDegree);

// The mean of flipErrorMap.
double meanFlip(const RgbImage& reference, const RgbImage& test, double pixelsPerDegree);

} // namespace hlod
