#include "FrameMetrics.h"

#include "pipeline/eval/Flip.h"
#include "pipeline/eval/ImageError.h"
#include "pipeline/eval/Popping.h"

namespace hlod::cli {

FrameMetrics::FrameMetrics(std::size_t configs, double pixelsPerDegree)
    : ppd_(pixelsPerDegree), previous_(configs) {}

void FrameMetrics::setReference(const RgbImage& image) {
    previousReference_ = std::move(reference_);
    reference_ = image;
}

void FrameMetrics::measure(std::size_t config, const RgbImage& image, std::vector<int> units,
                           const std::function<int(int)>& parent, FrameRecord& r) {
    if (image.pixels == reference_.pixels) {
        r.psnrDb = kPsnrCapDb; // the Original itself, or a frame drawing exactly the same
        r.diffShare = 0.0;
        r.flip = 0.0;
    } else {
        const ImageError e = compareImages(reference_, image);
        r.psnrDb = e.psnrDb;
        r.diffShare = e.diffShare;
        r.flip = meanFlip(reference_, image, ppd_);
    }
    Previous& prev = previous_[config];
    r.lodSwitch = prev.valid && lodSwitched(prev.units, units, parent);
    r.pop = r.lodSwitch ? popFlip(prev.image, image, previousReference_, reference_, ppd_) : 0.0;
    prev.image = image;
    prev.units = std::move(units);
    prev.valid = true;
}

} // namespace hlod::cli
