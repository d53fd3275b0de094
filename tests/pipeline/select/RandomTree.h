// Random HLOD trees for selection tests and benchmarks: leaves are small spheres scattered in
// a box, grouped bottom-up into parents of 2..maxChildren with enclosing spheres.
#pragma once

#include <random>

#include "pipeline/cluster/ClusterTree.h"

namespace hlod::test {

inline ClusterTree randomTree(std::size_t leaves, unsigned seed, int maxChildren = 4,
                              double extent = 1000.0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> pos(-extent, extent), rad(0.5, 5.0);
    ClusterTree t;
    std::vector<Id> level;
    for (std::size_t i = 0; i < leaves; ++i) {
        ClusterNode n;
        n.sphere = {{pos(rng), pos(rng) * 0.1, pos(rng)}, rad(rng)};
        n.instance = static_cast<Id>(i);
        t.nodes.push_back(n);
        level.push_back(static_cast<Id>(i));
    }
    std::uniform_int_distribution<int> fan(2, maxChildren);
    int lvl = 1;
    while (level.size() > 1) {
        // Sort by x then z so siblings are near each other (like a real clusterer).
        std::sort(level.begin(), level.end(), [&](Id a, Id b) {
            const auto& ca = t.nodes[a].sphere.center;
            const auto& cb = t.nodes[b].sphere.center;
            return lvl % 2 ? ca.x < cb.x : ca.z < cb.z;
        });
        std::vector<Id> next;
        for (std::size_t i = 0; i < level.size();) {
            const std::size_t k = std::min<std::size_t>(fan(rng), level.size() - i);
            ClusterNode p;
            p.level = lvl;
            glm::dvec3 c(0.0);
            for (std::size_t j = 0; j < k; ++j)
                c += t.nodes[level[i + j]].sphere.center;
            c /= static_cast<double>(k);
            double r = 0.0;
            const Id pid = static_cast<Id>(t.nodes.size());
            for (std::size_t j = 0; j < k; ++j) {
                ClusterNode& ch = t.nodes[level[i + j]];
                r = std::max(r, glm::length(ch.sphere.center - c) + ch.sphere.radius);
                ch.parent = pid;
                p.children.push_back(level[i + j]);
            }
            p.sphere = {c, r};
            t.nodes.push_back(p);
            next.push_back(pid);
            i += k;
        }
        level.swap(next);
        ++lvl;
    }
    t.root = level.front();
    return t;
}

} // namespace hlod::test
