// The embedded sample scene: a small procedurally generated "plant yard" (a ground plate,
// rows of tanks, pipe racks and crates with a few materials) so the app and the CLI have
// something to show with no file given. Deterministic: the same scene every time.
#pragma once

#include "pipeline/scene/Scene.h"

namespace hlod {

Scene makeSampleScene();

} // namespace hlod
