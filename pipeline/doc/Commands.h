// The document's edit commands (contract in Command.h): parameter edits, graph edits, source
// changes and cluster hand edits. Each stores what it changes before and after, so apply and
// revert are plain assignments and a revert restores the document exactly.
// Texts name the node they act on, as the history shows them: "Set Volume of Cluster #5",
// "Add Bake #8", "Merge clusters (Cluster #2)" (nodeLabel, PipelineGraph.h).
//
// Cluster hand edits name clusters by their leaf sets (instance ids, HandEdits.h) and act on
// one Cluster node's HandEdits through the pure functions of ClusterEdits.h; the node is rerun
// by the next graph run, and the Bake stage rebakes only the proxies whose content changed (the
// edited clusters and their ancestors), reusing the rest from the cache.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "pipeline/doc/Command.h"
#include "pipeline/graph/HandEdits.h"
#include "pipeline/graph/PipelineGraph.h"

namespace hlod {

// Sets one parameter of one node. With a non-zero mergeId, consecutive edits of the same
// parameter of the same node with that id become one undo step (a slider drag: the widget takes
// UndoStack::newMergeId() when the drag starts).
class SetParameter : public Command {
public:
    SetParameter(NodeId node, std::string key, ParamValue value, std::uint64_t mergeId = 0);
    std::string text() const override;
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    std::uint64_t mergeId() const override { return mergeId_; }
    bool mergeWith(const Command& next) override;
    nlohmann::json toJson() const override;

private:
    NodeId node_;
    std::string key_;
    ParamValue value_;
    std::optional<ParamValue> before_;
    std::uint64_t mergeId_;
};

class SetSources : public Command {
public:
    SetSources(NodeId importNode, std::vector<std::filesystem::path> sources);
    std::string text() const override { return "Set scene files"; }
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    nlohmann::json toJson() const override;

private:
    NodeId node_;
    std::vector<std::filesystem::path> after_, before_;
};

// Adds a node of `kind` at (x, y); with `input` set, the new node's first input is connected to
// the first output of `input` in the same step (a Bake added after a Cluster node). Throws
// InvalidArgument when the port types do not match.
class AddNode : public Command {
public:
    AddNode(NodeKind kind, double x = 0.0, double y = 0.0, NodeId input = kNoNode);
    std::string text() const override;
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    nlohmann::json toJson() const override;
    NodeId node() const { return node_.id; } // valid after the first apply

private:
    GraphNode node_;
    NodeId input_;
    NodeId nextBefore_ = kNoNode;
};

class RemoveNode : public Command {
public:
    explicit RemoveNode(NodeId node) : id_(node) {}
    std::string text() const override;
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    nlohmann::json toJson() const override;

private:
    NodeId id_;
    std::optional<GraphNode> removed_;
    std::vector<Connection> connections_;
};

class ConnectNodes : public Command {
public:
    explicit ConnectNodes(Connection c) : c_(c) {}
    std::string text() const override { return text_; }
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    nlohmann::json toJson() const override;

private:
    Connection c_;
    std::string text_ = "Connect nodes";
};

class DisconnectNodes : public Command {
public:
    explicit DisconnectNodes(Connection c) : c_(c) {}
    std::string text() const override { return text_; }
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    nlohmann::json toJson() const override;

private:
    Connection c_;
    std::string text_ = "Disconnect nodes";
};

// Removes every connection of a node (its input and its outputs) in one step.
class DisconnectNode : public Command {
public:
    explicit DisconnectNode(NodeId node) : id_(node) {}
    std::string text() const override { return text_; }
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    nlohmann::json toJson() const override;

private:
    NodeId id_;
    std::vector<Connection> removed_;
    std::string text_ = "Disconnect node";
};

// Gives a node a name (empty: none); names label nodes in the editor and pick an Export on the
// command line (hlod build --export NAME). Nothing is rerun.
class RenameNode : public Command {
public:
    RenameNode(NodeId node, std::string name) : id_(node), name_(std::move(name)) {}
    std::string text() const override { return text_; }
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    nlohmann::json toJson() const override;

private:
    NodeId id_;
    std::string name_;
    std::optional<std::string> before_;
    std::string text_ = "Rename node";
};

// Copies `nodes` (parameters, sources, hand edits, name) with fresh ids to `positions` (one per
// node, in the order given), in one step: a connection between two copied nodes is copied, and
// a connection from outside into a copied node feeds its copy too, so "Duplicate Branch" of a
// Cluster node gives a second Cluster -> Bake -> Export variant fed by the same Import.
// Connections from a copied node to one that is not copied are not (an input takes one). A
// copied Export writes to its own folder: the original's with "-ID" appended (ID the copy's id),
// so two Exports never write one folder. `branch` only chooses the text.
class DuplicateNodes : public Command {
public:
    DuplicateNodes(std::vector<NodeId> nodes, std::vector<std::pair<double, double>> positions,
                   bool branch = false);
    std::string text() const override { return text_; }
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    nlohmann::json toJson() const override;
    // The copies' ids, parallel to the nodes given (valid after the first apply).
    const std::vector<NodeId>& copies() const { return copies_; }

