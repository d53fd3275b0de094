// Tiny hand-built scenes for the clustering tests: unit cubes placed by translation, so every
// box, volume and cost can be worked out by hand.
#pragma once

#include <algorithm>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "RandomScenes.h"
#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/scene/Scene.h"

namespace hlod::test {

// One instance of the cube [0,1]^3 (scaled by `size`) at each corner position, in order.
inline Scene cubesAt(const std::vector<glm::dvec3>& corners, double size = 1.0) {
    Scene s;
    s.addMesh(makeBoxMesh({0, 0, 0}, {1, 1, 1}, "cube"));
    for (const glm::dvec3& c : corners) {
        const glm::dmat4 m =
            glm::translate(glm::dmat4(1.0), c) * glm::scale(glm::dmat4(1.0), glm::dvec3(size));
        s.addInstance(0, s.addNode("cube", 0, m));
    }
    return s;
}

// Leaf instance ids below `node` (ascending).
inline std::vector<Id> leavesBelow(const ClusterTree& t, Id node) {
    std::vector<Id> out, stack{node};
    while (!stack.empty()) {
        const Id id = stack.back();
        stack.pop_back();
        if (t.nodes[id].isLeaf()) out.push_back(t.nodes[id].instance);
        for (Id c : t.nodes[id].children)
            stack.push_back(c);
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace hlod::test
