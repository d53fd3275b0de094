// The document of a build from the command line, and the process's resource usage; see
// DocumentInput.h.
#include "DocumentInput.h"

#include <sys/resource.h>

#include "pipeline/core/Error.h"
#include "pipeline/doc/ProjectFile.h"

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
        for (NodeId id : graph.nodeIds()) {
            if (graph.node(id).kind == decl->node) graph.setParam(id, decl->key, value);
        }
    }
    return doc;
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
