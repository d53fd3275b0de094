// The cost bounds of CostBounds.h for four regions at once: one query region (an item of a
// clustering level, packed) against the four slots of a wide BVH node (MergeBvh.h), in double
// precision over GCC/Clang vector types, W lanes at a time: W = 2 is one SSE2 (or NEON)
// register, the baseline; W = 4 is one AVX register, for code compiled for AVX2 (MergeBvh.h
// picks it at run time when the processor has it; in a function compiled for the baseline a
// four-double vector would be split into scalar code).
//
// The arithmetic is that of the scalar pair test the tests keep (PackedPairTest in
// tests/pipeline/cluster/ScalarBounds.h), term for term and in the same order, lane by lane: a
// lane exceeds exactly when the scalar test would, and a lane's bound is the scalar
// pairLowerBound up to the rounding of one multiplication (both carry the 1 - 1e-9 safety
// factor, far above it). What differs is only that there is no early exit: every term is
// computed for the four lanes and the verdicts are or-ed, which is the same verdict (the scalar
// test returns true at the first term that exceeds, false when none does). So every argument
// of CostBounds.h carries over: a lane that exceeds holds no pair within the threshold. The
// tests check the lanes against the scalar test (MergeBvhTest).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "pipeline/cluster/CostBounds.h"

namespace hlod {

// Four slots of a wide node, structure of arrays (lane l = slot l). An unused lane holds zeros.
struct WideRegions {
    float lo[3][4];
    float hi[3][4];
    float maxFv[4];
    float minSize[4]; // radius (sphere model) or volume (box model)
    float minExtent[3][4];
    float minArea[3][4];
};

// Writes `r` (packed: PackedRegion, and PackedExtra for the box model) into lane `lane`.
inline void setLane(WideRegions& w, int lane, const PackedRegion& r, const PackedExtra& e) {
    for (int i = 0; i < 3; ++i) {
        w.lo[i][lane] = r.lo[i];
        w.hi[i][lane] = r.hi[i];
        w.minExtent[i][lane] = e.minExtent[i];
        w.minArea[i][lane] = e.minArea[i];
    }
    w.maxFv[lane] = r.maxFv;
    w.minSize[lane] = r.minSize;
}

// Reads lane `lane` back (exact: the lanes hold the packed floats).
inline void getLane(const WideRegions& w, int lane, PackedRegion& r, PackedExtra& e) {
    for (int i = 0; i < 3; ++i) {
        r.lo[i] = w.lo[i][lane];
        r.hi[i] = w.hi[i][lane];
        e.minExtent[i] = w.minExtent[i][lane];
        e.minArea[i] = w.minArea[i][lane];
    }
    r.maxFv = w.maxFv[lane];
    r.minSize = w.minSize[lane];
}

namespace wide {

template <int W> struct Lanes;
template <> struct Lanes<2> {
    using Vd = double __attribute__((vector_size(16)));
    using Vm = long long __attribute__((vector_size(16))); // a comparison's lanes: all ones or 0
    [[gnu::always_inline]] static Vd load(const float* p) {
#if defined(__SSE2__)
        // One 8-byte load and one cvtps2pd (the generic form compiles to two scalar loads and
        // conversions).
        return reinterpret_cast<Vd>(
            _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p)))));
#else
        using Vf = float __attribute__((vector_size(8)));
        Vf f;
        std::memcpy(&f, p, sizeof f);
        return __builtin_convertvector(f, Vd);
#endif
    }
    [[gnu::always_inline]] static Vd splat(double x) { return Vd{x, x}; }
    // Bit l set when lane l of a comparison is true.
    [[gnu::always_inline]] static unsigned bits(Vm m) {
#if defined(__SSE2__)
        return static_cast<unsigned>(_mm_movemask_pd(reinterpret_cast<__m128d>(m)));
#else
        return static_cast<unsigned>((m[0] & 1) | (m[1] & 2));
#endif
    }
};
template <> struct Lanes<4> {
    using Vd = double __attribute__((vector_size(32)));
    using Vm = long long __attribute__((vector_size(32)));
    // Element by element: inlined into AVX2 code this becomes one vcvtps2pd from memory
    // (__builtin_convertvector there converts two halves through the stack).
    [[gnu::always_inline]] static Vd load(const float* p) { return Vd{p[0], p[1], p[2], p[3]}; }
    [[gnu::always_inline]] static Vd splat(double x) { return Vd{x, x, x, x}; }
    // Two SSE2 sign-mask moves (AVX's own is not callable from this generic code; inlined
    // into AVX2 code these are two vmovmskpd). Lane by lane the compiler stored the vector
    // and branched on each lane.
    [[gnu::always_inline]] static unsigned bits(Vm m) {
#if defined(__SSE2__)
        using V2 = long long __attribute__((vector_size(16)));
        const V2 lo = __builtin_shufflevector(m, m, 0, 1);
        const V2 hi = __builtin_shufflevector(m, m, 2, 3);
        return static_cast<unsigned>(_mm_movemask_pd(reinterpret_cast<__m128d>(lo)) |
                                     _mm_movemask_pd(reinterpret_cast<__m128d>(hi)) << 2);
#else
        return static_cast<unsigned>((m[0] & 1) | (m[1] & 2) | (m[2] & 4) | (m[3] & 8));
#endif
    }
};

