// HLOD builds made synchronously for the widget tests (what a GraphRunner run delivers, without
// the thread), the graphs they come from, and the scenes they are made from.
#pragma once

#include <memory>

#include "pipeline/graph/PipelineGraph.h"
#include "widgets/GraphRunner.h"

namespace hlod::widgets {
class ProjectSession;
class StudioModel;
} // namespace hlod::widgets

namespace hlod::widgets::test {

// The parameters' declared defaults (what a new document builds: sphere clustering, level
// growth 2, decimate proxies, S = 300 px, proxy ratio 0.35), with two threads and no disk cache
// for the Bake node.
ParamValues testBakeValues();

// Gives `graph`'s Import node `import` the scene `scene` as its output, as the editor's loader
// hands over the scene it read (PipelineGraph::adopt).
void seedScene(PipelineGraph& graph, std::shared_ptr<const Scene> scene,
               NodeId import = kDefaultImport);

// The default graph Import -> Cluster -> Bake -> Export with testBakeValues() on its Bake node,
// `scene` as its Import node's output, and `cluster` and `bake` values on top.
PipelineGraph testGraph(std::shared_ptr<const Scene> scene, const ParamValues& cluster = {},
                        const ParamValues& bake = {});

// Runs Bake node kDefaultBake of testGraph(scene, cluster, bake) now, with the statistics, as a
// run delivers it.
BuiltHlod buildNow(std::shared_ptr<const Scene> scene, const ParamValues& cluster = {},
                   const ParamValues& bake = {});

// Three unit cubes on the X axis at x = -4, 0, 4 (nodes "cube 0..2", instances 0..2, the middle
// one red): far enough apart that none hides another's centre from any view not along X.
Scene makeCubeRow();

// The embedded sample scene and its build, made once per test run (about two seconds).
const BuiltHlod& sampleBuild();

// Sets the document's bake parameters to testBakeValues()' (no disk cache, two threads) through
// undoable commands, so an unedited rebuild of the sample gives sampleBuild()'s tree.
bool useTestBakeParameters(ProjectSession& session);

// The editor as it stands after opening the sample: the document's bake parameters set as
// useTestBakeParameters does, its Import node holding the sample scene, and `model` running the
// document's graph, showing its Bake node and sampleBuild(). False when a parameter could not be
// set.
bool showSampleBuild(ProjectSession& session, StudioModel& model);

// Waits for the next run of `model` to start (AutoRebuild's timer) and end well; true when it
// did within two minutes.
bool waitForBuild(StudioModel& model);

} // namespace hlod::widgets::test
