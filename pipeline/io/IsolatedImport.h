// Runs an importer in a child process (fork), so that a crash, a runaway allocation or a hang
// inside a third-party parser becomes a clean error instead of taking the application down.
// assimp reads ~40 formats of untrusted files and some of its readers crash on bad input (the
// RAW reader leaves child pointers uninitialised, for instance); the scene comes back through
// a pipe in SceneBinary form.
//
// Progress: the importer gets a Progress whose reports travel up the same pipe (at most ~20 a
// second, plus every stage change and the last one) and are re-emitted on the caller's
// `progress` from the calling thread. Cancellation: the caller's cancel flag is looked at
// every 100 ms while the child runs; when raised the child is killed and Error(Cancelled)
// naming the file is thrown, however deep inside a third-party call the child was.
//
// Limits: the child gets an address-space limit (`memoryLimitBytes`) and the call a wall-clock
// timeout. Failure: the child's own hlod::Error is rethrown as is; a crash, a kill or a timeout
// throws Error(Malformed) naming the file and what happened.
#pragma once

#include <filesystem>
#include <functional>

#include "pipeline/core/Progress.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct IsolationLimits {
    unsigned long long memoryLimitBytes = 8ull << 30;
    unsigned timeoutSeconds = 600;
};

Scene runIsolated(const std::filesystem::path& file,
                  const std::function<Scene(const Progress&)>& import,
                  const IsolationLimits& limits = {}, const Progress& progress = {});

} // namespace hlod
