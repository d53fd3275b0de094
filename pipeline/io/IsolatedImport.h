// Runs an importer in a child process (fork), so that a crash, a runaway allocation or a hang
// inside a third-party parser becomes a clean error instead of taking the application down.
// assimp reads ~40 formats of untrusted files and some of its readers crash on bad input (the
// RAW reader leaves child pointers uninitialised, for instance); the scene comes back through
// a pipe in SceneBinary form.
//
// Limits: the child gets an address-space limit (`memoryLimitBytes`) and the call a wall-clock
// timeout. Failure: the child's own hlod::Error is rethrown as is; a crash, a kill or a timeout
// throws Error(Malformed) naming the file and what happened.
#pragma once

#include <filesystem>
#include <functional>

#include "pipeline/scene/Scene.h"

namespace hlod {

struct IsolationLimits {
    unsigned long long memoryLimitBytes = 8ull << 30;
    unsigned timeoutSeconds = 600;
};

Scene runIsolated(const std::filesystem::path& file, const std::function<Scene()>& import,
                  const IsolationLimits& limits = {});

} // namespace hlod