template <class V> [[gnu::always_inline]] inline V vmax(V a, V b) { return a > b ? a : b; }
template <class V> [[gnu::always_inline]] inline V vmin(V a, V b) { return a < b ? a : b; }

} // namespace wide

// Bit l set when the box of lane l has a squared diagonal above `size2`, in single precision
// (one 128-bit vector): it only decides which nodes a join group opens itself, never which
// pairs the join reports.
[[gnu::always_inline]] inline unsigned diagonalAbove(const WideRegions& w, float size2) {
    using F4 = float __attribute__((vector_size(16)));
    const auto load = [](const float* p) __attribute__((always_inline)) {
        F4 x;
        std::memcpy(&x, p, sizeof x);
        return x;
    };
    F4 d2{};
#pragma GCC unroll 3
    for (int i = 0; i < 3; ++i) {
        const F4 x = load(w.hi[i]) - load(w.lo[i]);
        d2 += x * x;
    }
    const auto above = d2 > F4{size2, size2, size2, size2};
#if defined(__SSE2__)
    return static_cast<unsigned>(_mm_movemask_ps(reinterpret_cast<__m128>(above)));
#else
    return static_cast<unsigned>((above[0] & 1) | (above[1] & 2) | (above[2] & 4) | (above[3] & 8));
#endif
}

// Which bound a query evaluates: known at compile time (one of the fixed kinds, so the
// branches on the model fold away and only that bound's arithmetic is emitted), or Any: read
// from the model at run time (any k; the tests use it).
// BoxK0Single: the box bound for k = 0 evaluated in single precision (WideQueryT::exceeds;
// the self-join uses it where singleUsable(threshold)).
enum class BoundKind { Any, Sphere, BoxK0, BoxK1, BoxK2, BoxK0Single };

// The kind for `model`: Sphere, BoxK0/1/2 for k = 0, 1, 2, else Any.
inline BoundKind boundKindOf(const CostModel& model) {
    if (model.volume() == VolumeType::Sphere) return BoundKind::Sphere;
    if (model.k() == 0.0) return BoundKind::BoxK0;
    if (model.k() == 1.0) return BoundKind::BoxK1;
    if (model.k() == 2.0) return BoundKind::BoxK2;
    return BoundKind::Any;
}

// Calls f(std::integral_constant<BoundKind, kind>{}), so that f can instantiate code for the
// kind known at run time (one instantiation per kind).
template <class F> void withKind(BoundKind kind, F&& f) {
    using enum BoundKind;
    const auto tryKinds = [&]<BoundKind... Ks>() {
        ((kind == Ks ? (f(std::integral_constant<BoundKind, Ks>{}), true) : false) || ...);
    };
    tryKinds.template operator()<Any, Sphere, BoxK0, BoxK1, BoxK2, BoxK0Single>();
}

// Whether the single-precision k = 0 test (BoundKind::BoxK0Single) runs at `threshold`: the
// threshold and what it is compared with stay in single precision's normal range.
// (Beyond 1e-15..1e15 squared volumes near the threshold would leave single precision's range
// and the test would prune little.)
inline bool singleUsable(double threshold) { return threshold >= 1e-15 && threshold <= 1e15; }

