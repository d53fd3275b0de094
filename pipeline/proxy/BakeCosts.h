// Measured bake costs (issue 30): what a distributed bake's shards record about the time each
// proxy took, so that the next plan (ShardPlan.h "Measured costs") balances shards by measured
// CPU seconds instead of estimated input triangles.
//
// Files: `<cache>/costs/<name>.costs`, text: the line "hlod-costs 1", then one line per node
// "<16 hex digits: structural key> <CPU seconds>". One file per shard run (named by the plan id
// and shard index), written atomically (AtomicFile.h), so shards on many machines never write
// the same file. Reading merges every file in name order (a key in several files: the last
// one's seconds). The costs are hints only: a file that cannot be read or is not in this
// format is skipped (the plan falls back to estimates for its nodes), never an error.
// Failure: writeBakeCosts throws Error(Io) naming the file when it cannot be written.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/proxy/ShardPlan.h"

namespace hlod {

// The folder of the cost records inside a cache folder.
std::filesystem::path bakeCostsFolder(const std::filesystem::path& cacheDir);

// Writes `costs` (structural key, CPU seconds) as `<cache>/costs/<name>.costs`; nothing is
// written when `costs` is empty.
void writeBakeCosts(const std::filesystem::path& cacheDir, const std::string& name,
                    const std::vector<std::pair<std::uint64_t, double>>& costs);

// Every record under `<cache>/costs/` (empty when there is none).
MeasuredCosts readBakeCosts(const std::filesystem::path& cacheDir);

} // namespace hlod
