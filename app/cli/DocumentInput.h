// Shared by `hlod build` and `hlod plan`: the document a build runs (a project file's, or the
// default graph Import -> Cluster -> Bake -> Export over the SCENE arguments) with the pipeline
// flags given on the command line applied to every node of their kind (the output folder -o
// excepted: it names one Export, pickExports), the Export nodes a run writes, and the resources
// a process used (for the shard and plan summaries).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "Args.h"
#include "pipeline/doc/Document.h"
#include "pipeline/graph/LeanFinal.h"

namespace hlod::cli {

using ParamFlags = std::vector<std::pair<const ParamDecl*, ParamValue>>;

// Throws InvalidArgument for a project file given with other files. The Export node's
// "output" flag (-o) is not applied here.
Document documentFromArgs(const std::vector<std::string>& positionals, const ParamFlags& flags);

// The Export nodes a build writes: every one of the graph (each branch is a variant), or the
// one `pick` names (--export ID|NAME: its id, "#ID", or its name). `output` (-o DIR) becomes the
// output folder of the picked Export, so it needs exactly one. Throws InvalidArgument naming
// what is wrong: no Export node, a pick that names none, -o with several Exports.
std::vector<NodeId> pickExports(PipelineGraph& graph, const std::optional<std::string>& pick,
                                const std::optional<std::string>& output);

// The output flag among the parsed flags (-o / --output), and the flags without it.
std::optional<std::string> takeOutputFlag(ParamFlags& flags);

// What the lean final step of a distributed bake matches a plan and a final build by
// (pipeline/graph/LeanFinal.h): the Import node upstream of `clusterNode` (its scene files,
// absolute, a folder's as the files it holds, and parameters) and the Cluster node's parameters,
// with `compression`. Nullopt when the branch cannot be matched without importing: hand edits,
// or a package folder as the source.
std::optional<LeanInputs> leanInputsOf(const PipelineGraph& graph, NodeId clusterNode,
                                       GlbCompression compression);

// This process so far: CPU seconds (user + system) and peak resident memory in bytes.
struct ProcessUsage {
    double cpuSeconds = 0.0;
    std::size_t peakBytes = 0;
};
ProcessUsage processUsage();

} // namespace hlod::cli
