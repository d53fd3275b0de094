// The document's edit commands (see Commands.h).
#include "pipeline/doc/Commands.h"

#include "pipeline/core/Error.h"
#include "pipeline/doc/Document.h"
#include "pipeline/graph/ClusterEdits.h"

namespace hlod {

namespace {

nlohmann::json valueJson(const ParamValue& v) {
    nlohmann::json j;
    std::visit([&](const auto& x) { j = x; }, v);
    return j;
}

nlohmann::json connectionJson(const Connection& c) {
    return {{"from", c.from}, {"from_port", c.fromPort}, {"to", c.to}, {"to_port", c.toPort}};
}

} // namespace

// --- SetParameter ---------------------------------------------------------------------------

SetParameter::SetParameter(NodeId node, std::string key, ParamValue value, std::uint64_t mergeId)
    : node_(node), key_(std::move(key)), value_(std::move(value)), mergeId_(mergeId) {}

std::string SetParameter::text() const {
    const ParamDecl* d = findParameter(key_);
    if (!d) return "Set " + key_;
    return "Set " + d->label + " of " + kindLabel(d->node) + " #" + std::to_string(node_);
}

void SetParameter::apply(Document& doc) {
    const GraphNode& n = doc.graph().node(node_);
    const ParamValue before = n.params.count(key_) ? n.params.at(key_) : ParamValue{};
    doc.graph().setParam(node_, key_, value_); // validates; throws before anything changes
    if (!before_) before_ = before;
}

void SetParameter::revert(Document& doc) { doc.graph().setParam(node_, key_, *before_); }

bool SetParameter::mergeWith(const Command& next) {
    const auto* o = dynamic_cast<const SetParameter*>(&next);
    if (!o || o->node_ != node_ || o->key_ != key_) return false;
    value_ = o->value_;
    return true;
}

nlohmann::json SetParameter::toJson() const {
    return {{"command", "set_parameter"},
            {"node", node_},
            {"key", key_},
            {"value", valueJson(value_)},
            {"before", before_ ? valueJson(*before_) : nlohmann::json()}};
}

// --- SetSources -----------------------------------------------------------------------------

SetSources::SetSources(NodeId importNode, std::vector<std::filesystem::path> sources)
    : node_(importNode), after_(std::move(sources)) {}

void SetSources::apply(Document& doc) {
    const auto before = doc.graph().node(node_).sources;
    doc.graph().setSources(node_, after_);
    before_ = before;
}

void SetSources::revert(Document& doc) { doc.graph().setSources(node_, before_); }

nlohmann::json SetSources::toJson() const {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& p : after_)
        a.push_back(p.generic_string());
    return {{"command", "set_sources"}, {"node", node_}, {"sources", a}};
}

// --- AddNode / RemoveNode -------------------------------------------------------------------

AddNode::AddNode(NodeKind kind, double x, double y, NodeId input) : input_(input) {
    node_.kind = kind;
    node_.params = defaultValues(kind);
    node_.x = x;
    node_.y = y;
}

std::string AddNode::text() const {
    if (node_.id == kNoNode) return std::string("Add ") + kindLabel(node_.kind) + " node";
    return "Add " + nodeLabel(node_);
}

void AddNode::apply(Document& doc) {
    PipelineGraph& g = doc.graph();
    const NodeId next = g.nextId();
    if (node_.id == kNoNode) node_.id = next; // a redo reuses the first id
    g.insertNode(node_);
    if (input_ != kNoNode) {
        try {
            g.connect({input_, 0, node_.id, 0});
        } catch (...) {
            g.removeNode(node_.id);
            g.setNextId(next);
            throw;
        }
    }
    nextBefore_ = next;
}

void AddNode::revert(Document& doc) {
    doc.graph().removeNode(node_.id);
    doc.graph().setNextId(nextBefore_);
}

