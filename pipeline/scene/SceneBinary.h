// Compact binary serialisation of a Scene (little-endian host layout, versioned header).
// Used to hand a scene across a process boundary (IsolatedImport) and for caches; not an
// interchange format. Failure: readSceneBinary throws Error(Malformed) on truncated or
// inconsistent input, never reads past the buffer, and caps counts by the buffer size.
#pragma once

#include <string>
#include <vector>

#include "pipeline/scene/Scene.h"

namespace hlod {

std::string writeSceneBinary(const Scene& scene);
Scene readSceneBinary(const std::string& bytes, const std::filesystem::path& origin);

} // namespace hlod
