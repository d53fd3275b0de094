// Which inputs of a node count as rigid copies of each other (CopyParts.h): the same key placed
// by a proper rotation; scaled, sheared and mirrored placements stay with the joint inputs.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/proxy/BakeFrame.h"
#include "pipeline/proxy/CopyParts.h"

using namespace hlod;

namespace {

glm::dmat3 turn(double radians, const glm::dvec3& axis) {
    return glm::dmat3(glm::rotate(glm::dmat4(1.0), radians, glm::normalize(axis)));
}

} // namespace

TEST(CopyParts, QuantisedRotationsAreRigidScalesMirrorsAndShearsAreNot) {
    EXPECT_TRUE(isRigidPlacement(glm::dmat3(1.0)));
    // Turns as the baker stores them (BakeFrame.h: columns rounded to 2^-32 of their length).
    for (double a : {0.3, 1.9, -2.4, 4.0})
        EXPECT_TRUE(isRigidPlacement(quantizeLinear(turn(a, {0.2, 1.0, -0.4})))) << a;
    EXPECT_FALSE(isRigidPlacement(glm::dmat3(2.0)));        // scaled
    EXPECT_FALSE(isRigidPlacement(glm::dmat3(1.0 + 1e-6))); // scaled a little
    EXPECT_FALSE(isRigidPlacement(glm::dmat3(glm::dvec3(-1, 0, 0), {0, 1, 0}, {0, 0, 1})));
    glm::dmat3 shear(1.0);
    shear[1][0] = 0.01;
    EXPECT_FALSE(isRigidPlacement(shear));
    EXPECT_FALSE(isRigidPlacement(glm::dmat3(0.0))); // degenerate (an unset placement)
}

TEST(CopyParts, GroupsKeysPlacedRigidlyAtLeastTwiceAndKeepsTheRestInOrder) {
    const glm::dmat3 r = quantizeLinear(turn(0.7, {0, 1, 0}));
    const glm::dmat3 mirror(glm::dvec3(-1, 0, 0), {0, 1, 0}, {0, 0, 1});
    //                              0  1  2  3  4  5  6
    const std::uint64_t keys[] = {7, 9, 7, 7, 9, 5, 7};
    const glm::dmat3 linears[] = {r, r, glm::dmat3(1.0), glm::dmat3(2.0), mirror, r, r};
    const CopyGroups g = groupRigidCopies(keys, linears);
    ASSERT_EQ(g.copies.size(), 1u); // key 7 at 0, 2, 6 (3 is scaled); key 9 once rigidly
    EXPECT_EQ(g.copies[0], (std::vector<std::size_t>{0, 2, 6}));
    EXPECT_EQ(g.rest, (std::vector<std::size_t>{1, 3, 4, 5}));

    const std::uint64_t unique[] = {1, 2, 3};
    const glm::dmat3 same[] = {r, r, r};
    const CopyGroups none = groupRigidCopies(unique, same);
    EXPECT_TRUE(none.copies.empty());
    EXPECT_EQ(none.rest, (std::vector<std::size_t>{0, 1, 2}));
}
