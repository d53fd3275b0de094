// The clustering cost of thesis sections 3.2.3 and 4.1-4.2: how two clusters merge, the fill
// factor of the result and what the merge costs.
//
// Sphere (Sappa & Garcia 2004, thesis algorithm 2 and eq. 3.1):
//     AB = smallest sphere enclosing A and B,   C_AB = r_AB^3 / F_AB
// AABB (thesis eq. 4.1):
//     AB = hull of A and B,   C_AB = V_AB / F_AB * (max extent / min extent)^k
// Fill factor (eq. 3.1), with the exact overlap of the two volumes (OverlapVolume.h):
//     F_AB = (F_A V_A + F_B V_B - V_overlap) / V_AB
//
// Choices the thesis leaves open (documented here because the fast clusterer, the naive test
// reference and the baselines all evaluate costs through this one class):
// - Clamped fill. With F < 1 the overlap term can exceed what the two clusters really hold
//   (two sparse clusters whose volumes overlap a lot), and eq. 3.1 then goes to zero or below,
//   which would make the cost infinite or negative. The numerator is clamped to
//   [max(F_A V_A, F_B V_B), V_AB]: the merged cluster holds at least the geometry of the
//   fuller part and at most its whole volume. So 0 < F <= 1 always.
// - Degenerate volumes. A flat part (a floor plate, a decal) has a zero box extent, which
//   makes V = 0 and the proportion ratio infinite. Every leaf box is padded about its centre to
//   a minimum extent `minExtent` per axis and every leaf sphere to a minimum radius
//   minExtent / 2 before clustering (the clusterer derives minExtent from the scene size, see
//   ClusterDriver.h). Only the clustering volumes are padded; ClusterNode::box stays exact.
// - Canonical operand order. merge(lo, hi) is evaluated with the lower-keyed cluster first, so
//   rounding never depends on who asked: cost(A, B) is one number.
// The unit stores F*V directly ("geometry volume") rather than F, so eq. 3.1 needs no
// volume recomputation and the fill is fv / volume.
#pragma once

#include <algorithm>
#include <cmath>

#include "pipeline/bounds/Sphere.h"
#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/scene/Aabb.h"

namespace hlod {

// A cluster as the cost model sees it. `volume` is V of the model's volume type (sphere or
// padded box), `fv` is F*V, `cost` is the model cost of this cluster.
struct ClusterUnit {
    Sphere sphere; // enclosing sphere (padded for leaves)
    Aabb box;      // padded box (hull of padded leaf boxes)
    double volume = 0.0;
    double fv = 0.0;
    double cost = 0.0;
    double fill() const { return volume > 0.0 ? fv / volume : 1.0; }
};

class CostModel {
public:
    // `volume` must be VolumeType::Sphere or VolumeType::Aabb; `k` >= 0 (used by Aabb only).
    // Throws Error(InvalidArgument) otherwise.
    CostModel(VolumeType volume, double k);

    VolumeType volume() const { return volume_; }
    double k() const { return k_; }

    // A leaf (F = 1) from its exact bounds, padded to `minExtent` (> 0) as described above.
    ClusterUnit leaf(const Sphere& sphere, const Aabb& box, double minExtent) const;

    // The cluster of lo and hi (both bounds, fill, cost). `lo` is the operand with the lower
    // tie-break key.
    ClusterUnit merge(const ClusterUnit& lo, const ClusterUnit& hi) const;

    // merge(lo, hi).cost, computing only what the cost needs (same arithmetic, same bits).
    double mergeCost(const ClusterUnit& lo, const ClusterUnit& hi) const;

    // mergeCost(lo, hi) when it is <= limit, else some value > limit. The cost is at least
    // r_AB^3 (sphere) or V_AB (box): fill <= 1 and the proportion term >= 1, and rounding is
    // monotone, so when that bound already exceeds `limit` it is returned before the overlap
    // volume, the fill and the proportion are computed.
    double mergeCostWithin(const ClusterUnit& lo, const ClusterUnit& hi, double limit) const;

    // Model cost of a single cluster with its own volume and fill.
    double costOf(const Sphere& s, const Aabb& box, double volume, double fv) const;

    // ratio^k; exact for the thesis' k = 0, 1, 2 and cheaper than pow() there.
    double powK(double ratio) const {
        if (k_ == 0.0) return 1.0;
        if (k_ == 1.0) return ratio;
        if (k_ == 2.0) return ratio * ratio;
        return std::pow(ratio, k_);
    }

private:
    struct Eval {
        double volume;
        double fv;
        double cost;
    };
    Eval evaluate(const ClusterUnit& lo, const ClusterUnit& hi, const Sphere& sphere,
                  const Aabb& box) const;

    VolumeType volume_;
    double k_;
};

// Box `b` grown about its centre so that every extent is at least `minExtent`.
Aabb padBox(const Aabb& b, double minExtent);

} // namespace hlod
