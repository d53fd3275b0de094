// Quantised proxy frames, see BakeFrame.h.
#include "pipeline/proxy/BakeFrame.h"

#include <cmath>

namespace hlod {

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
    return glm::round(offset / grid) * grid;
}

} // namespace hlod