    // `node` and everything downstream of it, ascending (what Duplicate Branch copies).
    static std::vector<NodeId> branchFrom(const PipelineGraph& graph, NodeId node);

private:
    std::vector<NodeId> nodes_;
    std::vector<std::pair<double, double>> positions_;
    bool branch_;
    std::vector<GraphNode> made_; // the copies, as first made (a redo repeats them)
    std::vector<Connection> wires_;
    std::vector<NodeId> copies_;
    NodeId nextBefore_ = kNoNode;
    std::string text_ = "Duplicate nodes";
};

// Moves a node in the graph view; a drag with one mergeId is one step.
class MoveNode : public Command {
public:
    MoveNode(NodeId node, double x, double y, std::uint64_t mergeId = 0);
    std::string text() const override { return "Move " + label_; }
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    std::uint64_t mergeId() const override { return mergeId_; }
    bool mergeWith(const Command& next) override;
    nlohmann::json toJson() const override;

private:
    NodeId node_;
    double x_, y_;
    std::optional<std::pair<double, double>> before_;
    std::uint64_t mergeId_;
    std::string label_ = "node";
};

// Base of the cluster hand edits: computes the new HandEdits of `clusterNode` once (edit()),
// then assigns after/before.
class HandEditCommand : public Command {
public:
    explicit HandEditCommand(NodeId clusterNode) : node_(clusterNode) {}
    // "Merge clusters (Cluster #2)": what() and the node.
    std::string text() const override {
        return what() + " (Cluster #" + std::to_string(node_) + ")";
    }
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    nlohmann::json toJson() const override;
    const HandEdits& after() const { return *after_; } // valid after the first apply

protected:
    virtual std::string what() const = 0; // "Merge clusters"
    virtual HandEdits edit(const HandEdits& current, const Document& doc) const = 0;
    virtual nlohmann::json arguments() const = 0;
    NodeId node_;

private:
    std::optional<HandEdits> before_, after_;
};

// Base of the hand edits that act on one instance set (a cluster's leaf set, or meshes): holds
// the set, normalised, and writes it as the one argument `argument` ("cluster", "instances").
class InstanceSetEdit : public HandEditCommand {
protected:
    InstanceSetEdit(NodeId clusterNode, InstanceSet set, const char* argument);
    nlohmann::json arguments() const override;
    InstanceSet set_;

private:
    const char* argument_;
};

class MergeClusters : public HandEditCommand {
public:
    MergeClusters(NodeId clusterNode, std::vector<InstanceSet> clusters);
    std::string what() const override { return "Merge clusters"; }

protected:
    HandEdits edit(const HandEdits& current, const Document& doc) const override;
    nlohmann::json arguments() const override;

private:
    std::vector<InstanceSet> clusters_;
};

// Needs the Cluster node's current tree (the graph must have run): it gives the children.
class SplitCluster : public InstanceSetEdit {
public:
    SplitCluster(NodeId clusterNode, InstanceSet cluster);
    std::string what() const override { return "Split cluster"; }

protected:
    HandEdits edit(const HandEdits& current, const Document& doc) const override;
};

class MoveToCluster : public HandEditCommand {
public:
    MoveToCluster(NodeId clusterNode, std::vector<InstanceSet> items, InstanceSet target);
    std::string what() const override { return "Move to cluster"; }

protected:
    HandEdits edit(const HandEdits& current, const Document& doc) const override;
    nlohmann::json arguments() const override;

private:
    std::vector<InstanceSet> items_;
    InstanceSet target_;
};

class LockCluster : public InstanceSetEdit {
public:
    LockCluster(NodeId clusterNode, InstanceSet cluster);
    std::string what() const override { return "Lock cluster"; }

protected:
    HandEdits edit(const HandEdits& current, const Document& doc) const override;
};

class UnlockCluster : public InstanceSetEdit {
public:
    UnlockCluster(NodeId clusterNode, InstanceSet cluster);
    std::string what() const override { return "Unlock cluster"; }

protected:
    HandEdits edit(const HandEdits& current, const Document& doc) const override;
};

class ExcludeInstance : public InstanceSetEdit {
public:
    ExcludeInstance(NodeId clusterNode, InstanceSet instances);
    std::string what() const override { return "Exclude from HLOD"; }

protected:
    HandEdits edit(const HandEdits& current, const Document& doc) const override;
};

class IncludeInstance : public InstanceSetEdit {
public:
    IncludeInstance(NodeId clusterNode, InstanceSet instances);
    std::string what() const override { return "Include in HLOD"; }

protected:
    HandEdits edit(const HandEdits& current, const Document& doc) const override;
};

} // namespace hlod
