// Quantised proxy frames, see BakeFrame.h.
#include "pipeline/proxy/BakeFrame.h"

#include <cmath>

namespace hlod {

namespace {

// Bits of a linear part's column kept below its length (BakeFrame.h).
constexpr int kLinearBits = 32;

// x rounded to `bits` significant bits (round to nearest; 0 and non-finite values as is).
// Continuous across powers of two: values just below and just above 2^k both round to 2^k.
double roundSignificant(double x, int bits) {
    if (x == 0.0 || !std::isfinite(x)) return x;
    int exponent = 0;
    const double mantissa = std::frexp(x, &exponent); // in [0.5, 1)
    return std::ldexp(std::round(std::ldexp(mantissa, bits)), exponent - bits);
}

// The grid a column of length `length` (> 0) is rounded to: 2^-32 of the length rounded to 32
// significant bits, down to a power of two.
double columnGrid(double length) {
    int exponent = 0;
    std::frexp(roundSignificant(length, kLinearBits), &exponent); // in [2^(e-1), 2^e)
    return std::ldexp(1.0, exponent - kLinearBits);
}

} // namespace

glm::dmat4 RigidFrame::matrix() const {
    glm::dmat4 m(rotation);
    m[3] = glm::dvec4(origin, 1.0);
    return m;
}

double quantizedBudget(double budget) {
    if (!(budget > 0.0) || !std::isfinite(budget)) return budget;
    int exponent = 0;
    const double mantissa = std::frexp(budget, &exponent); // in [0.5, 1)
    return std::ldexp(std::floor(std::ldexp(mantissa, 10)), exponent - 10);
}

double offsetGrid(double budget) {
    if (!(budget > 0.0) || !std::isfinite(budget)) return 0.0;
    int exponent = 0;
    std::frexp(budget / 1024.0, &exponent); // budget / 1024 in [2^(e-1), 2^e)
    return std::ldexp(1.0, exponent - 1);
}

glm::dvec3 quantizeOffset(const glm::dvec3& offset, double grid) {
    if (!(grid > 0.0)) return offset;
    // + 0.0: a negative zero (a tiny negative offset rounded) hashes like a positive one.
    return glm::round(offset / grid) * grid + 0.0;
}

glm::dmat3 frameRotation(const glm::dmat3& linear) {
    glm::dvec3 a = linear[0], b = linear[1];
    const double la = glm::length(a);
    if (!(la > 0.0) || !std::isfinite(la)) return glm::dmat3(1.0);
    a /= la;
    b -= glm::dot(a, b) * a;
    const double lb = glm::length(b);
    // A second column (nearly) along the first: no frame to take from this map.
    if (!(lb > 1e-9 * glm::length(linear[1])) || !std::isfinite(lb)) return glm::dmat3(1.0);
    b /= lb;
    // The right-handed third axis, also for a mirroring map: its own third column then points
    // along -c in the frame (the part stays mirrored, not the frame). Exactly the identity for a
    // diagonal map with a positive diagonal: a / |a| and b / |b| are unit axes.
    return glm::dmat3(a, b, glm::cross(a, b));
}

glm::dmat3 quantizeLinear(const glm::dmat3& linear) {
    glm::dmat3 out(0.0);
    for (int k = 0; k < 3; ++k) {
        const double length = glm::length(linear[k]);
        if (!(length > 0.0) || !std::isfinite(length)) {
            out[k] = linear[k];
            continue;
        }
        const double grid = columnGrid(length);
        out[k] = glm::round(linear[k] / grid) * grid + 0.0; // no negative zeros (see above)
    }
    return out;
}

PartPlacement placeInFrame(const RigidFrame& frame, const glm::dmat3& linear, const glm::dvec3& at,
                           double budget) {
    const glm::dmat3 back = glm::transpose(frame.rotation);
    return {quantizeLinear(back * linear),
            quantizeOffset(back * (at - frame.origin), offsetGrid(budget))};
}

double placementError(const PartPlacement& placement, double reach, double budget) {
    // Each column moved by at most sqrt(3)/2 of its grid, the grid at most 2^-31 of the length
    // (2^-32 of a length rounded up by at most one part in 2^32, then down to a power of two).
    double columns = 0.0;
    for (int k = 0; k < 3; ++k)
        columns += glm::length(placement.linear[k]) * std::ldexp(1.0, 1 - kLinearBits);
    return std::sqrt(3.0) * 0.5 * (columns * reach + offsetGrid(budget));
}

} // namespace hlod