nlohmann::json AddNode::toJson() const {
    nlohmann::json j = {
        {"command", "add_node"}, {"kind", toString(node_.kind)}, {"node", node_.id}};
    if (input_ != kNoNode) j["input"] = input_;
    return j;
}

std::string RemoveNode::text() const {
    return removed_ ? "Remove " + nodeLabel(*removed_) : "Remove node " + std::to_string(id_);
}

void RemoveNode::apply(Document& doc) {
    GraphNode n = doc.graph().node(id_);
    connections_ = doc.graph().connectionsOf(id_);
    doc.graph().removeNode(id_);
    removed_ = std::move(n);
}

void RemoveNode::revert(Document& doc) {
    doc.graph().insertNode(*removed_);
    for (const Connection& c : connections_)
        doc.graph().connect(c);
}

nlohmann::json RemoveNode::toJson() const { return {{"command", "remove_node"}, {"node", id_}}; }

// --- Connections, names and positions -------------------------------------------------------

namespace {

std::string wireText(const PipelineGraph& g, const Connection& c, const char* verb,
                     const char* between) {
    return std::string(verb) + " " + nodeLabel(g.node(c.from)) + " " + between + " " +
           nodeLabel(g.node(c.to));
}

} // namespace

void ConnectNodes::apply(Document& doc) {
    doc.graph().connect(c_);
    text_ = wireText(doc.graph(), c_, "Connect", "to");
}
void ConnectNodes::revert(Document& doc) { doc.graph().disconnect(c_); }
nlohmann::json ConnectNodes::toJson() const {
    return {{"command", "connect"}, {"connection", connectionJson(c_)}};
}

void DisconnectNodes::apply(Document& doc) {
    doc.graph().disconnect(c_);
    text_ = wireText(doc.graph(), c_, "Disconnect", "from");
}
void DisconnectNodes::revert(Document& doc) { doc.graph().connect(c_); }
nlohmann::json DisconnectNodes::toJson() const {
    return {{"command", "disconnect"}, {"connection", connectionJson(c_)}};
}

void DisconnectNode::apply(Document& doc) {
    PipelineGraph& g = doc.graph();
    const std::vector<Connection> wires = g.connectionsOf(id_);
    if (wires.empty())
        throw Error(ErrorCode::InvalidArgument, nodeLabel(g.node(id_)) + " has no connections");
    for (const Connection& c : wires)
        g.disconnect(c);
    removed_ = wires;
    text_ = "Disconnect " + nodeLabel(g.node(id_));
}

void DisconnectNode::revert(Document& doc) {
    for (const Connection& c : removed_)
        doc.graph().connect(c);
}

nlohmann::json DisconnectNode::toJson() const {
    return {{"command", "disconnect_node"}, {"node", id_}};
}

void RenameNode::apply(Document& doc) {
    const GraphNode& n = doc.graph().node(id_);
    const std::string before = n.name;
    text_ = name_.empty() ? "Clear the name of " + nodeLabel(n)
                          : "Rename " + nodeLabel(n) + " to '" + name_ + "'";
    doc.graph().setName(id_, name_);
    before_ = before;
}

void RenameNode::revert(Document& doc) { doc.graph().setName(id_, *before_); }

nlohmann::json RenameNode::toJson() const {
    return {{"command", "rename_node"}, {"node", id_}, {"name", name_}};
}

MoveNode::MoveNode(NodeId node, double x, double y, std::uint64_t mergeId)
    : node_(node), x_(x), y_(y), mergeId_(mergeId) {}

void MoveNode::apply(Document& doc) {
    const GraphNode& n = doc.graph().node(node_);
    const std::pair<double, double> before{n.x, n.y};
    label_ = nodeLabel(n);
    doc.graph().setPosition(node_, x_, y_);
    if (!before_) before_ = before;
}

void MoveNode::revert(Document& doc) {
    doc.graph().setPosition(node_, before_->first, before_->second);
}

