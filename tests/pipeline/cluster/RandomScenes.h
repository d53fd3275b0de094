// Generated scenes for the clustering tests and benchmarks (header-only so bench/ can use it).
//
// A few shared meshes (a unit cube, an octahedron, a flat quad with a zero extent, a long thin
// bar) placed by one node each with a random rotation, uniform scale (log-uniform over two
// decades, so sizes vary like real parts) and position; one instance in eight gets a
// non-uniform scale (exercises the per-instance Welzl path). Layouts: uniform in a cube, or
// clumped (Gaussian blobs of varying size and population, like parts of assemblies). Exact
// duplicates (same mesh, same transform) are sprinkled in so that equal costs, and with them
// the id tie-breaks, really occur.
// Deterministic for a seed (std::mt19937_64 and libstdc++'s distributions).
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/scene/Scene.h"

namespace hlod::test {

enum class Layout { Uniform, Clumped };

struct RandomSceneOptions {
    std::size_t instances = 100;
    Layout layout = Layout::Uniform;
    std::uint64_t seed = 1;
    double duplicateRate = 0.05; // fraction of instances that copy the previous transform
};

inline Mesh makeBoxMesh(const glm::vec3& lo, const glm::vec3& hi, const std::string& name) {
    Mesh m;
    m.name = name;
    for (int i = 0; i < 8; ++i) {
        m.positions.emplace_back((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y,
                                 (i & 4) ? hi.z : lo.z);
    }
    m.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
    return m;
}

inline void addRandomSceneMeshes(Scene& s) {
    s.addMesh(makeBoxMesh({-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}, "cube"));
    Mesh octa;
    octa.name = "octahedron";
    octa.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    octa.indices = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    s.addMesh(std::move(octa));
    Mesh quad;
    quad.name = "quad";
    quad.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    s.addMesh(std::move(quad));
    s.addMesh(makeBoxMesh({-2.0f, -0.1f, -0.1f}, {2.0f, 0.1f, 0.1f}, "bar"));
}

inline Scene makeRandomScene(const RandomSceneOptions& o) {
    Scene s;
    addRandomSceneMeshes(s);
    std::mt19937_64 rng(o.seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> gauss(0.0, 1.0);
    // World size grows with n so that density stays comparable across sizes.
    const double side = 10.0 * std::cbrt(static_cast<double>(o.instances));
    struct Clump {
        glm::dvec3 center;
        double sigma;
    };
    std::vector<Clump> clumps;
    if (o.layout == Layout::Clumped) {
        const std::size_t count = std::max<std::size_t>(1, o.instances / 200);
        for (std::size_t c = 0; c < count; ++c) {
            clumps.push_back({glm::dvec3(unit(rng), unit(rng), unit(rng)) * side,
                              side * 0.01 * (1.0 + 4.0 * unit(rng))});
        }
    }
    s.nodes.reserve(o.instances + 1);
    s.instances.reserve(o.instances);
    glm::dmat4 previous(1.0);
    Id previousMesh = 0;
    for (std::size_t i = 0; i < o.instances; ++i) {
        glm::dmat4 m;
        Id mesh;
        if (i > 0 && unit(rng) < o.duplicateRate) {
            m = previous;
            mesh = previousMesh;
        } else {
            glm::dvec3 pos;
            if (clumps.empty()) {
                pos = glm::dvec3(unit(rng), unit(rng), unit(rng)) * side;
            } else {
                const Clump& c =
                    clumps[static_cast<std::size_t>(unit(rng) * clumps.size()) % clumps.size()];
                pos = c.center + glm::dvec3(gauss(rng), gauss(rng), gauss(rng)) * c.sigma;
            }
            const double scale = 0.2 * std::pow(10.0, 2.0 * unit(rng));
            const glm::dvec3 axis =
                glm::normalize(glm::dvec3(gauss(rng), gauss(rng), gauss(rng)) + 1e-9);
            m = glm::translate(glm::dmat4(1.0), pos) *
                glm::rotate(glm::dmat4(1.0), unit(rng) * 6.283185307179586, axis) *
                glm::scale(glm::dmat4(1.0), glm::dvec3(scale));
            if (unit(rng) < 0.125) {
                m = m *
                    glm::scale(glm::dmat4(1.0), glm::dvec3(1.0 + unit(rng), 1.0, 0.5 + unit(rng)));
            }
            mesh = static_cast<Id>(rng() % s.meshes.size());
        }
        const Id node = s.addNode("", 0, m);
        s.addInstance(mesh, node);
        previous = m;
        previousMesh = mesh;
    }
    return s;
}

} // namespace hlod::test
