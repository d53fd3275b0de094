// The document of a build from the command line, and the process's resource usage; see
// DocumentInput.h.
#include "DocumentInput.h"

#include <algorithm>

#include <sys/resource.h>

#include "pipeline/core/Error.h"
#include "pipeline/doc/ProjectFile.h"
#include "pipeline/export/Package.h"
#include "pipeline/io/Import.h"

namespace hlod::cli {

namespace {

bool isProjectFile(const std::string& arg) {
    const std::string ext = kProjectExtension;
    return arg.size() > ext.size() && arg.compare(arg.size() - ext.size(), ext.size(), ext) == 0;
}

} // namespace

Document documentFromArgs(const std::vector<std::string>& positionals, const ParamFlags& flags) {
    Document doc = [&] {
        for (const std::string& p : positionals) {
            if (!isProjectFile(p)) continue;
            if (positionals.size() != 1) {
                throw Error(ErrorCode::InvalidArgument,
                            "a project file is built on its own (its scenes are in the project)");
            }
            return openProject(p);
        }
        return Document(std::vector<std::filesystem::path>(positionals.begin(), positionals.end()));
    }();
    PipelineGraph& graph = doc.graph();
    for (const auto& [decl, value] : flags) {
        if (decl->key == "output") continue; // one Export's: pickExports
        for (NodeId id : graph.nodesOf(decl->node))
            graph.setParam(id, decl->key, value);
    }
    return doc;
}

std::optional<std::string> takeOutputFlag(ParamFlags& flags) {
    std::optional<std::string> out;
    std::erase_if(flags, [&](const auto& flag) {
        if (flag.first->key != "output") return false;
        out = std::get<std::string>(flag.second);
        return true;
    });
    return out;
}

namespace {

std::string listExports(const PipelineGraph& graph) {
    std::string list;
    for (NodeId id : graph.nodesOf(NodeKind::Export))
        list += (list.empty() ? "" : ", ") + describeNode(graph.node(id));
    return list;
}

NodeId findExport(const PipelineGraph& graph, const std::string& pick) {
    std::string digits = pick.starts_with('#') ? pick.substr(1) : pick;
    const bool number =
        !digits.empty() && digits.size() < 10 &&
        std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
    for (NodeId id : graph.nodeIds()) {
        const GraphNode& n = graph.node(id);
        const bool named =
            (number && id == std::stoul(digits)) || (!n.name.empty() && n.name == pick);
        if (!named) continue;
        if (n.kind != NodeKind::Export) {
            throw Error(ErrorCode::InvalidArgument, "--export " + pick + ": " + describeNode(n) +
                                                        " is not an Export node (" +
                                                        listExports(graph) + ")");
        }
        return id;
    }
    throw Error(ErrorCode::InvalidArgument,
                "--export " + pick +
                    " names no node of the project (its Export nodes: " + listExports(graph) + ")");
}

} // namespace

std::vector<NodeId> pickExports(PipelineGraph& graph, const std::optional<std::string>& pick,
                                const std::optional<std::string>& output) {
    std::vector<NodeId> exports = graph.nodesOf(NodeKind::Export);
    if (exports.empty()) {
        throw Error(ErrorCode::InvalidArgument,
                    "the project has no Export node: add one after a Bake node (it writes the "
                    "package)");
    }
    if (pick) exports = {findExport(graph, *pick)};
    if (!output) return exports;
    if (exports.size() != 1) {
        throw Error(ErrorCode::InvalidArgument,
                    "-o names one output folder, but the project has " +
                        std::to_string(exports.size()) + " Export nodes (" + listExports(graph) +
                        "): pick one with --export ID|NAME, or leave out -o to write each to its "
                        "own folder");
    }
    graph.setParam(exports.front(), "output", *output);
    return exports;
}

std::optional<LeanInputs> leanInputsOf(const PipelineGraph& graph, NodeId clusterNode,
                                       GlbCompression compression) {
    const GraphNode& cluster = graph.node(clusterNode);
    const NodeId importNode = graph.upstreamOf(clusterNode);
    if (importNode == kNoNode || !cluster.edits.empty()) return std::nullopt;
    const GraphNode& import = graph.node(importNode);
    // The files the import reads (a folder: its scene files, so a file added later is seen).
    if (import.sources.size() == 1 && isPackageFolder(import.sources[0])) return std::nullopt;
    std::vector<std::filesystem::path> files;
    try {
        files = expandInputs(import.sources);
    } catch (const Error&) {
        return std::nullopt; // the import names the problem
    }
    LeanInputs in;
    for (const std::filesystem::path& p : files) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(p, ec)) return std::nullopt;
        in.sources.push_back(std::filesystem::absolute(p).lexically_normal());
    }
    in.importParams = paramsToJson(NodeKind::Import, import.params);
    in.clusterParams = paramsToJson(NodeKind::Cluster, cluster.params);
    in.compression = compression;
    return in;
}

ProcessUsage processUsage() {
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    ProcessUsage u;
    u.cpuSeconds = static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
                   static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec) / 1e6;
    u.peakBytes = static_cast<std::size_t>(ru.ru_maxrss) * 1024; // Linux: kilobytes
    return u;
}

} // namespace hlod::cli
