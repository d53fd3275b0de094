// Runtime LOD selection over an HLOD tree: thesis Algorithm 5 (frustum cull; draw a node when
// its projected bounding diameter is within the screen-size threshold S, else recurse), plus a
// frame-coherent front cache that starts from last frame's cut and refines or coarsens it.
//
// Why the front cache gives the same cut as the full traversal: call a node "open" when it is
// visible, has children and projects larger than S. With nested bounding spheres (a parent
// contains its children, enforced by SelectionTree's construction with a small margin) a child
// that is open has an open parent (visible child => visible parent; r_p >= r_c + |c_p - c_c|
// gives r_p/d_p >= r_c/d_c). The open nodes therefore form an ancestor-closed set and the cut is
// exactly {n : n not open, parent(n) open (or n is the root)}. Any previous cut covers every
// leaf once, so coarsening non-open front nodes up to the highest non-open ancestor and
// refining open front nodes down reaches every node of the new cut (tests compare both with a
// brute-force reference on random trees and cameras).
#pragma once

#include <cstdint>
#include <vector>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/select/Camera.h"

namespace hlod {

// Flat, cache-friendly copy of the tree's selection data (structure of arrays).
class SelectionTree {
public:
    // `nodeTriangles[i]`: what drawing node i costs (its proxy, or its leaf mesh).
    // `refineAlways`: the root when it has no proxy (the proxy economy's root whose proxy did
    // not pay, ProxyBaker.h): never drawn as itself, always refined while visible. Only the
    // root may be flagged (a flag elsewhere would break the ancestor-closed open set).
    SelectionTree(const ClusterTree& tree, std::vector<std::uint64_t> nodeTriangles,
                  bool refineRootAlways = false);

    std::size_t size() const { return parent_.size(); }
    Id root() const { return root_; }
    Id parent(Id n) const { return parent_[n]; }
    std::uint32_t childBegin(Id n) const { return childStart_[n]; }
    std::uint32_t childEnd(Id n) const { return childStart_[n + 1]; }
    Id child(std::uint32_t i) const { return children_[i]; }
    const glm::dvec3& center(Id n) const { return center_[n]; }
    double radius(Id n) const { return radius_[n]; }
    std::uint64_t triangles(Id n) const { return triangles_[n]; }
    bool refineAlways(Id n) const { return refineRoot_ && n == root_; }

private:
    std::vector<Id> parent_;
    std::vector<std::uint32_t> childStart_;
    std::vector<Id> children_;
    std::vector<glm::dvec3> center_;
    std::vector<double> radius_;
    std::vector<std::uint64_t> triangles_;
    Id root_ = 0;
    bool refineRoot_ = false;
};

struct SelectionParams {
    double screenSizePx = 300.0; // S: draw a node once it projects to at most this many pixels
};

struct SelectionResult {
    std::vector<Id> drawList;       // nodes to draw, sorted by id
    std::uint64_t nodesVisited = 0; // nodes whose bounds were tested
    std::uint64_t drawCalls = 0;    // one per drawn node
    std::uint64_t triangles = 0;
};

// Classifies one node for one camera; shared by every traversal so they agree exactly.
class NodeClassifier {
public:
    NodeClassifier(const SelectionTree& tree, const Camera& camera, const SelectionParams& p);
    bool visible(Id n) const;
    // Projected diameter > S (or the eye is inside the sphere), or a node without a proxy.
    bool tooBig(Id n) const;
    bool open(Id n) const;   // visible, has children and too big: recurse into it

private:
    const SelectionTree& tree_;
    Frustum frustum_;
    glm::dvec3 eye_;
    double sizeFactor_; // S / (pixels per unit at distance 1) / 2: compare r against d·factor
};

// Algorithm 5: full traversal from the root.
SelectionResult selectFull(const SelectionTree& tree, const Camera& camera,
                           const SelectionParams& params);

// Frame-coherent selection. Holds the previous frame's cut; the first call (or after reset)
// starts from the root. Same result as selectFull for the same camera.
class FrontCache {
public:
    explicit FrontCache(const SelectionTree& tree) : tree_(tree) {}
    SelectionResult select(const Camera& camera, const SelectionParams& params);
    void reset() { front_.clear(); }

private:
    const SelectionTree& tree_;
    std::vector<Id> front_;            // last cut (drawn and culled frontier nodes)
    std::vector<std::uint32_t> stamp_; // per node: frame number it was put in the new cut
    std::uint32_t frame_ = 0;
};

} // namespace hlod
