// Thesis Algorithm 5 (section 5.4) and its frame-coherent variant; see LodSelection.h for why
// both give the same cut.
#include "pipeline/select/LodSelection.h"

#include <algorithm>
#include <cmath>

namespace hlod {

SelectionTree::SelectionTree(const ClusterTree& tree, std::vector<std::uint64_t> nodeTriangles,
                             bool refineRootAlways)
    : triangles_(std::move(nodeTriangles)), root_(tree.root), refineRoot_(refineRootAlways) {
    const std::size_t n = tree.nodes.size();
    triangles_.resize(n, 0);
    parent_.resize(n);
    childStart_.assign(n + 1, 0);
    center_.resize(n);
    radius_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        parent_[i] = tree.nodes[i].parent;
        childStart_[i + 1] =
            childStart_[i] + static_cast<std::uint32_t>(tree.nodes[i].children.size());
        center_[i] = tree.nodes[i].sphere.center;
        radius_[i] = tree.nodes[i].sphere.radius;
    }
    children_.reserve(childStart_[n]);
    for (const ClusterNode& node : tree.nodes) {
        children_.insert(children_.end(), node.children.begin(), node.children.end());
    }
    // Enforce nesting with a margin, children before parents (post-order), so the open set is
    // ancestor-closed even where the clusterer's spheres touch within rounding.
    if (n == 0) return;
    std::vector<Id> order;
    order.reserve(n);
    std::vector<Id> stack{root_};
    while (!stack.empty()) {
        const Id id = stack.back();
        stack.pop_back();
        order.push_back(id);
        for (std::uint32_t c = childStart_[id]; c < childStart_[id + 1]; ++c) {
            stack.push_back(children_[c]);
        }
    }
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        const Id id = *it;
        double r = radius_[id];
        for (std::uint32_t c = childStart_[id]; c < childStart_[id + 1]; ++c) {
            const Id ch = children_[c];
            r = std::max(r, glm::length(center_[ch] - center_[id]) + radius_[ch]);
        }
        radius_[id] = r == radius_[id] ? r : r * (1.0 + 1e-12) + 1e-12;
    }
}

NodeClassifier::NodeClassifier(const SelectionTree& tree, const Camera& camera,
                               const SelectionParams& p)
    : tree_(tree), frustum_(Frustum::fromCamera(camera)), eye_(camera.eye) {
    // Projected diameter 2·r·ppu/d > S  <=>  d < r · (2·ppu/S). Clamped to >= 1 so a node is
    // never drawn with the eye inside its sphere (and the open set stays ancestor-closed).
    sizeFactor_ = std::max(2.0 * camera.pixelsPerUnitAtDistanceOne() / p.screenSizePx, 1.0);
}

bool NodeClassifier::visible(Id n) const {
    return frustum_.intersectsSphere(tree_.center(n), tree_.radius(n));
}

bool NodeClassifier::tooBig(Id n) const {
    if (tree_.refineAlways(n)) return true;
    const double d = glm::length(tree_.center(n) - eye_);
    return d < tree_.radius(n) * sizeFactor_;
}

bool NodeClassifier::open(Id n) const {
    return tree_.childBegin(n) != tree_.childEnd(n) && visible(n) && tooBig(n);
}

namespace {

void finish(const SelectionTree& tree, SelectionResult& r) {
    std::sort(r.drawList.begin(), r.drawList.end());
    r.drawCalls = r.drawList.size();
    for (Id n : r.drawList)
        r.triangles += tree.triangles(n);
}

} // namespace

SelectionResult selectFull(const SelectionTree& tree, const Camera& camera,
                           const SelectionParams& params) {
    SelectionResult r;
    if (tree.size() == 0) return r;
    const NodeClassifier cls(tree, camera, params);
    std::vector<Id> stack{tree.root()};
    while (!stack.empty()) {
        const Id n = stack.back();
        stack.pop_back();
        ++r.nodesVisited;
        if (!cls.visible(n)) continue; // culled with its whole subtree
        const bool leaf = tree.childBegin(n) == tree.childEnd(n);
        if (leaf || !cls.tooBig(n)) {
            r.drawList.push_back(n);
            continue;
        }
        for (std::uint32_t c = tree.childBegin(n); c < tree.childEnd(n); ++c) {
            stack.push_back(tree.child(c));
        }
    }
    finish(tree, r);
    return r;
}

SelectionResult FrontCache::select(const Camera& camera, const SelectionParams& params) {
    SelectionResult r;
    if (tree_.size() == 0) return r;
    const NodeClassifier cls(tree_, camera, params);
    if (stamp_.size() != tree_.size()) {
        stamp_.assign(tree_.size(), 0);
        front_.clear();
    }
    if (++frame_ == 0) { // wrapped: clear stamps once every 2^32 frames
        std::fill(stamp_.begin(), stamp_.end(), 0);
        frame_ = 1;
    }
    if (front_.empty()) front_.push_back(tree_.root());
    std::vector<Id> next;
    next.reserve(front_.size() + 16);
    auto addToCut = [&](Id n) {
        if (stamp_[n] == frame_) return;
        stamp_[n] = frame_;
        next.push_back(n);
    };
    std::vector<Id> stack;
    for (Id f : front_) {
        if (stamp_[f] == frame_) continue; // already covered by a coarsened ancestor
        ++r.nodesVisited;
        if (cls.open(f)) { // refine: Algorithm 5 below f
            stack.assign(1, f);
            while (!stack.empty()) {
                const Id n = stack.back();
                stack.pop_back();
                for (std::uint32_t c = tree_.childBegin(n); c < tree_.childEnd(n); ++c) {
                    const Id ch = tree_.child(c);
                    ++r.nodesVisited;
                    if (cls.open(ch))
                        stack.push_back(ch);
                    else
                        addToCut(ch);
                }
            }
            continue;
        }
        // Coarsen: climb while the parent is not open (an open parent keeps f in the cut).
        Id a = f;
        while (tree_.parent(a) != kNoId && stamp_[tree_.parent(a)] != frame_) {
            ++r.nodesVisited;
            if (cls.open(tree_.parent(a))) break;
            a = tree_.parent(a);
        }
        if (tree_.parent(a) != kNoId && stamp_[tree_.parent(a)] == frame_) {
            continue; // an ancestor is already in the new cut
        }
        addToCut(a);
    }
    front_.swap(next);
    for (Id n : front_) {
        if (cls.visible(n)) r.drawList.push_back(n);
    }
    finish(tree_, r);
    return r;
}

} // namespace hlod
