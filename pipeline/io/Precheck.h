// Refuses files whose headers declare absurd element counts, before any parser allocates for
// them (assimp's OFF reader, for instance, reserves what the header says: an 8 GB allocation
// from a 100-byte file). Counts are checked against `maxElements` and against the file size:
// a declared element needs at least a few bytes of data, so more elements than the file could
// hold is a lie. Covers OFF, PLY and binary STL, the formats whose headers carry counts, and
// COLLADA's instancing graph (DaeInstancing.h).
// Failure: throws Error(TooLarge) or Error(Malformed) naming the file.
#pragma once

#include <cstddef>
#include <filesystem>

#include "pipeline/io/ImportLimits.h"

namespace hlod {

void precheckElementCounts(const std::filesystem::path& file, const ImportLimits& limits);

} // namespace hlod
