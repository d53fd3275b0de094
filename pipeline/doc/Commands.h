// The document's edit commands (contract in Command.h): parameter edits, graph edits, source
// changes and cluster hand edits. Each stores what it changes before and after, so apply and
// revert are plain assignments and a revert restores the document exactly.
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

class AddNode : public Command {
public:
    AddNode(NodeKind kind, double x = 0.0, double y = 0.0);
    std::string text() const override;
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    nlohmann::json toJson() const override;
    NodeId node() const { return node_.id; } // valid after the first apply

private:
    GraphNode node_;
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
    std::string text() const override { return "Connect nodes"; }
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    nlohmann::json toJson() const override;

private:
    Connection c_;
};

class DisconnectNodes : public Command {
public:
    explicit DisconnectNodes(Connection c) : c_(c) {}
    std::string text() const override { return "Disconnect nodes"; }
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    nlohmann::json toJson() const override;

private:
    Connection c_;
};

// Moves a node in the graph view; a drag with one mergeId is one step.
class MoveNode : public Command {
public:
    MoveNode(NodeId node, double x, double y, std::uint64_t mergeId = 0);
    std::string text() const override { return "Move node"; }
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
};

// Base of the cluster hand edits: computes the new HandEdits of `clusterNode` once (edit()),
// then assigns after/before.
class HandEditCommand : public Command {
public:
    explicit HandEditCommand(NodeId clusterNode) : node_(clusterNode) {}
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    nlohmann::json toJson() const override;
    const HandEdits& after() const { return *after_; } // valid after the first apply

protected:
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
    std::string text() const override { return "Merge clusters"; }

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
    std::string text() const override { return "Split cluster"; }

protected:
    HandEdits edit(const HandEdits& current, const Document& doc) const override;
};

class MoveToCluster : public HandEditCommand {
public:
    MoveToCluster(NodeId clusterNode, std::vector<InstanceSet> items, InstanceSet target);
    std::string text() const override { return "Move to cluster"; }

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
    std::string text() const override { return "Lock cluster"; }

protected:
    HandEdits edit(const HandEdits& current, const Document& doc) const override;
};

class UnlockCluster : public InstanceSetEdit {
public:
    UnlockCluster(NodeId clusterNode, InstanceSet cluster);
    std::string text() const override { return "Unlock cluster"; }

protected:
    HandEdits edit(const HandEdits& current, const Document& doc) const override;
};

class ExcludeInstance : public InstanceSetEdit {
public:
    ExcludeInstance(NodeId clusterNode, InstanceSet instances);
    std::string text() const override { return "Exclude from HLOD"; }

protected:
    HandEdits edit(const HandEdits& current, const Document& doc) const override;
};

class IncludeInstance : public InstanceSetEdit {
public:
    IncludeInstance(NodeId clusterNode, InstanceSet instances);
    std::string text() const override { return "Include in HLOD"; }

protected:
    HandEdits edit(const HandEdits& current, const Document& doc) const override;
};

} // namespace hlod
