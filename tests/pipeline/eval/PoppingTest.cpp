// Popping at level switches (Popping.h): the HLOD's change beyond the Original's, and what
// counts as a switch.
#include <gtest/gtest.h>

#include "pipeline/core/Error.h"
#include "pipeline/eval/Flip.h"
#include "pipeline/eval/Popping.h"

using namespace hlod;

namespace {

// A 32x32 grey frame with a dark 8x8 box whose left edge is at `x` (the camera pans); the
// whole frame `offset` levels darker.
RgbImage frame(int x, int offset = 0) {
    RgbImage img(32, 32, Rgb(static_cast<std::uint8_t>(180 - offset)));
    img.fillRect(x, 12, x + 8, 20, Rgb(static_cast<std::uint8_t>(40 - offset)));
    return img;
}

} // namespace

TEST(Popping, ChangeLikeTheOriginalsIsNoPop) {
    // The HLOD frames are the Original's 4 levels darker (an error that moves with the view),
    // and the box moves the same way in both: carried forward, the previous HLOD frame becomes
    // exactly the current one.
    const RgbImage o0 = frame(4), o1 = frame(6);
    const RgbImage h0 = frame(4, 4), h1 = frame(6, 4);
    EXPECT_EQ(carriedForward(h0, o0, o1).pixels, h1.pixels);
    EXPECT_EQ(popFlip(h0, h1, o0, o1, 5.44), 0.0);
}

TEST(Popping, AStillCameraPopsByTheSwitchItself) {
    // The Original does not change; the HLOD swaps a proxy for a box one pixel wider: the pop
    // is the FLIP between the two HLOD frames.
    const RgbImage o = frame(10);
    RgbImage h1 = o;
    h1.fillRect(9, 12, 10, 20, Rgb(40));
    const double pop = popFlip(o, h1, o, o, 5.44);
    EXPECT_GT(pop, 0.0);
    EXPECT_DOUBLE_EQ(pop, meanFlip(o, h1, 5.44));
}

TEST(Popping, CarriedForwardClampsToTheByteRange) {
    RgbImage prev(1, 1, Rgb(250, 5, 100)), oPrev(1, 1, Rgb(0, 200, 100)),
        oCur(1, 1, Rgb(20, 100, 100));
    // 250 + 20 = 270 -> 255; 5 - 100 = -95 -> 0; 100 + 0 = 100.
    EXPECT_EQ(carriedForward(prev, oPrev, oCur).at(0, 0), Rgb(255, 0, 100));
    EXPECT_THROW(carriedForward(RgbImage(2, 2), RgbImage(2, 3), RgbImage(2, 2)), Error);
}

TEST(Popping, SwitchesAreRefinementsAndCoarseningsNotCulling) {
    // Forest: 0 -> {1, 2}, 1 -> {3, 4}; 5 is another root.
    const std::vector<int> parents{-1, 0, 0, 1, 1, -1};
    auto parent = [&](int u) { return parents[static_cast<std::size_t>(u)]; };
    EXPECT_FALSE(lodSwitched({1, 2}, {1, 2}, parent));    // nothing changed
    EXPECT_TRUE(lodSwitched({0}, {1, 2}, parent));        // refined
    EXPECT_TRUE(lodSwitched({2, 3, 4}, {1, 2}, parent));  // 3 and 4 coarsened to 1
    EXPECT_TRUE(lodSwitched({0}, {2, 3}, parent));        // refined two levels (1 culled)
    EXPECT_FALSE(lodSwitched({1, 2}, {1, 2, 5}, parent)); // 5 came into view
    EXPECT_FALSE(lodSwitched({1, 2, 5}, {2}, parent));    // 1 and 5 left the view
    EXPECT_FALSE(lodSwitched({}, {0}, parent));           // first frame with anything
}
