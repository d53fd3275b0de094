// Shared by `hlod build` and `hlod plan`: the document a build runs (a project file's, or the
// default graph Import -> Cluster -> Bake -> Export over the SCENE arguments) with the pipeline
// flags given on the command line applied to every node of their kind, and the resources a
// process used (for the shard and plan summaries).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "Args.h"
#include "pipeline/doc/Document.h"

namespace hlod::cli {

using ParamFlags = std::vector<std::pair<const ParamDecl*, ParamValue>>;

// Throws InvalidArgument for a project file given with other files.
Document documentFromArgs(const std::vector<std::string>& positionals, const ParamFlags& flags);

// This process so far: CPU seconds (user + system) and peak resident memory in bytes.
struct ProcessUsage {
    double cpuSeconds = 0.0;
    std::size_t peakBytes = 0;
};
ProcessUsage processUsage();

} // namespace hlod::cli
