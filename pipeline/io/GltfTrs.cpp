// TRS decomposition of an affine matrix without shear (see GltfTrs.h).
#include "pipeline/io/GltfTrs.h"

#include <cmath>

namespace hlod {

std::optional<Trs> decomposeTrs(const glm::dmat4& m, double tolerance) {
    if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0) return std::nullopt;
    Trs trs;
    trs.translation = glm::dvec3(m[3]);
    glm::dmat3 r(m);
    for (int c = 0; c < 3; ++c) {
        const double len = glm::length(r[c]);
        if (!std::isfinite(len) || len <= 0.0) return std::nullopt;
        trs.scale[c] = len;
        r[c] /= len;
    }
    for (int a = 0; a < 3; ++a) {
        for (int b = a + 1; b < 3; ++b) {
            if (std::abs(glm::dot(r[a], r[b])) > tolerance) return std::nullopt;
        }
    }
    if (glm::determinant(r) < 0.0) { // a mirror: fold it into the x scale
        trs.scale.x = -trs.scale.x;
        r[0] = -r[0];
    }
    // Re-orthonormalise (Gram-Schmidt) so the quaternion is exactly a rotation.
    r[0] = glm::normalize(r[0]);
    r[1] = glm::normalize(r[1] - glm::dot(r[1], r[0]) * r[0]);
    r[2] = glm::cross(r[0], r[1]);
    trs.rotation = glm::normalize(glm::quat_cast(r));
    if (trs.rotation.w < 0.0) trs.rotation = -trs.rotation; // one of the two equal quaternions
    return trs;
}

glm::dmat4 composeTrs(const Trs& trs) {
    glm::dmat4 m(glm::mat3_cast(trs.rotation));
    m[0] *= trs.scale.x;
    m[1] *= trs.scale.y;
    m[2] *= trs.scale.z;
    m[3] = glm::dvec4(trs.translation, 1.0);
    return m;
}

} // namespace hlod
