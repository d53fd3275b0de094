// HLOD builds made synchronously for the widget tests (what HlodBuilder delivers, without the
// thread), and the scenes they are made from.
#pragma once

#include <memory>

#include "pipeline/doc/HlodBuild.h"
#include "widgets/HlodBuilder.h"

namespace hlod::widgets {
class ProjectSession;
class StudioModel;
} // namespace hlod::widgets

namespace hlod::widgets::test {

// The parameters' declared defaults (what a new document builds: sphere clustering, level
// growth 2, decimate proxies, S = 300 px, proxy ratio 0.35), with two threads and no disk cache.
HlodSettings testSettings();

// buildHlod plus the statistics, as HlodBuilder computes them.
BuiltHlod buildNow(std::shared_ptr<const Scene> scene,
                   const HlodSettings& settings = testSettings());

// Three unit cubes on the X axis at x = -4, 0, 4 (nodes "cube 0..2", instances 0..2, the middle
// one red): far enough apart that none hides another's centre from any view not along X.
Scene makeCubeRow();

// The embedded sample scene and its build, made once per test run (about two seconds).
const BuiltHlod& sampleBuild();

// Sets the document's bake parameters to testSettings()' (no disk cache, two threads) through
// undoable commands, so an unedited rebuild of the sample gives sampleBuild()'s tree.
bool useTestBakeParameters(ProjectSession& session);

// The editor as it stands after opening the sample: the document's bake parameters set as
// useTestBakeParameters does, and `model` showing that document, the sample scene and
// sampleBuild(). False when a parameter could not be set.
bool showSampleBuild(ProjectSession& session, StudioModel& model);

// Waits for the next build of `model` to start (AutoRebuild's timer) and finish; true when it
// finished within two minutes.
bool waitForBuild(StudioModel& model);

} // namespace hlod::widgets::test
