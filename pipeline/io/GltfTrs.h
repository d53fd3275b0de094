// A node transform as glTF writes it: translation, rotation (unit quaternion) and scale (glTF 2.0
// specification 3.5.3 "Transformations": a matrix must be decomposable to TRS, no shear or
// projection). The decomposition is the classic one (Shoemake & Duff, "Matrix animation and
// polar decomposition", 1992, for the affine case without shear): scale = the column lengths,
// rotation = the columns divided by them, a mirror folded into a negative x scale.
//
// Contract: decomposeTrs returns nullopt when `m` is not affine (last row not 0 0 0 1), has a
// zero or non-finite column, or has shear: some pair of normalised columns has a dot product
// above `tolerance` (default 1e-6, well below what float vertices can show). composeTrs gives
// the matrix back (exactly the original up to rounding when it had no shear).
#pragma once

#include <optional>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace hlod {

struct Trs {
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0}; // w, x, y, z; unit length
    glm::dvec3 scale{1.0};                   // x negative for a mirroring transform
};

std::optional<Trs> decomposeTrs(const glm::dmat4& m, double tolerance = 1e-6);

glm::dmat4 composeTrs(const Trs& trs);

} // namespace hlod
