// The pipeline graph model and its incremental run (contract in PipelineGraph.h).
#include "pipeline/graph/PipelineGraph.h"

#include <algorithm>
#include <set>

#include "pipeline/core/Error.h"

namespace hlod {

namespace {

[[noreturn]] void invalid(const std::string& what) {
    throw Error(ErrorCode::InvalidArgument, what);
}

std::string nodeName(const GraphNode& n) { return nodeLabel(n); }

} // namespace

const char* kindLabel(NodeKind kind) {
    switch (kind) {
    case NodeKind::Import:
        return "Import";
    case NodeKind::Cluster:
        return "Cluster";
    case NodeKind::Bake:
        return "Bake";
    case NodeKind::Export:
        return "Export";
    }
    return "?";
}

std::string nodeLabel(const GraphNode& node) {
    return std::string(kindLabel(node.kind)) + " #" + std::to_string(node.id);
}

std::string describeNode(const GraphNode& node) {
    return node.name.empty() ? nodeLabel(node) : nodeLabel(node) + " '" + node.name + "'";
}

const char* toString(PortType type) {
    switch (type) {
    case PortType::Scene:
        return "scene";
    case PortType::Clusters:
        return "clusters";
    case PortType::Hlod:
        return "hlod";
    }
    return "?";
}

const char* toString(NodeStatus status) {
    switch (status) {
    case NodeStatus::UpToDate:
        return "up to date";
    case NodeStatus::Pending:
        return "pending";
    case NodeStatus::Running:
        return "running";
    case NodeStatus::Failed:
        return "failed";
    }
    return "?";
}

const std::vector<Port>& inputPorts(NodeKind kind) {
    static const std::vector<Port> none;
    static const std::vector<Port> cluster{{"scene", PortType::Scene}};
    static const std::vector<Port> bake{{"clusters", PortType::Clusters}};
    static const std::vector<Port> exp{{"hlod", PortType::Hlod}};
    switch (kind) {
    case NodeKind::Import:
        return none;
    case NodeKind::Cluster:
        return cluster;
    case NodeKind::Bake:
        return bake;
    case NodeKind::Export:
        return exp;
    }
    return none;
}

const std::vector<Port>& outputPorts(NodeKind kind) {
    static const std::vector<Port> none;
    static const std::vector<Port> import{{"scene", PortType::Scene}};
    static const std::vector<Port> cluster{{"clusters", PortType::Clusters}};
    static const std::vector<Port> bake{{"hlod", PortType::Hlod}};
    switch (kind) {
    case NodeKind::Import:
        return import;
    case NodeKind::Cluster:
        return cluster;
    case NodeKind::Bake:
        return bake;
    case NodeKind::Export:
        return none;
    }
    return none;
}

PipelineGraph PipelineGraph::makeDefault(std::vector<std::filesystem::path> sources) {
    PipelineGraph g;
    const NodeId import = g.addNode(NodeKind::Import, 0.0, 0.0);
    const NodeId cluster = g.addNode(NodeKind::Cluster, 220.0, 0.0);
    const NodeId bake = g.addNode(NodeKind::Bake, 440.0, 0.0);
    const NodeId exp = g.addNode(NodeKind::Export, 660.0, 0.0);
    g.setSources(import, std::move(sources));
    g.connect({import, 0, cluster, 0});
    g.connect({cluster, 0, bake, 0});
    g.connect({bake, 0, exp, 0});
    return g;
}

NodeId PipelineGraph::addNode(NodeKind kind, double x, double y) {
    GraphNode n;
    n.id = nextId_;
    n.kind = kind;
    n.params = defaultValues(kind);
    n.x = x;
    n.y = y;
    insertNode(std::move(n));
    return nextId_ - 1;
}

void PipelineGraph::insertNode(GraphNode node) {
    if (node.id == kNoNode || hasNode(node.id))
        invalid("node id " + std::to_string(node.id) + " is already taken");
    const NodeId id = node.id;
    nodes_.emplace(id, std::move(node));
    state_[id] = RunState{};
    nextId_ = std::max(nextId_, id + 1);
}

void PipelineGraph::setNextId(NodeId next) {
    if (next == kNoNode || (!nodes_.empty() && next <= nodes_.rbegin()->first))
        invalid("next node id " + std::to_string(next) + " is taken");
    nextId_ = next;
}

void PipelineGraph::removeNode(NodeId id) {
    node(id); // throws for an unknown id
    for (NodeId d : downstreamOf(id))
        invalidate(d);
    std::erase_if(connections_, [id](const Connection& c) { return c.from == id || c.to == id; });
    nodes_.erase(id);
    state_.erase(id);
}

void PipelineGraph::connect(const Connection& c) {
    const GraphNode& from = node(c.from);
    const GraphNode& to = node(c.to);
    const auto& outs = outputPorts(from.kind);
    const auto& ins = inputPorts(to.kind);
    if (c.fromPort < 0 || c.fromPort >= static_cast<int>(outs.size()))
        invalid(nodeName(from) + " has no output port " + std::to_string(c.fromPort));
    if (c.toPort < 0 || c.toPort >= static_cast<int>(ins.size()))
        invalid(nodeName(to) + " has no input port " + std::to_string(c.toPort));
    if (outs[c.fromPort].type != ins[c.toPort].type) {
        invalid(std::string("cannot connect ") + toString(outs[c.fromPort].type) + " output of " +
                nodeName(from) + " to " + toString(ins[c.toPort].type) + " input of " +
                nodeName(to));
    }
    if (upstreamOf(c.to, c.toPort) != kNoNode)
        invalid("input '" + ins[c.toPort].name + "' of " + nodeName(to) + " is already connected");
    if (c.from == c.to || reaches(c.to, c.from))
        invalid("connecting " + nodeName(from) + " to " + nodeName(to) + " would make a cycle");
    connections_.insert(std::upper_bound(connections_.begin(), connections_.end(), c), c);
    invalidate(c.to);
}

void PipelineGraph::disconnect(const Connection& c) {
    auto it = std::find(connections_.begin(), connections_.end(), c);
    if (it == connections_.end()) invalid("no such connection");
    connections_.erase(it);
    invalidate(c.to);
}

void PipelineGraph::setParam(NodeId id, const std::string& key, const ParamValue& value) {
    GraphNode& n = mutableNode(id);
    const ParamDecl& d = parameterDeclaration(key);
    if (d.node != n.kind) invalid(nodeName(n) + " has no parameter '" + key + "'");
    ParamValue v = normalizedValue(d, value);
    if (n.params[key] == v) return;
    n.params[key] = std::move(v);
    invalidate(id);
}

void PipelineGraph::setSources(NodeId id, std::vector<std::filesystem::path> sources) {
    GraphNode& n = mutableNode(id);
    if (n.kind != NodeKind::Import) invalid(nodeName(n) + " has no sources");
    if (n.sources == sources) return;
    n.sources = std::move(sources);
    invalidate(id);
}

void PipelineGraph::setHandEdits(NodeId id, HandEdits edits) {
    GraphNode& n = mutableNode(id);
    if (n.kind != NodeKind::Cluster) invalid(nodeName(n) + " has no hand edits");
    normalize(edits);
    if (n.edits == edits) return;
    n.edits = std::move(edits);
    invalidate(id);
}

void PipelineGraph::setPosition(NodeId id, double x, double y) {
    GraphNode& n = mutableNode(id);
    n.x = x;
    n.y = y;
}

void PipelineGraph::setName(NodeId id, std::string name) { mutableNode(id).name = std::move(name); }

const GraphNode& PipelineGraph::node(NodeId id) const {
    auto it = nodes_.find(id);
    if (it == nodes_.end()) invalid("no node with id " + std::to_string(id));
    return it->second;
}

GraphNode& PipelineGraph::mutableNode(NodeId id) {
    node(id);
    return nodes_.find(id)->second;
}

std::vector<NodeId> PipelineGraph::nodeIds() const {
    std::vector<NodeId> ids;
    for (const auto& [id, n] : nodes_)
        ids.push_back(id);
    return ids;
}

std::vector<Connection> PipelineGraph::connectionsOf(NodeId id) const {
    std::vector<Connection> out;
    for (const Connection& c : connections_) {
        if (c.from == id || c.to == id) out.push_back(c);
    }
    return out;
}

std::vector<NodeId> PipelineGraph::nodesOf(NodeKind kind) const {
    std::vector<NodeId> out;
    for (const auto& [id, n] : nodes_) {
        if (n.kind == kind) out.push_back(id);
    }
    return out;
}

NodeId PipelineGraph::upstreamOf(NodeId id, int port) const {
    for (const Connection& c : connections_) {
        if (c.to == id && c.toPort == port) return c.from;
    }
    return kNoNode;
}

std::vector<NodeId> PipelineGraph::downstreamOf(NodeId id) const {
    std::set<NodeId> seen;
    std::vector<NodeId> stack{id};
    while (!stack.empty()) {
        const NodeId n = stack.back();
        stack.pop_back();
        for (const Connection& c : connections_) {
            if (c.from == n && seen.insert(c.to).second) stack.push_back(c.to);
        }
    }
    seen.erase(id);
    return {seen.begin(), seen.end()};
}

std::vector<NodeId> PipelineGraph::branchOf(NodeId id) const {
    std::vector<NodeId> chain;
    for (NodeId n = id; n != kNoNode && hasNode(n); n = upstreamOf(n)) {
        chain.push_back(n);
        if (inputPorts(node(n).kind).empty()) break;
    }
    return {chain.rbegin(), chain.rend()};
}

NodeId PipelineGraph::upstreamOfKind(NodeId id, NodeKind kind) const {
    for (NodeId n : branchOf(id)) {
        if (node(n).kind == kind) return n;
    }
    return kNoNode;
}

bool PipelineGraph::reaches(NodeId from, NodeId to) const {
    const std::vector<NodeId> d = downstreamOf(from);
    return std::find(d.begin(), d.end(), to) != d.end();
}

NodeStatus PipelineGraph::status(NodeId id) const {
    node(id);
    return state_.at(id).status;
}

const std::string& PipelineGraph::error(NodeId id) const {
    node(id);
    return state_.at(id).error;
}

const NodeOutput* PipelineGraph::output(NodeId id) const {
    auto it = state_.find(id);
    return it == state_.end() ? nullptr : it->second.output.get();
}

std::shared_ptr<const NodeOutput> PipelineGraph::sharedOutput(NodeId id) const {
    auto it = state_.find(id);
    return it == state_.end() ? nullptr : it->second.output;
}

void PipelineGraph::invalidate(NodeId id) {
    node(id);
    setStatus(id, NodeStatus::Pending);
    for (NodeId d : downstreamOf(id))
        setStatus(d, NodeStatus::Pending);
}

void PipelineGraph::setStatusListener(std::function<void(NodeId, NodeStatus)> listener) {
    listener_ = std::move(listener);
}

void PipelineGraph::setProgressListener(std::function<void(NodeId, const ProgressInfo&)> listener) {
    progressListener_ = std::move(listener);
}

void PipelineGraph::setStatus(NodeId id, NodeStatus s) {
    RunState& st = state_.at(id);
    if (st.status == s) return;
    st.status = s;
    if (s != NodeStatus::Failed) st.error.clear();
    if (listener_) listener_(id, s);
}

} // namespace hlod
