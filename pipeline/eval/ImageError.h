// Image error of a rendered frame against the reference (Original) frame of the same camera.
//
// PSNR (peak signal-to-noise ratio) over all three channels of all pixels:
//   MSE = mean over pixels and channels of (a - b)^2,  PSNR = 10 log10(255^2 / MSE) dB.
// Identical images have MSE 0 and an infinite PSNR; it is reported as kPsnrCapDb (100 dB) so
// tables and means stay finite. Differences too small to reach below the cap (one channel of
// one pixel off by one level in a 640x360 frame gives 106.5 dB) are reported as 100 dB too.
// Rule of thumb: >= 40 dB is hard to see, 30-40 dB is visible when flicking between frames.
// Differing pixels: a pixel differs when any channel differs by more than `threshold` levels
// (default 8 of 255, about 3%): small shading noise is not counted, a missing or extra part is.
#pragma once

#include <cstddef>

#include "pipeline/eval/Image.h"

namespace hlod {

inline constexpr double kPsnrCapDb = 100.0;
inline constexpr int kDiffThreshold = 8;

struct ImageError {
    double mse = 0.0;
    double psnrDb = kPsnrCapDb; // capped at kPsnrCapDb
    std::size_t diffPixels = 0; // pixels with a channel difference > threshold
    double diffShare = 0.0;     // diffPixels / all pixels, in [0, 1]
};

// Throws Error(InvalidArgument) when the sizes differ or an image is empty.
ImageError compareImages(const RgbImage& reference, const RgbImage& test,
                         int threshold = kDiffThreshold);

// 10 log10(255^2 / mse), kPsnrCapDb when mse is 0 or the value would exceed the cap.
double psnrFromMse(double mse);

} // namespace hlod
