// Duplicate and Duplicate Branch (contract in Commands.h, DuplicateNodes): copies of nodes with
// fresh ids, the connections into them reproduced, so a copied chain is a new branch.
#include <algorithm>
#include <map>

#include "pipeline/core/Error.h"
#include "pipeline/doc/Commands.h"
#include "pipeline/doc/Document.h"

namespace hlod {

namespace {

// The copy of an Export writes next to the original: "pkg" -> "pkg-7".
std::string copiedOutput(std::string folder, NodeId copy) {
    while (folder.size() > 1 && folder.back() == '/')
        folder.pop_back();
    return folder.empty() ? folder : folder + "-" + std::to_string(copy);
}

} // namespace

DuplicateNodes::DuplicateNodes(std::vector<NodeId> nodes,
                               std::vector<std::pair<double, double>> positions, bool branch)
    : nodes_(std::move(nodes)), positions_(std::move(positions)), branch_(branch) {}

std::vector<NodeId> DuplicateNodes::branchFrom(const PipelineGraph& graph, NodeId node) {
    std::vector<NodeId> out = graph.downstreamOf(node);
    out.push_back(node);
    std::sort(out.begin(), out.end());
    return out;
}

void DuplicateNodes::apply(Document& doc) {
    PipelineGraph& g = doc.graph();
    const NodeId next = g.nextId();
    if (made_.empty()) {
        if (nodes_.empty() || nodes_.size() != positions_.size())
            throw Error(ErrorCode::InvalidArgument, "nothing to duplicate");
        std::map<NodeId, NodeId> copyOf;
        NodeId id = next;
        for (std::size_t i = 0; i < nodes_.size(); ++i) {
            GraphNode c = g.node(nodes_[i]); // throws for an unknown node
            c.id = id++;
            c.x = positions_[i].first;
            c.y = positions_[i].second;
            if (!c.name.empty()) c.name += " copy";
            if (c.kind == NodeKind::Export)
                c.params["output"] = copiedOutput(paramText(c.params, "output"), c.id);
            copyOf[nodes_[i]] = c.id;
            made_.push_back(std::move(c));
        }
        for (const Connection& w : g.connections()) {
            const auto to = copyOf.find(w.to);
            if (to == copyOf.end()) continue;
            Connection c = w;
            c.to = to->second;
            if (const auto from = copyOf.find(w.from); from != copyOf.end()) c.from = from->second;
            wires_.push_back(c);
        }
        const std::string first = nodeLabel(g.node(nodes_.front()));
        text_ = branch_ ? "Duplicate the branch of " + first + " (" +
                              std::to_string(nodes_.size()) + " nodes)"
                        : "Duplicate " + first;
    }
    copies_.clear();
    for (const GraphNode& c : made_) {
        g.insertNode(c);
        copies_.push_back(c.id);
    }
    try {
        for (const Connection& w : wires_)
            g.connect(w);
    } catch (...) {
        for (NodeId c : copies_)
            g.removeNode(c);
        g.setNextId(next);
        throw;
    }
    nextBefore_ = next;
}

void DuplicateNodes::revert(Document& doc) {
    for (NodeId c : copies_)
        doc.graph().removeNode(c);
    doc.graph().setNextId(nextBefore_);
}

nlohmann::json DuplicateNodes::toJson() const {
    return {{"command", branch_ ? "duplicate_branch" : "duplicate"},
            {"nodes", nodes_},
            {"copies", copies_}};
}

} // namespace hlod
