// The image metrics `hlod bench` records per frame and configuration against the Original
// frame of the same camera: PSNR and differing pixels (ImageError.h), mean FLIP (Flip.h), and
// popping at level-of-detail switches (Popping.h), which needs each configuration's previous
// frame and selection. Frames must come in path order, the Original's first in each frame.
#pragma once

#include <functional>
#include <vector>

#include "pipeline/eval/BenchReport.h"
#include "pipeline/eval/Image.h"

namespace hlod::cli {

class FrameMetrics {
public:
    // `configs` configurations (index 0 may be the Original itself), FLIP at `pixelsPerDegree`.
    FrameMetrics(std::size_t configs, double pixelsPerDegree);

    // The Original's frame, the reference of every configuration's frame until the next call.
    void setReference(const RgbImage& image);

    // Fills r.psnrDb, r.diffShare, r.flip, r.lodSwitch and r.pop for configuration `config`'s
    // frame `image`, whose drawn units are `units` (sorted ascending; `parent` gives a unit's
    // parent unit, negative at a root; Popping.h). The Original passes its own frame: 0 error.
    void measure(std::size_t config, const RgbImage& image, std::vector<int> units,
                 const std::function<int(int)>& parent, FrameRecord& r);

    double pixelsPerDegree() const { return ppd_; }

private:
    struct Previous {
        RgbImage image;
        std::vector<int> units;
        bool valid = false;
    };
    double ppd_;
    RgbImage reference_, previousReference_;
    std::vector<Previous> previous_;
};

} // namespace hlod::cli
