// Tree quality measures (definitions in TreeMetrics.h).
#include "pipeline/cluster/TreeMetrics.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hlod {

namespace {

// Count, mean and sum of squared deviations of a set of points.
struct Moments {
    double n = 0.0;
    glm::dvec3 mean{0.0};
    double m2 = 0.0;

    void add(const Moments& o) {
        if (o.n == 0.0) return;
        if (n == 0.0) {
            *this = o;
            return;
        }
        const double total = n + o.n;
        const glm::dvec3 delta = o.mean - mean;
        mean += delta * (o.n / total);
        m2 += o.m2 + glm::dot(delta, delta) * n * o.n / total;
        n = total;
    }
};

} // namespace

TreeMetrics computeTreeMetrics(const ClusterTree& tree) {
    TreeMetrics m;
    if (tree.root == kNoId || tree.nodes.empty()) return m;
    const std::vector<Id> order = childrenFirst(tree, {tree.root});
    std::vector<Moments> moments(tree.nodes.size());
    std::vector<int> depthOf(tree.nodes.size(), 0);
    // Depths top-down: reverse post-order visits parents first.
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        for (Id c : tree.nodes[*it].children)
            depthOf[c] = depthOf[*it] + 1;
    }
    const glm::dvec3 origin = tree.nodes[tree.root].box.center(); // keeps moments well scaled
    double leafDepthSum = 0.0, childSum = 0.0, fillSum = 0.0, spreadSum = 0.0;
    m.minChildren = static_cast<std::size_t>(-1);
    for (Id id : order) {
        const ClusterNode& n = tree.nodes[id];
        ++m.nodes;
        if (n.isLeaf()) {
            ++m.leaves;
            m.depth = std::max(m.depth, depthOf[id]);
            leafDepthSum += depthOf[id];
            moments[id] = Moments{1.0, n.box.center() - origin, 0.0};
            continue;
        }
        ++m.innerNodes;
        for (Id c : n.children)
            moments[id].add(moments[c]);
        childSum += static_cast<double>(n.children.size());
        m.minChildren = std::min(m.minChildren, n.children.size());
        m.maxChildren = std::max(m.maxChildren, n.children.size());
        m.totalSphereVolume += n.sphere.volume();
        m.totalBoxVolume += n.box.volume();
        fillSum += n.fill;
        const double rms = std::sqrt(moments[id].m2 / moments[id].n);
        const double spread = n.sphere.radius > 0.0 ? rms / n.sphere.radius : 0.0;
        spreadSum += spread;
        m.maxSpread = std::max(m.maxSpread, spread);
    }
    m.meanLeafDepth = leafDepthSum / static_cast<double>(m.leaves);
    if (m.innerNodes == 0) {
        m.minChildren = 0;
        return m;
    }
    const double inner = static_cast<double>(m.innerNodes);
    m.meanChildren = childSum / inner;
    m.meanFill = fillSum / inner;
    m.meanSpread = spreadSum / inner;
    return m;
}

} // namespace hlod
