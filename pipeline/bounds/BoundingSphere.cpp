// Welzl's minimum enclosing ball, iterative form (see BoundingSphere.h for the reference).
//
// The recursion "ball of P with the support set R on its boundary" is unrolled into four
// nested loops, one per support size (|R| = 1, 2, 3 then the sphere through four points): with
// the points in random order every loop does expected linear work, and the depth is bounded by
// four, so huge meshes cannot overflow the stack.
#include "pipeline/bounds/BoundingSphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace hlod {

namespace {

// A point is "inside" when within this fraction of the radius beyond the surface. The points
// are centred first, so the radius is the scale of every coordinate and a relative tolerance
// is meaningful.
constexpr double kInsideTol = 1e-10;

bool inside(const Sphere& s, const glm::dvec3& p) {
    const double r = s.radius * (1.0 + kInsideTol) + 1e-300;
    const glm::dvec3 d = p - s.center;
    return glm::dot(d, d) <= r * r;
}

Sphere fromTwo(const glm::dvec3& a, const glm::dvec3& b) {
    return Sphere{(a + b) * 0.5, glm::length(b - a) * 0.5};
}

// Smallest sphere with a, b, c on its boundary: the circumcircle of the triangle. Collinear
// input has no circumcircle; the sphere on the farthest pair then contains all three.
Sphere fromThree(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 u = a - c;
    const glm::dvec3 v = b - c;
    const glm::dvec3 n = glm::cross(u, v);
    const double n2 = glm::dot(n, n);
    const double scale = std::max(glm::dot(u, u), glm::dot(v, v));
    if (n2 <= 1e-24 * scale * scale) {
        Sphere best = fromTwo(a, b);
        for (const Sphere& s : {fromTwo(a, c), fromTwo(b, c)}) {
            if (s.radius > best.radius) best = s;
        }
        return best;
    }
    const glm::dvec3 offset = glm::cross(glm::dot(u, u) * v - glm::dot(v, v) * u, n) / (2.0 * n2);
    return Sphere{c + offset, glm::length(offset)};
}

// Sphere through four points. Coplanar points have no unique circumsphere; then the smallest
// sphere through three of them that contains the fourth is the answer (they are cocircular or
// one lies inside the others' circle).
Sphere fromFour(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                const glm::dvec3& d) {
    const glm::dvec3 u = b - a;
    const glm::dvec3 v = c - a;
    const glm::dvec3 w = d - a;
    const double det = glm::dot(u, glm::cross(v, w));
    const double scale = std::max({glm::length(u), glm::length(v), glm::length(w)});
    if (std::abs(det) > 1e-12 * scale * scale * scale) {
        const glm::dvec3 offset =
            (glm::dot(u, u) * glm::cross(v, w) + glm::dot(v, v) * glm::cross(w, u) +
             glm::dot(w, w) * glm::cross(u, v)) /
            (2.0 * det);
        return Sphere{a + offset, glm::length(offset)};
    }
    const std::array<glm::dvec3, 4> p{a, b, c, d};
    Sphere best{glm::dvec3(0.0), -1.0};
    for (int skip = 0; skip < 4; ++skip) {
        std::array<glm::dvec3, 3> t{};
        for (int i = 0, j = 0; i < 4; ++i) {
            if (i != skip) t[static_cast<std::size_t>(j++)] = p[static_cast<std::size_t>(i)];
        }
        const Sphere s = fromThree(t[0], t[1], t[2]);
        if (inside(s, p[static_cast<std::size_t>(skip)]) &&
            (best.radius < 0.0 || s.radius < best.radius)) {
            best = s;
        }
    }
    if (best.radius >= 0.0) return best;
    // Rounding left no triple containing the fourth point: take the largest, the final
    // containment pass of minimumBoundingSphere restores exact containment.
    best = fromThree(a, b, c);
    for (const Sphere& s : {fromThree(a, b, d), fromThree(a, c, d), fromThree(b, c, d)}) {
        if (s.radius > best.radius) best = s;
    }
    return best;
}

// Ball of pts[0..end) with q1, q2, q3 on the boundary.
Sphere ballWith3(const std::vector<glm::dvec3>& pts, std::size_t end, const glm::dvec3& q1,
                 const glm::dvec3& q2, const glm::dvec3& q3) {
    Sphere s = fromThree(q1, q2, q3);
    for (std::size_t i = 0; i < end; ++i) {
        if (!inside(s, pts[i])) s = fromFour(q1, q2, q3, pts[i]);
    }
    return s;
}

Sphere ballWith2(const std::vector<glm::dvec3>& pts, std::size_t end, const glm::dvec3& q1,
                 const glm::dvec3& q2) {
    Sphere s = fromTwo(q1, q2);
    for (std::size_t i = 0; i < end; ++i) {
        if (!inside(s, pts[i])) s = ballWith3(pts, i, q1, q2, pts[i]);
    }
    return s;
}

Sphere ballWith1(const std::vector<glm::dvec3>& pts, std::size_t end, const glm::dvec3& q) {
    Sphere s{q, 0.0};
    for (std::size_t i = 0; i < end; ++i) {
        if (!inside(s, pts[i])) s = ballWith2(pts, i, q, pts[i]);
    }
    return s;
}

// Fixed-seed Fisher-Yates (splitmix64): deterministic, and random enough for Welzl's expected
// linear running time.
void shuffle(std::vector<glm::dvec3>& pts) {
    std::uint64_t state = 0x9E3779B97F4A7C15ull;
    for (std::size_t i = pts.size(); i > 1; --i) {
        state += 0x9E3779B97F4A7C15ull;
        std::uint64_t z = state;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        std::swap(pts[i - 1], pts[static_cast<std::size_t>(z % i)]);
    }
}

} // namespace

Sphere minimumBoundingSphere(std::span<const glm::dvec3> points) {
    if (points.empty()) return Sphere{};
    glm::dvec3 lo = points[0];
    glm::dvec3 hi = points[0];
    for (const glm::dvec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::dvec3 origin = (lo + hi) * 0.5;
    std::vector<glm::dvec3> pts;
    pts.reserve(points.size());
    for (const glm::dvec3& p : points)
        pts.push_back(p - origin);
    shuffle(pts);

    Sphere s{pts[0], 0.0};
    for (std::size_t i = 1; i < pts.size(); ++i) {
        if (!inside(s, pts[i])) s = ballWith1(pts, i, pts[i]);
    }
    // Containment guarantee: grow to the farthest point (a no-op up to rounding).
    double r2 = s.radius * s.radius;
    for (const glm::dvec3& p : pts)
        r2 = std::max(r2, glm::dot(p - s.center, p - s.center));
    return Sphere{s.center + origin, std::sqrt(r2)};
}

Sphere enclosingSphere(const Sphere& a, const Sphere& b) {
    const glm::dvec3 delta = b.center - a.center;
    const double d = glm::length(delta);
    if (d + b.radius <= a.radius) return a;
    if (d + a.radius <= b.radius) return b;
    const double r = (d + a.radius + b.radius) * 0.5;
    // d > 0 here: with d == 0 one of the two tests above holds.
    return Sphere{a.center + delta * ((r - a.radius) / d), r};
}

bool sphereContains(const Sphere& outer, const Sphere& inner, double relTol, double absTol) {
    const double d = glm::length(inner.center - outer.center);
    return d + inner.radius <= outer.radius * (1.0 + relTol) + absTol;
}

} // namespace hlod
