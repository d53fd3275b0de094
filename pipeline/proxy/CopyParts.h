// Parts of one node that are rigid copies of each other (issue 26: work on identical inputs is
// done once). A node's inputs are leaves and children's proxies, each placed in the node's
// frame by a linear map and an offset (BakeFrame.h). Inputs with the same content key placed
// by rotations are the same mesh turned and moved: a decimated proxy of one of them, made in
// the part's own frame within the node's budget, placed the same way, lies within the budget
// of every copy both ways (rigid motions keep distances), so the node simplifies each such
// part once and places it as often as it occurs; the other inputs are simplified together as
// before. The whole proxy lies within the budget of the union of the inputs (the Hausdorff
// distance of two unions is at most the largest of the pairs').
//
// What it costs: copies are not welded to their neighbours nor simplified across them (a
// row of touching fence pieces keeps the seams), and a copy hidden inside another input is
// not dropped as covered. Where copies sit apart (the usual case: turned instances of a
// machine, chairs, trees) the proxy is the same size as a joint simplification, made in a
// fraction of the time.
//
// Rigid: the quantised linear map (BakeFrame.h: columns rounded to 2^-32 of their length) is a
// proper rotation to within kRigidTolerance (|L^T L - I| per entry, determinant > 0); its
// largest stretch is then below 1 + 1.5 * kRigidTolerance, so parts are simplified within the
// budget shrunk by partBudgetScale and stay within the whole budget once placed. Scaled,
// sheared and mirrored placements are simplified jointly, as before.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace hlod {

inline constexpr double kRigidTolerance = 1e-7;
// Budget factor for a part simplified in its own frame (covers the stretch of a rigid map).
inline constexpr double kPartBudgetScale = 1.0 - 1e-6;

bool isRigidPlacement(const glm::dmat3& linear);

// The inputs' indices grouped: `copies` holds every key that occurs at least twice among the
// rigidly placed inputs (each group in input order, groups in order of their first member);
// `rest` every other input, in order.
struct CopyGroups {
    std::vector<std::vector<std::size_t>> copies;
    std::vector<std::size_t> rest;
};
CopyGroups groupRigidCopies(std::span<const std::uint64_t> keys,
                            std::span<const glm::dmat3> linears);

} // namespace hlod
