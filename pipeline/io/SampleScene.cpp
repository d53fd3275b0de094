// The embedded sample scene: a small process plant on a 120 m x 80 m yard. It is made to show
// what HLOD does: clumps of detailed objects (tank farms, pipe racks, crate stacks) spread
// over a large area, shared meshes (instancing) and several materials.
#include "pipeline/io/SampleScene.h"

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/scene/Primitives.h"

namespace hlod {

namespace {

Id material(Scene& s, const char* name, glm::vec4 c) {
    return s.addMaterial(Material{name, c, {}, false, glm::vec4(1.0f)});
}

Id mesh(Scene& s, Mesh m, const char* name, Id mat) {
    m.name = name;
    m.material = mat;
    return s.addMesh(std::move(m));
}

glm::dmat4 at(double x, double y, double z) {
    return glm::translate(glm::dmat4(1.0), glm::dvec3(x, y, z));
}

} // namespace

Scene makeSampleScene() {
    Scene s;
    s.nodes[0].name = "sample-plant";
    const Id concrete = material(s, "concrete", {0.55f, 0.55f, 0.52f, 1.0f});
    const Id steel = material(s, "steel", {0.70f, 0.72f, 0.75f, 1.0f});
    const Id paint = material(s, "safety-yellow", {0.95f, 0.75f, 0.10f, 1.0f});
    const Id wood = material(s, "wood", {0.60f, 0.42f, 0.25f, 1.0f});
    const Id pipeRed = material(s, "pipe-red", {0.75f, 0.18f, 0.15f, 1.0f});

    const Id ground = mesh(s, makeBox({120.0f, 0.5f, 80.0f}), "yard", concrete);
    const Id tank = mesh(s, makeCylinder(3.0f, 9.0f, 48), "tank", steel);
    const Id dome = mesh(s, makeSphere(3.0f, 32, 12), "tank-dome", steel);
    const Id post = mesh(s, makeBox({0.4f, 6.0f, 0.4f}), "rack-post", paint);
    const Id beam = mesh(s, makeBox({10.0f, 0.3f, 0.3f}), "rack-beam", paint);
    const Id pipe = mesh(s, makeCylinder(0.25f, 10.0f, 24), "pipe", pipeRed);
    const Id crate = mesh(s, makeBox({1.2f, 1.2f, 1.2f}), "crate", wood);

    s.addInstance(ground, s.addNode("yard", 0, at(0, -0.25, 0)));
    const Id farm = s.addNode("tank-farm", 0, at(-35, 0, -15));
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const Id t =
                s.addNode("tank-" + std::to_string(i * 3 + j), farm, at(i * 9.0, 0, j * 9.0));
            s.addInstance(tank, t);
            s.addInstance(dome, s.addNode("dome", t, at(0, 9.0, 0)));
        }
    }
    for (int r = 0; r < 3; ++r) {
        const Id rack = s.addNode("pipe-rack-" + std::to_string(r), 0, at(5 + r * 11.0, 0, 10));
        for (int p = 0; p < 2; ++p) {
            s.addInstance(post, s.addNode("post", rack, at(p * 9.6 - 4.8, 3.0, -1.5)));
            s.addInstance(post, s.addNode("post", rack, at(p * 9.6 - 4.8, 3.0, 1.5)));
        }
        s.addInstance(beam, s.addNode("beam", rack, at(0, 6.0, -1.5)));
        s.addInstance(beam, s.addNode("beam", rack, at(0, 6.0, 1.5)));
        const glm::dmat4 alongX = glm::rotate(glm::dmat4(1.0), -glm::pi<double>() / 2, {0, 0, 1});
        for (int k = 0; k < 4; ++k) {
            s.addInstance(pipe, s.addNode("pipe", rack, at(-5.0, 6.4, -1.2 + k * 0.8) * alongX));
        }
    }
    for (int st = 0; st < 4; ++st) {
        const Id stack = s.addNode("crate-stack-" + std::to_string(st), 0,
                                   at(30 + (st % 2) * 12.0, 0, -25 + (st / 2) * 12.0));
        for (int c = 0; c < 12; ++c) {
            const double x = (c % 3) * 1.3, z = ((c / 3) % 2) * 1.3, y = 0.6 + (c / 6) * 1.2;
            s.addInstance(crate, s.addNode("crate", stack, at(x, y, z)));
        }
    }
    s.sourceFiles.push_back("sample:plant");
    return s;
}

} // namespace hlod
