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
//   BottomUpClusterer.h). Only the clustering volumes are padded; ClusterNode::box stays exact.
// - Canonical operand order. merge(lo, hi) is evaluated with the lower-keyed cluster first, so
//   rounding never depends on who asked: cost(A, B) is one number.
// The unit stores F*V directly ("geometry volume") rather than F, so eq. 3.1 needs no
// volume recomputation and the fill is fv / volume.
#pragma once

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

// What a spatial search knows about a set of clusters (a BVH node, MergeBvh.h): lower bounds
// of their size and an upper bound of their F*V.
struct Region {
    Aabb box;            // holds every cluster's search volume
    double maxFv = 0.0;  // largest F*V
    double minRadius = 0.0;
    double minVolume = 0.0;
    glm::dvec3 minExtent{0.0}; // smallest box extent per axis
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

    // Lower bound of mergeCost(x, g) over every cluster g described by `region`. Used to prune
    // spatial searches; it is slightly below the mathematical bound so rounding can never make
    // it exceed a real cost.
    double lowerBound(const ClusterUnit& x, const Region& region) const;

    // The region of the single cluster u (its search box: the sphere's box for the sphere
    // model).
    Region regionOf(const ClusterUnit& u) const;

    // Size class for MergeBvh: binary exponent of the radius (sphere) or of the cube root of
    // the volume (box), so clusters within a class differ in size by less than 2x.
    int sizeClass(const ClusterUnit& u) const;

    // Model cost of a single cluster with its own volume and fill.
    double costOf(const Sphere& s, const Aabb& box, double volume, double fv) const;

private:
    struct Eval {
        double volume;
        double fv;
        double cost;
    };
    Eval evaluate(const ClusterUnit& lo, const ClusterUnit& hi, const Sphere& sphere,
                  const Aabb& box) const;
    double powK(double ratio) const;

    VolumeType volume_;
    double k_;
};

// Box `b` grown about its centre so that every extent is at least `minExtent`.
Aabb padBox(const Aabb& b, double minExtent);

} // namespace hlod