namespace wide {

// The box bound for k = 0 in single precision (four lanes of one node per 128-bit vector, or
// two nodes' lanes per 256-bit vector, SingleBoxK0 below): no conversions to double and half
// the operations per node, for the self-join's node tests. It is slightly weaker than the
// double test, never stronger. It tests
// v * max(fvSum, v) > (threshold / kSafety) * fvSum, as the double test does (CostBounds.h):
// - Every operation on floats is correctly rounded: its result is within a relative 2^-24 of
//   the exact result of the same operation on the same (float) inputs, a subtraction of two
//   floats too, however close they are. The packed regions are the inputs (already rounded
//   outward, CostBounds.h), so no error comes before the first operation.
// - Only e_i = max(m, gap + s) (m = max(wa, wb), s = wa + wb, so m <= s <= 2m) can cancel:
//   gap < 0 with gap + s > m means |gap| < s - m <= s / 2 <= m < gap + s, so the absolute
//   error (the two roundings of gap and s, and the sum's own) stays under 7 * 2^-24 of the
//   result; where gap + s <= m the computed e_i exceeds m, the exact e_i, by at most that.
// - The rest (sums of positives, products, maxima) adds at most 2^-24 per operation: the
//   left side is within 60 * 2^-24 < 4e-6 of its exact value, the right side within 4 * 2^-24
//   (the threshold's division and rounding, the sum, the product). The margin kSafety
//   (SingleThreshold, 1 - 2^-12) covers both sixty times over, so a lane is rejected only
//   when the exact bound of CostBounds.h exceeds the threshold.
// - Range (the caller runs it only where singleUsable(threshold), so the threshold is a
//   normal float): fvSum is raised to at least 1e-36 / threshold (SingleThreshold), so the
//   right side stays a normal float (no underflow), and raising fvSum only lowers the bound
//   (cost >= v * max(1, v / fvSum) falls as fvSum grows). A right side at or above 1e37 never
//   rejects (its rounding near the top of the range is not covered). Below that, a left side
//   that overflows to infinity has an exact value above 3.4e38, so rejecting is right; an
//   underflow only lowers the left side; a NaN compares false (kept).
// A query region's values, each broadcast to every lane of a vector V (`splat`: a float to a
// V), so that a node test reads them as vector operands instead of broadcasting each again.
template <class V> struct QueryLanes {
    template <class Splat>
    QueryLanes(const PackedRegion& r, const PackedExtra& e, Splat splat)
        : maxFv(splat(r.maxFv)), minSize(splat(r.minSize)) {
        for (int i = 0; i < 3; ++i) {
            lo[i] = splat(r.lo[i]);
            hi[i] = splat(r.hi[i]);
            minExtent[i] = splat(e.minExtent[i]);
            minArea[i] = splat(e.minArea[i]);
        }
    }
    V lo[3], hi[3], minExtent[3], minArea[3];
    V maxFv, minSize;
};

// Stands in for a member a query kind does not use.
struct Nothing {
    template <class... Args> explicit Nothing(const Args&...) {}
};

struct SingleThreshold {
    explicit SingleThreshold(double threshold)
        : value(static_cast<float>(threshold / kSafety)),
          minFvSum(static_cast<float>(1e-36 / threshold)) {}
    // The margin of the test below: 1 - 2^-12.
    static constexpr double kSafety = 1.0 - 1.0 / 4096.0;
    float value;    // the threshold over kSafety, rounded to nearest
    float minFvSum; // F*V sums are raised to this, so that value * fvSum stays a normal float
};

// N = 4: one node's four lanes in a 128-bit vector; N = 8: two nodes' lanes in a 256-bit
// vector (inlined into AVX2 code one instruction per operation; elsewhere two), which halves
// the work per node where the processor has AVX2.
using F4 = float __attribute__((vector_size(16)));
using F8 = float __attribute__((vector_size(32)));
using I4 = int __attribute__((vector_size(16)));
using I8 = int __attribute__((vector_size(32)));

template <int N> class SingleBoxK0 {
    using Vf = std::conditional_t<N == 4, F4, F8>;
    using Vi = std::conditional_t<N == 4, I4, I8>;

public:
    SingleBoxK0(const PackedRegion& r, const PackedExtra& e)
        : q_(r, e, [](float x) { return splat(x); }) {}

    // Bit l set when lane l's pair bound certainly exceeds `t` (the threshold, singleUsable):
    // lanes 0-3 of node a, for N = 8 lanes 4-7 those of node b (N = 4 ignores b).
    [[gnu::always_inline]] unsigned exceeds(const WideRegions& a, const WideRegions& b,
                                            const SingleThreshold& t) const {
        const Vf fvSum = vmax(q_.maxFv + loadLanes(a.maxFv, b.maxFv), splat(t.minFvSum));
        Vf e[3];
        Vf area[3];
#pragma GCC unroll 3
        for (int i = 0; i < 3; ++i) {
            const Vf gap = vmax(loadLanes(a.lo[i], b.lo[i]) - q_.hi[i],
                                q_.lo[i] - loadLanes(a.hi[i], b.hi[i]));
            const Vf wb = loadLanes(a.minExtent[i], b.minExtent[i]);
            e[i] = vmax(vmax(q_.minExtent[i], wb), gap + (q_.minExtent[i] + wb));
            area[i] = vmax(q_.minArea[i], loadLanes(a.minArea[i], b.minArea[i]));
        }
        const Vf vx = e[0] * vmax(area[0], e[1] * e[2]);
        const Vf vy = e[1] * vmax(area[1], e[0] * e[2]);
        const Vf vz = e[2] * vmax(area[2], e[0] * e[1]);
        // (The maxima paired so that the chain from the loads to the verdict stays short: the
        // processor overlaps the tests of a wave as far as their latency allows.)
        const Vf v =
            vmax(vmax(vx, vy), vmax(vz, vmax(q_.minSize, loadLanes(a.minSize, b.minSize))));
        const Vf rhs = splat(t.value) * fvSum;
        return bits((v * vmax(fvSum, v) > rhs) & (rhs < splat(1e37f)));
    }

private:
    [[gnu::always_inline]] static F4 load4(const float* p) {
        F4 x;
        std::memcpy(&x, p, sizeof x);
        return x;
    }
    [[gnu::always_inline]] static Vf loadLanes(const float (&x)[4], const float (&y)[4]) {
        if constexpr (N == 4) {
            (void)y;
            return load4(x);
        } else {
            return __builtin_shufflevector(load4(x), load4(y), 0, 1, 2, 3, 4, 5, 6, 7);
        }
    }
    [[gnu::always_inline]] static Vf splat(float x) {
        Vf v{};
        for (int l = 0; l < N; ++l)
            v[l] = x;
        return v;
    }
    [[gnu::always_inline]] static unsigned bits4(I4 m) {
#if defined(__SSE2__)
        return static_cast<unsigned>(_mm_movemask_ps(reinterpret_cast<__m128>(m)));
#else
        return static_cast<unsigned>((m[0] & 1) | (m[1] & 2) | (m[2] & 4) | (m[3] & 8));
#endif
    }
    // (For N = 8 two 128-bit sign-mask moves, as Lanes<4>::bits.)
    [[gnu::always_inline]] static unsigned bits(Vi m) {
        if constexpr (N == 4) {
            return bits4(m);
        } else {
            return bits4(__builtin_shufflevector(m, m, 0, 1, 2, 3)) |
                   bits4(__builtin_shufflevector(m, m, 4, 5, 6, 7)) << 4;
        }
    }

    QueryLanes<Vf> q_;
};

} // namespace wide

