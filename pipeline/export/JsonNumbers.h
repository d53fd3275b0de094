// Short JSON numbers for the package's tileset.json and hlod.json: 7 significant decimal digits
// (float precision, which is what runtimes keep), so a number prints as "1503.86" and not as
// "1503.8599853515625". Bounds are rounded outward (a rounded box still holds what the exact
// one held) and errors upward (so a parent's error stays >= its children's: the rounding is
// monotone). Transforms are never rounded (they place content; they keep full precision).
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace hlod {

// The decimal with 7 significant digits nearest to x (non-finite and 0 returned as is).
inline double shortNumber(double x) {
    if (!std::isfinite(x) || x == 0.0) return x;
    char text[32];
    std::snprintf(text, sizeof(text), "%.6e", x);
    return std::strtod(text, nullptr);
}

// A 7-digit decimal >= x, for x >= 0 (at most 1.5e-6 relative above it).
inline double shortNumberUp(double x) {
    if (!std::isfinite(x) || x <= 0.0) return x;
    return shortNumber(x * (1.0 + 1e-6));
}

} // namespace hlod
