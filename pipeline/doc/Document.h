// The editor's document: the pipeline graph (source scene paths in its Import node, parameters
// in every node, hand edits in its Cluster nodes), the view state, and the undo history.
// Every change of the model goes through execute(command) (Commands.h), so it can be undone;
// the graph's run state (statuses, outputs) is not part of the document's identity.
//
// Serialized form (toJson): {"graph": PipelineGraph JSON, "view": {...}}, paths as held (the
// project file makes them relative, ProjectFile.h). Two documents with equal toJson() are the
// same document: that is what the undo tests compare.
// View state: a JSON object owned by the editor (camera, selection, panel layout...); the
// document stores and round-trips it but never interprets it, and changing it is not a command.
// Threads: single-threaded like the graph; the editor runs a copy of the graph on a worker and
// brings the outcome back (PipelineGraph::adopt).
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/doc/Command.h"
#include "pipeline/doc/UndoStack.h"
#include "pipeline/graph/PipelineGraph.h"

namespace hlod {

class Document {
public:
    // The default graph (Import -> Cluster -> Bake -> Export) over `sources` (empty = sample).
    explicit Document(std::vector<std::filesystem::path> sources = {});
    explicit Document(PipelineGraph graph);
    Document(Document&&) = default;
    Document& operator=(Document&&) = default;

    PipelineGraph& graph() { return graph_; }
    const PipelineGraph& graph() const { return graph_; }

    const nlohmann::json& viewState() const { return view_; }
    void setViewState(nlohmann::json view); // throws InvalidArgument unless an object

    // Applies `command` and records it (see UndoStack::push); throws when it does not apply.
    void execute(std::unique_ptr<Command> command);
    void undo() { history_.undo(*this); }
    void redo() { history_.redo(*this); }
    UndoStack& history() { return history_; }
    const UndoStack& history() const { return history_; }
    bool isDirty() const { return !history_.isClean(); }
    void markSaved() { history_.setClean(); }

    // The Import node whose scene the editor opens (the lowest id; kNoNode when none) and its
    // sources. Every branch is built from the graph (PipelineGraph::run), never from a node
    // picked by kind.
    NodeId importNode() const;
    std::vector<std::filesystem::path> sources() const; // of importNode()
    // The tree a Cluster node produced last (what the user sees; nullptr before the first run).
    const ClusterTree* currentTree(NodeId clusterNode) const;

    nlohmann::json toJson() const;
    // Throws Malformed naming `file` (InvalidArgument when empty) for a bad document.
    static Document fromJson(const nlohmann::json& j, const std::filesystem::path& file = {});

private:
    PipelineGraph graph_;
    nlohmann::json view_ = nlohmann::json::object();
    UndoStack history_;
};

} // namespace hlod