// One query region against wide nodes, for one cost model (sphere, or box with its k), W lanes
// per vector (2 or 4, see the header). Every member is inlined into its caller, so the
// caller's target decides the instructions. A fixed kind K must be the model's
// (boundKindOf); Any works for every model.
template <int W, BoundKind K = BoundKind::Any> class WideQueryT {
    using L = wide::Lanes<W>;
    using Vd = typename L::Vd;
    using Vm = typename L::Vm;

public:
    WideQueryT(const CostModel& model, const PackedRegion& r, const PackedExtra& e)
        : single_(r, e), q_(r, e, [](float x) { return splat(x); }), k_(model.k()),
          sphere_(model.volume() == VolumeType::Sphere) {}

    // Bit l set when lane l's pair bound exceeds `threshold`.
    // (BoxK0Single: when the bound certainly exceeds it, wide::SingleBoxK0.)
    [[gnu::always_inline]] unsigned exceeds(const WideRegions& w, double threshold) const {
        if constexpr (K == BoundKind::BoxK0Single) {
            return single_.exceeds(w, w, wide::SingleThreshold(threshold)) & 0xfu;
        } else {
            unsigned out = 0;
            for (int at = 0; at < 4; at += W)
                out |= exceedsPart(w, at, threshold) << at;
            return out;
        }
    }

    // exceeds() of two nodes at once: a's lanes in bits 0-3, b's in bits 4-7 (BoxK0Single
    // with W = 4 tests both in one vector).
    [[gnu::always_inline]] unsigned exceeds2(const WideRegions& a, const WideRegions& b,
                                             double threshold) const {
        if constexpr (K == BoundKind::BoxK0Single && W == 4) {
            return single_.exceeds(a, b, wide::SingleThreshold(threshold));
        }
        return exceeds(a, threshold) | exceeds(b, threshold) << 4;
    }

    // Lane l: a lower bound of the cost of the query with anything in slot l, for ordering a
    // search.
    [[gnu::always_inline]] void bounds(const WideRegions& w, double out[4]) const {
        static_assert(K != BoundKind::BoxK0Single, "the single-precision kind only tests");
        for (int at = 0; at < 4; at += W)
            boundsPart(w, at, out + at);
    }

private:
    static constexpr double kSafety = 1.0 - 1e-9;
    static constexpr double kSphereVolume = 4.0 / 3.0 * 3.14159265358979323846;

    struct Terms {
        Vd fvSum;
        Vd lhs; // the volume bound times fvSum, safety applied
        Vd e[3];
        Vd v;
    };

    [[gnu::always_inline]] static Vd load(const float* p) { return L::load(p); }
    [[gnu::always_inline]] static Vd splat(double x) { return L::splat(x); }
    [[gnu::always_inline]] static unsigned bits(Vm m) { return L::bits(m); }

    // Lanes at..at+W-1 of exceeds(), as bits 0..W-1.
    [[gnu::always_inline]] unsigned exceedsPart(const WideRegions& w, int at,
                                                double threshold) const {
        using wide::vmax;
        using wide::vmin;
        const Terms t = terms(w, at);
        const Vd rhs = splat(threshold) * t.fvSum;
        Vm out = t.lhs > rhs;
        if (sphere() || kIs(0.0)) return bits(out);
        const Vd hi = vmax(t.e[0], vmax(t.e[1], t.e[2]));
        const Vd minUb = this->minUb(w, at);
        if (kIs(1.0) || kIs(2.0)) {
            const Vd mid = vmax(vmin(t.e[0], t.e[1]), vmin(vmax(t.e[0], t.e[1]), t.e[2]));
            const Vd p = hi * hi * mid;
            const Vd coupled = kIs(1.0) ? p * vmax(t.fvSum, t.v) : p * p;
            out |= coupled * splat(kSafety) > rhs;
            const Vd shape = vmax(minUb, hi);
            out |= kIs(1.0) ? t.lhs * shape > rhs * minUb
                            : t.lhs * (shape * shape) > rhs * (minUb * minUb);
            return bits(out);
        }
        unsigned result = bits(out);
        for (int l = 0; l < W; ++l) {
            const glm::dvec3 e(t.e[0][l], t.e[1][l], t.e[2][l]);
            if (shapeVolumeBound(k_, e, t.v[l], t.fvSum[l]) * kSafety > threshold) {
                result |= 1u << l;
                continue;
            }
            const double shape = std::max(minUb[l], std::max(e.x, std::max(e.y, e.z)));
            if (t.lhs[l] * std::pow(shape, k_) > rhs[l] * std::pow(minUb[l], k_)) {
                result |= 1u << l;
            }
        }
        return result;
    }

    [[gnu::always_inline]] void boundsPart(const WideRegions& w, int at, double* out) const {
        using wide::vmax;
        const Terms t = terms(w, at);
        Vd bound = t.lhs / t.fvSum;
        if (!sphere() && !kIs(0.0)) {
            const Vd hi = vmax(t.e[0], vmax(t.e[1], t.e[2]));
            const Vd minUb = this->minUb(w, at);
            const Vd ratio = vmax(minUb, hi) / minUb;
            if (kIs(1.0) || kIs(2.0)) {
                // shapeVolumeBound (CostBounds.h) in the lanes, the same operations in order.
                using wide::vmin;
                const Vd mid = vmax(vmin(t.e[0], t.e[1]), vmin(vmax(t.e[0], t.e[1]), t.e[2]));
                const Vd p = hi * hi * mid;
                const Vd coupled = kIs(1.0) ? p * vmax(splat(1.0), t.v / t.fvSum) : p * p / t.fvSum;
                const Vd separate = kIs(1.0) ? bound * ratio : bound * (ratio * ratio);
                bound = vmax(separate, coupled * splat(kSafety));
            } else {
                for (int l = 0; l < W; ++l) {
                    const glm::dvec3 e(t.e[0][l], t.e[1][l], t.e[2][l]);
                    double b = bound[l] * std::pow(ratio[l], k_);
                    b = std::max(b, shapeVolumeBound(k_, e, t.v[l], t.fvSum[l]) * kSafety);
                    bound[l] = b;
                }
            }
        }
        for (int l = 0; l < W; ++l)
            out[l] = bound[l];
    }

    [[gnu::always_inline]] Terms terms(const WideRegions& w, int at) const {
        using wide::vmax;
        Terms t;
        t.fvSum = q_.maxFv + load(w.maxFv + at);
        Vd gap[3];
#pragma GCC unroll 3
        for (int i = 0; i < 3; ++i) {
            gap[i] = vmax(load(w.lo[i] + at) - q_.hi[i], q_.lo[i] - load(w.hi[i] + at));
        }
        if (sphere()) {
            const Vd zero = splat(0.0);
            const Vd gx = vmax(gap[0], zero), gy = vmax(gap[1], zero), gz = vmax(gap[2], zero);
            const Vd d2 = gx * gx + gy * gy + gz * gz;
            Vd d = d2;
            for (int l = 0; l < W; ++l)
                d[l] = std::sqrt(d2[l]);
            const Vd ra = q_.minSize, rb = load(w.minSize + at);
            const Vd r = vmax(vmax(ra, rb), (d + ra + rb) * splat(0.5));
            const Vd r3 = r * r * r;
            t.lhs = r3 * vmax(t.fvSum, splat(kSphereVolume) * r3) * splat(kSafety);
            return t;
        }
        Vd area[3];
#pragma GCC unroll 3
        for (int i = 0; i < 3; ++i) {
            const Vd wa = q_.minExtent[i], wb = load(w.minExtent[i] + at);
            t.e[i] = vmax(vmax(wa, wb), gap[i] + (wa + wb));
            area[i] = vmax(q_.minArea[i], load(w.minArea[i] + at));
        }
        const Vd vx = t.e[0] * vmax(area[0], t.e[1] * t.e[2]);
        const Vd vy = t.e[1] * vmax(area[1], t.e[0] * t.e[2]);
        const Vd vz = t.e[2] * vmax(area[2], t.e[0] * t.e[1]);
        t.v = vmax(vmax(vx, vmax(vy, vz)), vmax(q_.minSize, load(w.minSize + at)));
        t.lhs = t.v * vmax(t.fvSum, t.v) * splat(kSafety);
        return t;
    }

    // Smallest extent of the hull of the query and each of W slots.
    [[gnu::always_inline]] Vd minUb(const WideRegions& w, int at) const {
        using wide::vmax;
        using wide::vmin;
        Vd out = splat(std::numeric_limits<double>::max());
#pragma GCC unroll 3
        for (int i = 0; i < 3; ++i) {
            out =
                vmin(out, vmax(q_.hi[i], load(w.hi[i] + at)) - vmin(q_.lo[i], load(w.lo[i] + at)));
        }
        return out;
    }

    // The model, fixed by K or read at run time (Any). Each use is inlined with a constant
    // argument, so for a fixed kind it folds to a constant and the dead branches go.
    [[gnu::always_inline]] bool sphere() const {
        if constexpr (K == BoundKind::Any) return sphere_;
        return K == BoundKind::Sphere;
    }
    [[gnu::always_inline]] bool kIs(double k) const {
        if constexpr (K == BoundKind::Any) return !sphere_ && k_ == k;
        return ((K == BoundKind::BoxK0 || K == BoundKind::BoxK0Single) && k == 0.0) ||
               (K == BoundKind::BoxK1 && k == 1.0) || (K == BoundKind::BoxK2 && k == 2.0);
    }

    // (Two nodes per vector where W = 4, AVX2; one node per 128-bit vector otherwise.)
    // (BoxK0Single tests in single_ only; the other kinds in q_.)
    [[no_unique_address]] std::conditional_t<K == BoundKind::BoxK0Single,
                                             wide::SingleBoxK0<W == 4 ? 8 : 4>, wide::Nothing>
        single_;
    [[no_unique_address]] std::conditional_t<K == BoundKind::BoxK0Single, wide::Nothing,
                                             wide::QueryLanes<Vd>>
        q_;
    double k_;
    bool sphere_;
};

} // namespace hlod
