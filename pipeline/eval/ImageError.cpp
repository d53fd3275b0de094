#include "pipeline/eval/ImageError.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "pipeline/core/Error.h"

namespace hlod {

double psnrFromMse(double mse) {
    if (!(mse > 0.0)) return kPsnrCapDb;
    return std::min(kPsnrCapDb, 10.0 * std::log10(255.0 * 255.0 / mse));
}

ImageError compareImages(const RgbImage& reference, const RgbImage& test, int threshold) {
    if (reference.empty() || test.empty())
        throw Error(ErrorCode::InvalidArgument, "image error: empty image");
    if (reference.width != test.width || reference.height != test.height)
        throw Error(ErrorCode::InvalidArgument,
                    "image error: sizes differ (" + std::to_string(reference.width) + "x" +
                        std::to_string(reference.height) + " vs " + std::to_string(test.width) +
                        "x" + std::to_string(test.height) + ")");
    ImageError e;
    std::uint64_t sum = 0;
    const std::size_t n = reference.pixels.size();
    for (std::size_t i = 0; i < n; i += 3) {
        int worst = 0;
        for (std::size_t c = 0; c < 3; ++c) {
            const int d = std::abs(static_cast<int>(reference.pixels[i + c]) -
                                   static_cast<int>(test.pixels[i + c]));
            sum += static_cast<std::uint64_t>(d * d);
            worst = std::max(worst, d);
        }
        if (worst > threshold) ++e.diffPixels;
    }
    e.mse = static_cast<double>(sum) / static_cast<double>(n);
    e.psnrDb = psnrFromMse(e.mse);
    e.diffShare = static_cast<double>(e.diffPixels) / static_cast<double>(n / 3);
    return e;
}

} // namespace hlod
