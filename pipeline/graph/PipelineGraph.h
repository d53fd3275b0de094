// The pipeline graph (DESIGN.md: "a model behind ids; it runs without any view"): nodes Import
// -> Cluster -> Bake -> Export with typed ports and connections, per-node parameters (declared
// in Parameters.h), per-node status, and incremental runs. The editor's node-graph view and
// the CLI (`hlod build`) drive the same model.
//
// Ports: Import has out "scene" (Scene); Cluster in "scene", out "clusters" (ClusterTree);
// Bake in "clusters", out "hlod" (baked proxies); Export in "hlod". An output may feed several
// inputs (e.g. two Cluster nodes compared side by side), an input takes one connection, port
// types must match and the graph stays acyclic; connect() refuses anything else.
// Ids: NodeId values are never reused within a graph (nextId only grows), so commands and
// project files can refer to nodes by id.
// Incremental runs: any change of a node (parameter, sources, hand edits, input connection)
// marks it and everything downstream Pending; run() recomputes the Pending nodes upstream of its
// targets in dependency order and keeps the outputs of nodes that are UpToDate. The Bake stage
// also reuses every proxy whose content key is unchanged through the on-disk cache (ProxyBaker).
// Failure: run() marks the failing node Failed with the error message, leaves its downstream
// Pending and rethrows the hlod::Error; a cancel puts the running node back to Pending. Edits
// throw Error(InvalidArgument) and leave the graph unchanged.
// Threads: the graph is not synchronised; run() must not overlap with edits (the editor runs
// it on a copy or blocks edits while it runs). The status listener is called on the thread
// that runs.
#pragma once

#include <compare>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "pipeline/graph/ExportStep.h"
#include "pipeline/graph/HandEdits.h"
#include "pipeline/graph/Parameters.h"

namespace hlod {

using NodeId = std::uint32_t;
inline constexpr NodeId kNoNode = 0xffffffffu;

enum class PortType { Scene, Clusters, Hlod };
const char* toString(PortType type);

struct Port {
    std::string name;
    PortType type;
};
const std::vector<Port>& inputPorts(NodeKind kind);
const std::vector<Port>& outputPorts(NodeKind kind);

enum class NodeStatus { UpToDate, Pending, Running, Failed };
const char* toString(NodeStatus status);

struct Connection {
    NodeId from = kNoNode;
    int fromPort = 0; // index into outputPorts(kind of `from`)
    NodeId to = kNoNode;
    int toPort = 0; // index into inputPorts(kind of `to`)
    auto operator<=>(const Connection&) const = default;
};

// The model state of one node (what a project file stores).
struct GraphNode {
    NodeId id = kNoNode;
    NodeKind kind = NodeKind::Import;
    ParamValues params;                         // every declared key of `kind`
    std::vector<std::filesystem::path> sources; // Import: scene files; empty = sample scene
    HandEdits edits;                            // Cluster: hand edits
    double x = 0.0, y = 0.0;                    // position in the node-graph view
    bool operator==(const GraphNode&) const = default;
};

// What a node produced; each stage adds its part to its input's output (shared, immutable).
struct NodeOutput {
    std::shared_ptr<const Scene> scene;
    std::vector<std::string> inputs; // source paths as given, or {"sample:plant"}
    std::shared_ptr<const ClusterTree> tree;
    ClusterParams cluster; // with the hand-edit constraints applied
    HandEdits edits;
    double clusterSeconds = 0.0;
    std::shared_ptr<const BakeResult> bake;
    BakeParams bakeParams;
    std::shared_ptr<const ExportResult> exported;
};

class PipelineGraph {
public:
    // Import -> Cluster -> Bake -> Export (ids 1..4), laid out left to right.
    static PipelineGraph makeDefault(std::vector<std::filesystem::path> sources = {});

    // Model edits (each marks what it touches Pending).
    NodeId addNode(NodeKind kind, double x = 0.0, double y = 0.0);
    void insertNode(GraphNode node); // restores a removed node with its id (must be free)
    void removeNode(NodeId id);      // and its connections
    void connect(const Connection& c);
    void disconnect(const Connection& c);
    void setParam(NodeId id, const std::string& key, const ParamValue& value);
    void setSources(NodeId id, std::vector<std::filesystem::path> sources);
    void setHandEdits(NodeId id, HandEdits edits);
    void setPosition(NodeId id, double x, double y); // view state: marks nothing Pending

    // Queries.
    bool hasNode(NodeId id) const { return nodes_.count(id) != 0; }
    const GraphNode& node(NodeId id) const; // throws InvalidArgument for an unknown id
    std::vector<NodeId> nodeIds() const;    // ascending
    const std::vector<Connection>& connections() const { return connections_; } // sorted
    std::vector<Connection> connectionsOf(NodeId id) const;
    NodeId firstOf(NodeKind kind) const; // lowest id of that kind, kNoNode when none
    // The node feeding input port `port` of `id`, kNoNode when unconnected.
    NodeId upstreamOf(NodeId id, int port = 0) const;
    std::vector<NodeId> downstreamOf(NodeId id) const; // transitive, without `id`
    NodeId nextId() const { return nextId_; }
    // Undo of addNode gives the id back; throws InvalidArgument when `next` is not above every
    // node id.
    void setNextId(NodeId next);

    // Run state.
    NodeStatus status(NodeId id) const;
    const std::string& error(NodeId id) const; // message of the last failure
    const NodeOutput* output(NodeId id) const; // last output (may be stale when Pending)
    void invalidate(NodeId id);                // id and downstream -> Pending
    void setStatusListener(std::function<void(NodeId, NodeStatus)> listener);

    // Brings `targets` (and what they need) up to date; see the contract above.
    void run(const std::vector<NodeId>& targets, const Progress& progress = {});
    void runAll(const Progress& progress = {}); // every node

    // {"next_id": N, "nodes": [{"id", "kind", "params", "sources"?, "hand_edits"?,
    // "position"}], "connections": [{"from", "from_port", "to", "to_port"}]} (ports by name).
    // Reading validates everything (kinds, parameters, port names, types, cycles) and throws
    // Malformed naming `file` (InvalidArgument when `file` is empty).
    nlohmann::json toJson() const;
    static PipelineGraph fromJson(const nlohmann::json& j, const std::filesystem::path& file = {});

private:
    struct RunState {
        NodeStatus status = NodeStatus::Pending;
        std::string error;
        std::shared_ptr<const NodeOutput> output;
    };
    GraphNode& mutableNode(NodeId id);
    void setStatus(NodeId id, NodeStatus s);
    bool reaches(NodeId from, NodeId to) const;
    std::vector<NodeId> runOrder(const std::vector<NodeId>& targets) const;
    void runNode(NodeId id, const Progress& progress);

    std::map<NodeId, GraphNode> nodes_;
    std::map<NodeId, RunState> state_;
    std::vector<Connection> connections_;
    NodeId nextId_ = 1;
    std::function<void(NodeId, NodeStatus)> listener_;
};

// Runs one node's stage on its input (NodeSteps.cpp): exposed for tests.
NodeOutput runNodeStep(const GraphNode& node, const NodeOutput* input, const Progress& progress);

} // namespace hlod
