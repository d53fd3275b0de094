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

ParamValues testBakeValues() {
    // The declared defaults (pipeline/graph/Parameters.cpp: sphere, decimate, S = 300 px, level
    // growth 2, proxy ratio 0.35), which a new document and `hlod build` use: a test that shows a
    // build of these next to a document must be showing what the document would build.
    ParamValues bake = defaultValues(NodeKind::Bake);
    bake["cache"] = false;
    bake["threads"] = 2;
    return bake;
}

void seedScene(PipelineGraph& graph, std::shared_ptr<const Scene> scene, NodeId import) {
    NodeOutput out;
    out.scene = std::move(scene);
    out.inputs = {"test scene"};
    graph.adopt(import, graph.definition(import), NodeStatus::UpToDate,
                std::make_shared<const NodeOutput>(std::move(out)));
}

PipelineGraph testGraph(std::shared_ptr<const Scene> scene, const ParamValues& cluster,
                        const ParamValues& bake) {
    PipelineGraph g = PipelineGraph::makeDefault();
    for (const auto& [key, value] : testBakeValues())
        g.setParam(kDefaultBake, key, value);
    for (const auto& [key, value] : bake)
        g.setParam(kDefaultBake, key, value);
    for (const auto& [key, value] : cluster)
        g.setParam(kDefaultCluster, key, value);
    seedScene(g, std::move(scene));
    return g;
}

BuiltHlod buildNow(std::shared_ptr<const Scene> scene, const ParamValues& cluster,
                   const ParamValues& bake) {
    PipelineGraph g = testGraph(std::move(scene), cluster, bake);
    g.run({kDefaultBake});
    return withStatistics(kDefaultBake, g.sharedOutput(kDefaultBake));
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

namespace {

// The sample's run: the Bake node's build and the Cluster node's output it came from.
struct SampleRun {
    BuiltHlod built;
    std::shared_ptr<const NodeOutput> cluster;
};

const SampleRun& sampleRun() {
    static const SampleRun run = [] {
        PipelineGraph g = testGraph(std::make_shared<const Scene>(makeSampleScene()));
        g.run({kDefaultBake});
        return SampleRun{withStatistics(kDefaultBake, g.sharedOutput(kDefaultBake)),
                         g.sharedOutput(kDefaultCluster)};
    }();
    return run;
}

} // namespace

const BuiltHlod& sampleBuild() { return sampleRun().built; }

bool useTestBakeParameters(ProjectSession& session) {
    const NodeId bake = kDefaultBake;
    return session.undo()->execute(std::make_unique<SetParameter>(bake, "cache", false)) &&
           session.undo()->execute(std::make_unique<SetParameter>(bake, "threads", 2));
}

bool showSampleBuild(ProjectSession& session, StudioModel& model) {
    const BuiltHlod& sample = sampleBuild();
    if (!useTestBakeParameters(session)) return false;
    PipelineGraph& graph = session.document().graph();
    seedScene(graph, sample.scene);
    // The sample's build is this document's: its Cluster and Bake nodes are up to date with it.
    graph.adopt(kDefaultCluster, graph.definition(kDefaultCluster), NodeStatus::UpToDate,
                sampleRun().cluster);
    graph.adopt(kDefaultBake, graph.definition(kDefaultBake), NodeStatus::UpToDate, sample.build);
    model.setGraph(&graph);
    model.setScene(sample.scene);
    model.setShownBake(kDefaultBake);
    model.setBuilt(sample);
    return true;
}

bool waitForBuild(StudioModel& model) {
    QSignalSpy finished(&model, &StudioModel::runFinished);
    if (!model.building()) {
        QSignalSpy started(&model, &StudioModel::buildStarted);
        if (!started.wait(5000)) return false;
    }
    return !finished.isEmpty() || finished.wait(120000);
}

} // namespace hlod::widgets::test
