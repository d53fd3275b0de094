// Synchronous HLOD builds for the widget tests (see TestBuilds.h).
#include "TestBuilds.h"

#include <QSignalSpy>
#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/doc/Commands.h"
#include "pipeline/graph/Parameters.h"
#include "pipeline/io/SampleScene.h"
#include "pipeline/scene/Primitives.h"
#include "widgets/StudioModel.h"
#include "widgets/doc/ProjectSession.h"

namespace hlod::widgets::test {

HlodSettings testSettings() {
    // The declared defaults (pipeline/graph/Parameters.cpp: sphere, decimate, S = 300 px, level
    // growth 2, proxy ratio 0.35), which a new document and `hlod build` use, not the library
    // structs' (ClusterParams{}.levelGrowth is 1, the thesis' merges): a test that shows a build
    // of these next to a document must be showing what the document would build.
    ParamValues bake = defaultValues(NodeKind::Bake);
    bake["cache"] = false;
    bake["threads"] = 2;
    return hlodSettingsFrom(defaultValues(NodeKind::Cluster), bake);
}

BuiltHlod buildNow(std::shared_ptr<const Scene> scene, const HlodSettings& settings) {
    auto build = std::make_shared<HlodBuild>(buildHlod(*scene, settings));
    return withStatistics(std::move(scene), std::move(build));
}

Scene makeCubeRow() {
    Scene scene;
    Material red;
    red.name = "red";
    red.baseColor = {0.8f, 0.05f, 0.03f, 1.0f};
    const Id redId = scene.addMaterial(red);
    const Id grey = scene.addMesh(makeBox({1.0f, 1.0f, 1.0f}));
    Mesh redCube = makeBox({1.0f, 1.0f, 1.0f});
    redCube.material = redId;
    const Id redMesh = scene.addMesh(redCube);
    for (int i = 0; i < 3; ++i) {
        const Id node = scene.addNode("cube " + std::to_string(i), 0,
                                      glm::translate(glm::dmat4(1.0), {4.0 * (i - 1), 0.0, 0.0}));
        scene.addInstance(i == 1 ? redMesh : grey, node);
    }
    scene.updateWorldTransforms();
    return scene;
}

const BuiltHlod& sampleBuild() {
    static const BuiltHlod built = buildNow(std::make_shared<const Scene>(makeSampleScene()));
    return built;
}

bool useTestBakeParameters(ProjectSession& session) {
    const NodeId bake = session.document().bakeNode();
    return session.undo()->execute(std::make_unique<SetParameter>(bake, "cache", false)) &&
           session.undo()->execute(std::make_unique<SetParameter>(bake, "threads", 2));
}

bool showSampleBuild(ProjectSession& session, StudioModel& model) {
    const BuiltHlod& sample = sampleBuild();
    if (!useTestBakeParameters(session)) return false;
    model.setDocument(&session.document());
    model.setScene(sample.scene);
    model.setBuilt(sample);
    return true;
}

bool waitForBuild(StudioModel& model) {
    QSignalSpy finished(&model, &StudioModel::buildFinished);
    if (!model.building()) {
        QSignalSpy started(&model, &StudioModel::buildStarted);
        if (!started.wait(5000)) return false;
    }
    return !finished.isEmpty() || finished.wait(120000);
}

} // namespace hlod::widgets::test