bool MoveNode::mergeWith(const Command& next) {
    const auto* o = dynamic_cast<const MoveNode*>(&next);
    if (!o || o->node_ != node_) return false;
    x_ = o->x_;
    y_ = o->y_;
    return true;
}

nlohmann::json MoveNode::toJson() const {
    return {{"command", "move_node"}, {"node", node_}, {"position", {x_, y_}}};
}

// --- Cluster hand edits ---------------------------------------------------------------------

void HandEditCommand::apply(Document& doc) {
    const HandEdits current = doc.graph().node(node_).edits;
    if (!after_) {
        HandEdits next = edit(current, doc);
        // Check against the scene the node clustered last, so a bad id fails now, not at run.
        if (const NodeOutput* out = doc.graph().output(node_); out && out->scene)
            validateHandEdits(next, out->scene->instances.size());
        after_ = std::move(next);
    }
    doc.graph().setHandEdits(node_, *after_);
    before_ = current;
}

void HandEditCommand::revert(Document& doc) { doc.graph().setHandEdits(node_, *before_); }

nlohmann::json HandEditCommand::toJson() const {
    nlohmann::json j = {{"command", what()}, {"node", node_}, {"arguments", arguments()}};
    if (after_) j["after"] = handEditsToJson(*after_);
    return j;
}

InstanceSetEdit::InstanceSetEdit(NodeId n, InstanceSet set, const char* argument)
    : HandEditCommand(n), set_(normalizedSet(std::move(set))), argument_(argument) {}
nlohmann::json InstanceSetEdit::arguments() const { return {{argument_, set_}}; }

MergeClusters::MergeClusters(NodeId n, std::vector<InstanceSet> clusters)
    : HandEditCommand(n), clusters_(std::move(clusters)) {}
HandEdits MergeClusters::edit(const HandEdits& e, const Document&) const {
    return mergeClusters(e, clusters_);
}
nlohmann::json MergeClusters::arguments() const { return {{"clusters", clusters_}}; }

SplitCluster::SplitCluster(NodeId n, InstanceSet cluster)
    : InstanceSetEdit(n, std::move(cluster), "cluster") {}
HandEdits SplitCluster::edit(const HandEdits& e, const Document& doc) const {
    const ClusterTree* tree = doc.currentTree(node_);
    if (!tree) throw Error(ErrorCode::InvalidArgument, "run clustering before splitting a cluster");
    return splitCluster(e, *tree, set_);
}

MoveToCluster::MoveToCluster(NodeId n, std::vector<InstanceSet> items, InstanceSet target)
    : HandEditCommand(n), items_(std::move(items)), target_(normalizedSet(std::move(target))) {}
HandEdits MoveToCluster::edit(const HandEdits& e, const Document&) const {
    return moveToCluster(e, items_, target_);
}
nlohmann::json MoveToCluster::arguments() const { return {{"items", items_}, {"target", target_}}; }

LockCluster::LockCluster(NodeId n, InstanceSet cluster)
    : InstanceSetEdit(n, std::move(cluster), "cluster") {}
HandEdits LockCluster::edit(const HandEdits& e, const Document&) const {
    return lockCluster(e, set_);
}

UnlockCluster::UnlockCluster(NodeId n, InstanceSet cluster)
    : InstanceSetEdit(n, std::move(cluster), "cluster") {}
HandEdits UnlockCluster::edit(const HandEdits& e, const Document&) const {
    return unlockCluster(e, set_);
}

ExcludeInstance::ExcludeInstance(NodeId n, InstanceSet instances)
    : InstanceSetEdit(n, std::move(instances), "instances") {}
HandEdits ExcludeInstance::edit(const HandEdits& e, const Document&) const {
    return excludeInstances(e, set_);
}

IncludeInstance::IncludeInstance(NodeId n, InstanceSet instances)
    : InstanceSetEdit(n, std::move(instances), "instances") {}
HandEdits IncludeInstance::edit(const HandEdits& e, const Document&) const {
    return includeInstances(e, set_);
}

} // namespace hlod
