// The pipeline graph's run (contract in PipelineGraph.h): the order of the steps, the checks that
// refuse a graph before anything runs, the run itself with per-node progress, and the
// definitions that let a run made on a copy come back into the graph (adopt).
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "pipeline/core/Error.h"
#include "pipeline/graph/PipelineGraph.h"

namespace hlod {

namespace {

// The kind of node whose output an input of type `type` takes.
NodeKind feederOf(PortType type) {
    switch (type) {
    case PortType::Scene:
        return NodeKind::Import;
    case PortType::Clusters:
        return NodeKind::Cluster;
    case PortType::Hlod:
        return NodeKind::Bake;
    }
    return NodeKind::Import;
}

// A folder as the file system sees it, so "out", "./out/" and "/abs/out" compare equal.
std::filesystem::path folderKey(const std::filesystem::path& folder) {
    std::error_code ec;
    std::filesystem::path p = std::filesystem::absolute(folder, ec).lexically_normal();
    if (p.has_filename()) return p;
    return p.parent_path(); // "out/" -> "out"
}

} // namespace

std::vector<NodeId> PipelineGraph::runOrder(const std::vector<NodeId>& targets) const {
    // Depth-first post-order over the upstream closure: inputs before the nodes they feed.
    std::vector<NodeId> order;
    std::set<NodeId> done;
    std::vector<std::pair<NodeId, bool>> stack;
    for (auto it = targets.rbegin(); it != targets.rend(); ++it)
        stack.push_back({*it, false});
    while (!stack.empty()) {
        auto [id, expanded] = stack.back();
        stack.pop_back();
        if (done.count(id)) continue;
        if (expanded) {
            done.insert(id);
            order.push_back(id);
            continue;
        }
        stack.push_back({id, true});
        const GraphNode& n = node(id);
        for (int p = static_cast<int>(inputPorts(n.kind).size()) - 1; p >= 0; --p) {
            const NodeId up = upstreamOf(id, p);
            if (up != kNoNode && !done.count(up)) stack.push_back({up, false});
        }
    }
    return order;
}

void PipelineGraph::refuse(NodeId id, const std::string& problem) {
    state_.at(id).error = problem; // before the status, so a listener reads the message
    setStatus(id, NodeStatus::Failed);
    throw Error(ErrorCode::InvalidArgument, problem);
}

void PipelineGraph::checkRunnable(const std::vector<NodeId>& targets) {
    for (NodeId id : targets)
        node(id); // an unknown id throws
    const std::vector<NodeId> order = runOrder(targets);
    std::map<std::filesystem::path, NodeId> folders;
    for (NodeId id : order) {
        const GraphNode& n = node(id);
        const auto& ins = inputPorts(n.kind);
        for (int p = 0; p < static_cast<int>(ins.size()); ++p) {
            if (upstreamOf(id, p) != kNoNode) continue;
            const char* feeder = kindLabel(feederOf(ins[p].type));
            refuse(id, describeNode(n) + " has no " + feeder + " node upstream: connect a " +
                           feeder + " node's " + toString(ins[p].type) + " output to its input");
        }
        if (n.kind != NodeKind::Export) continue;
        const std::string out = paramText(n.params, "output");
        if (out.empty()) {
            refuse(id, describeNode(n) +
                           " has no output folder (set its Output folder, or -o DIR on the "
                           "command line)");
        }
        const auto [it, fresh] = folders.emplace(folderKey(out), id);
        if (!fresh) {
            refuse(id, describeNode(n) + " writes the same folder as " +
                           describeNode(node(it->second)) + " (" + it->first.string() +
                           "): give one of them another output folder");
        }
    }
}

void PipelineGraph::runNode(NodeId id, const Progress& progress) {
    const GraphNode& n = node(id);
    const NodeOutput* input = inputPorts(n.kind).empty() ? nullptr : output(upstreamOf(id, 0));
    Progress step = progress;
    if (progressListener_) {
        step.report = [this, id, &progress](const ProgressInfo& info) {
            progress.emit(info);
            progressListener_(id, info);
        };
    }
    setStatus(id, NodeStatus::Running);
    auto out = std::make_shared<const NodeOutput>(runNodeStep(n, input, step));
    state_.at(id).output = std::move(out);
    setStatus(id, NodeStatus::UpToDate);
}

void PipelineGraph::run(const std::vector<NodeId>& targets, const Progress& progress) {
    checkRunnable(targets);
    for (NodeId id : runOrder(targets)) {
        RunState& st = state_.at(id);
        if (st.status == NodeStatus::UpToDate && st.output) continue;
        try {
            runNode(id, progress);
        } catch (const Error& e) {
            if (e.code() == ErrorCode::Cancelled) {
                setStatus(id, NodeStatus::Pending);
            } else {
                state_.at(id).error = e.what();
                setStatus(id, NodeStatus::Failed);
            }
            throw;
        } catch (const std::exception& e) {
            state_.at(id).error = e.what();
            setStatus(id, NodeStatus::Failed);
            throw;
        }
    }
}

void PipelineGraph::runAll(const Progress& progress) { run(nodeIds(), progress); }

std::string PipelineGraph::definition(NodeId id) const {
    const std::vector<NodeId> closure = runOrder({id});
    nlohmann::json nodes = nlohmann::json::array();
    nlohmann::json wires = nlohmann::json::array();
    for (NodeId n : closure) {
        const GraphNode& g = node(n);
        nlohmann::json sources = nlohmann::json::array();
        for (const auto& s : g.sources)
            sources.push_back(s.generic_string());
        nodes.push_back({n, toString(g.kind), paramsToJson(g.kind, g.params), sources,
                         handEditsToJson(g.edits)});
        for (int p = 0; p < static_cast<int>(inputPorts(g.kind).size()); ++p)
            wires.push_back({upstreamOf(n, p), n, p});
    }
    return nlohmann::json{nodes, wires}.dump();
}

bool PipelineGraph::adopt(NodeId id, const std::string& ranDefinition, NodeStatus status,
                          std::shared_ptr<const NodeOutput> output, const std::string& error) {
    if (!hasNode(id) || definition(id) != ranDefinition) return false;
    RunState& st = state_.at(id);
    if (output) st.output = std::move(output);
    if (status == NodeStatus::Failed) st.error = error;
    setStatus(id, status);
    return true;
}

} // namespace hlod
