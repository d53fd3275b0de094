// Fills the texels no chart covers (gutters and the space between charts) from their covered
// neighbours, so mip levels and bilinear filtering at chart borders never mix in a background
// colour. After Sander et al. 2001 and the "edge padding" every texture baker does: repeated
// one-texel dilation (each pass: an unknown texel takes the mean of its known 8-neighbours,
// read from the previous pass, so the result does not depend on scan order), then the texels
// no pass reached take the mean of all known texels.
// Colour and alpha spread separately: colour only from opaque texels (a cut-out texel's colour
// is unknown too, and gets its neighbours' so filtering at the cut-out edge has no dark
// fringe), alpha from every covered texel (cut-out texels keep alpha 0).
#pragma once

#include <cstdint>
#include <vector>

#include "pipeline/scene/RgbaImage.h"

namespace hlod {

enum class TexelState : std::uint8_t { Empty, Opaque, CutOut };

// `image` texels with state Opaque hold colour and alpha 255, CutOut alpha 0; the others are
// rewritten. `passes`: dilation passes before the global fill.
void dilateAtlas(RgbaImage& image, const std::vector<TexelState>& state, int passes = 16);

} // namespace hlod
