// Popping: how visible a level-of-detail switch is as it happens, the temporal half of the
// image error `hlod bench` reports beside PSNR and FLIP (issue 28).
//
// Definition. Let O(f) and H(f) be the Original's and a configuration's frames f of the same
// camera path. At a frame f >= 1 where the configuration's selection switched a level of
// detail (lodSwitched below) between f - 1 and f, its image changes by H(f) - H(f - 1), of
// which the original's own change O(f) - O(f - 1) (the camera moved, things came into view) is
// legitimate. What is left, H(f) - H(f - 1) - (O(f) - O(f - 1)), is the pop. We measure how
// visible it is with FLIP (Flip.h), the evaluator made for two images shown one after the other:
//   carried(f) = clamp(H(f - 1) + O(f) - O(f - 1), 0, 255)   per pixel and channel (8-bit sRGB)
//   pop(f)     = mean FLIP(carried(f), H(f))                   in [0, 1]
// carried(f) is the configuration's previous frame moved on by the change the original shows;
// if the configuration's image changed exactly as the original's did, H(f) = carried(f) and
// pop(f) = 0. A still camera gives carried(f) = H(f - 1): the pop is then the FLIP of the switch
// itself. Frames without a switch have no pop. The error of a configuration also drifts as the
// camera moves without any switch (a proxy's silhouette sliding against the original's), and at
// a switch frame that drift is part of the value: with the camera moving, pop is an upper
// bound of what the switch alone changed.
//
// Switch. The selection is the set of drawn units (tiles, tree nodes or DLOD levels) of a frame;
// units form a forest given by `parent`. A switch between two frames is a unit drawn in one of
// them whose ancestor is drawn in the other (a tile replaced by its children or the other way
// round, a DLOD level replaced by a coarser or finer one of the same instance). Units that only
// enter or leave the view (frustum culling) are not switches.
#pragma once

#include <functional>
#include <vector>

#include "pipeline/eval/Image.h"

namespace hlod {

// clamp(previous + originalCurrent - originalPrevious) per channel. Throws
// Error(InvalidArgument) when the sizes differ or an image is empty.
RgbImage carriedForward(const RgbImage& previous, const RgbImage& originalPrevious,
                        const RgbImage& originalCurrent);

// pop(f) of the definition above, at `pixelsPerDegree` (Flip.h).
double popFlip(const RgbImage& previous, const RgbImage& current, const RgbImage& originalPrevious,
               const RgbImage& originalCurrent, double pixelsPerDegree);

// True when a unit drawn in `previous` or `current` (each sorted ascending, no duplicates) has
// an ancestor drawn in the other. `parent(u)` is u's parent unit, negative for a root.
bool lodSwitched(const std::vector<int>& previous, const std::vector<int>& current,
                 const std::function<int(int)>& parent);

} // namespace hlod
