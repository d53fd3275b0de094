// HLOD builds made synchronously for the widget tests (what HlodBuilder delivers, without the
// thread), and the scenes they are made from.
#pragma once

#include <memory>

#include "pipeline/doc/HlodBuild.h"
#include "widgets/HlodBuilder.h"

namespace hlod::widgets::test {

// Sphere clustering, decimate proxies, S = 300 px, two threads, no disk cache.
HlodSettings testSettings();

// buildHlod plus the statistics, as HlodBuilder computes them.
BuiltHlod buildNow(std::shared_ptr<const Scene> scene,
                   const HlodSettings& settings = testSettings());

// Three unit cubes on the X axis at x = -4, 0, 4 (nodes "cube 0..2", instances 0..2, the middle
// one red): far enough apart that none hides another's centre from any view not along X.
Scene makeCubeRow();

// The embedded sample scene and its build, made once per test run (about two seconds).
const BuiltHlod& sampleBuild();

} // namespace hlod::widgets::test
