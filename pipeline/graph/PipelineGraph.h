// The pipeline graph (docs/architecture.md, "The graph runner"): nodes Import -> Cluster ->
// Bake -> Export with typed ports and connections, per-node parameters (declared in
// Parameters.h), per-node status, and incremental runs. It is the only runner: `hlod build`,
// `hlod plan`, `hlod bench` and the editor (on a worker, widgets/GraphRunner.h) all run it.
//
// Ports: Import has out "scene" (Scene); Cluster in "scene", out "clusters" (ClusterTree);
// Bake in "clusters", out "hlod" (baked proxies); Export in "hlod". An output may feed several
// inputs, an input takes one connection, port types must match and the graph stays acyclic;
// connect() refuses anything else.
// Branches: every path Import -> Cluster -> Bake -> Export is a variant of the pipeline (a
// second Cluster fed by the same Import, with its own Bake and Export, builds a second package
// from the one import). branchOf() gives a node's chain; nodesOf(Export) the packages.
// Ids: NodeId values are never reused within a graph (nextId only grows), so commands and
// project files can refer to nodes by id. Nodes are called "Bake #6" (nodeLabel), followed by
// their name when the user gave one (describeNode: "Bake #6 'coarse'").
// Incremental runs: any change of a node (parameter, sources, hand edits, input connection)
// marks it and everything downstream Pending; run() recomputes the Pending nodes upstream of its
// targets in dependency order and keeps the outputs of nodes that are UpToDate. The Bake stage
// also reuses every proxy whose content key is unchanged through the on-disk cache (ProxyBaker).
// Refusal: before anything runs, run() checks what it was asked (checkRunnable): an input that
// is not connected ("Bake #6 has no Cluster node upstream"), an Export without an output folder
// or two Exports writing one folder are refused with one line naming the node, which is marked
// Failed with that message; nothing runs.
// Failure: run() marks the failing node Failed with the error message, leaves its downstream
// Pending and rethrows the hlod::Error; a cancel puts the running node back to Pending. Edits
// throw Error(InvalidArgument) and leave the graph unchanged.
// Threads: the graph is not synchronised; run() must not overlap with edits. The editor runs a
// copy on a worker (outputs are shared and immutable, so a copy is cheap) and brings the
// outcome back node by node with adopt(), which takes it only for nodes whose definition (the
// node and everything upstream, definition()) is still the one that ran. The status and
// progress listeners are called on the thread that runs.
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

// "Import", "Cluster", "Bake", "Export" (toString(NodeKind) is the lower-case key).
const char* kindLabel(NodeKind kind);

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
    std::string name;                           // the user's name for it; empty = none
    bool operator==(const GraphNode&) const = default;
};

// "Bake #6"; describeNode adds the name when there is one: "Bake #6 'coarse'".
std::string nodeLabel(const GraphNode& node);
std::string describeNode(const GraphNode& node);

// The ids makeDefault gives its chain.
inline constexpr NodeId kDefaultImport = 1, kDefaultCluster = 2, kDefaultBake = 3,
                        kDefaultExport = 4;

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
    void setName(NodeId id, std::string name);       // marks nothing Pending

    // Queries.
    bool hasNode(NodeId id) const { return nodes_.count(id) != 0; }
    const GraphNode& node(NodeId id) const; // throws InvalidArgument for an unknown id
    std::vector<NodeId> nodeIds() const;    // ascending
    const std::vector<Connection>& connections() const { return connections_; } // sorted
    std::vector<Connection> connectionsOf(NodeId id) const;
    std::vector<NodeId> nodesOf(NodeKind kind) const; // ascending
    // The node feeding input port `port` of `id`, kNoNode when unconnected.
    NodeId upstreamOf(NodeId id, int port = 0) const;
    std::vector<NodeId> downstreamOf(NodeId id) const; // transitive, without `id`
    // The chain that feeds `id`, from its Import down to `id` itself (following input 0; it
    // stops where an input is not connected).
    std::vector<NodeId> branchOf(NodeId id) const;
    // The nearest node of `kind` upstream of `id` (or `id` itself), kNoNode when none.
    NodeId upstreamOfKind(NodeId id, NodeKind kind) const;
    NodeId nextId() const { return nextId_; }
    // Undo of addNode gives the id back; throws InvalidArgument when `next` is not above every
    // node id.
    void setNextId(NodeId next);

    // Run state.
    NodeStatus status(NodeId id) const;
    const std::string& error(NodeId id) const; // message of the last failure
    const NodeOutput* output(NodeId id) const; // last output (may be stale when Pending)
    std::shared_ptr<const NodeOutput> sharedOutput(NodeId id) const;
    void invalidate(NodeId id); // id and downstream -> Pending
    void setStatusListener(std::function<void(NodeId, NodeStatus)> listener);
    // Progress of the step that runs, with the node it belongs to (the run's own Progress gets
    // the same reports).
    void setProgressListener(std::function<void(NodeId, const ProgressInfo&)> listener);

    // Throws Error(InvalidArgument) naming the node, and marks that node Failed with the same
    // message, when the nodes `targets` need cannot run (see Refusal above).
    void checkRunnable(const std::vector<NodeId>& targets);
    // Brings `targets` (and what they need) up to date; see the contract above.
    void run(const std::vector<NodeId>& targets, const Progress& progress = {});
    void runAll(const Progress& progress = {}); // every node

    // What `id` computes from, as a canonical string: the kind, parameters, sources and hand
    // edits of `id` and of every node upstream of it, and how they are connected. Names and
    // positions are not part of it.
    std::string definition(NodeId id) const;
    // Takes the outcome of a step that ran elsewhere (a copy of this graph on a worker, the
    // editor's scene loader running the Import step) for `id`: its status, its output when not
    // null (a Running or Pending node keeps its last one), its error when Failed. Only when
    // definition(id) equals `ranDefinition`; false (and nothing changes) otherwise or when the
    // node is gone.
    bool adopt(NodeId id, const std::string& ranDefinition, NodeStatus status,
               std::shared_ptr<const NodeOutput> output, const std::string& error = {});

    // {"next_id": N, "nodes": [{"id", "kind", "name"?, "params", "sources"?, "hand_edits"?,
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
    [[noreturn]] void refuse(NodeId id, const std::string& problem);
    bool reaches(NodeId from, NodeId to) const;
    std::vector<NodeId> runOrder(const std::vector<NodeId>& targets) const;
    void runNode(NodeId id, const Progress& progress);

    std::map<NodeId, GraphNode> nodes_;
    std::map<NodeId, RunState> state_;
    std::vector<Connection> connections_;
    NodeId nextId_ = 1;
    std::function<void(NodeId, NodeStatus)> listener_;
    std::function<void(NodeId, const ProgressInfo&)> progressListener_;
};

// Runs one node's stage on its input (NodeSteps.cpp): exposed for tests.
NodeOutput runNodeStep(const GraphNode& node, const NodeOutput* input, const Progress& progress);

} // namespace hlod
