// The editor's document (contract in Document.h).
#include "pipeline/doc/Document.h"

#include "pipeline/core/Error.h"

namespace hlod {

Document::Document(std::vector<std::filesystem::path> sources)
    : graph_(PipelineGraph::makeDefault(std::move(sources))) {}

Document::Document(PipelineGraph graph) : graph_(std::move(graph)) {}

void Document::setViewState(nlohmann::json view) {
    if (!view.is_object()) throw Error(ErrorCode::InvalidArgument, "view state must be an object");
    view_ = std::move(view);
}

void Document::execute(std::unique_ptr<Command> command) {
    history_.push(std::move(command), *this);
}

NodeId Document::importNode() const {
    const std::vector<NodeId> imports = graph_.nodesOf(NodeKind::Import);
    return imports.empty() ? kNoNode : imports.front();
}

std::vector<std::filesystem::path> Document::sources() const {
    const NodeId id = importNode();
    return id == kNoNode ? std::vector<std::filesystem::path>{} : graph_.node(id).sources;
}

const ClusterTree* Document::currentTree(NodeId clusterNode) const {
    const NodeOutput* out = graph_.output(clusterNode);
    return out ? out->tree.get() : nullptr;
}

nlohmann::json Document::toJson() const { return {{"graph", graph_.toJson()}, {"view", view_}}; }

Document Document::fromJson(const nlohmann::json& j, const std::filesystem::path& file) {
    auto fail = [&](const std::string& what) {
        if (file.empty()) throw Error(ErrorCode::InvalidArgument, what);
        throw Error(ErrorCode::Malformed, file, what);
    };
    if (!j.is_object() || !j.contains("graph")) fail("missing key 'graph'");
    Document doc(PipelineGraph::fromJson(j["graph"], file));
    if (j.contains("view")) {
        if (!j["view"].is_object()) fail("'view' must be an object");
        doc.view_ = j["view"];
    }
    return doc;
}

} // namespace hlod
