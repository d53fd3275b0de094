// The pipeline graph as JSON (format in PipelineGraph.h): written by the document and project
// files, read back with every field validated.
#include <nlohmann/json.hpp>

#include "pipeline/core/Error.h"
#include "pipeline/graph/PipelineGraph.h"

namespace hlod {

namespace {

int portIndex(const std::vector<Port>& ports, const std::string& name) {
    for (std::size_t i = 0; i < ports.size(); ++i) {
        if (ports[i].name == name) return static_cast<int>(i);
    }
    return -1;
}

struct Reader {
    const std::filesystem::path& file;

    [[noreturn]] void fail(const std::string& what) const {
        if (file.empty()) throw Error(ErrorCode::InvalidArgument, what);
        throw Error(ErrorCode::Malformed, file, what);
    }
    const nlohmann::json& at(const nlohmann::json& j, const char* key,
                             const std::string& where) const {
        if (!j.is_object() || !j.contains(key)) fail(where + ": missing key '" + key + "'");
        return j[key];
    }
    NodeId id(const nlohmann::json& j, const char* key, const std::string& where) const {
        const nlohmann::json& v = at(j, key, where);
        if (!v.is_number_unsigned() || v.get<unsigned long long>() >= kNoNode)
            fail(where + "." + key + " must be a node id");
        return v.get<NodeId>();
    }

    GraphNode node(const nlohmann::json& j, std::size_t index) const {
        const std::string where = "graph.nodes[" + std::to_string(index) + "]";
        GraphNode n;
        n.id = id(j, "id", where);
        const nlohmann::json& kind = at(j, "kind", where);
        if (!kind.is_string()) fail(where + ".kind must be a string");
        try {
            n.kind = nodeKindFromString(kind.get<std::string>());
        } catch (const Error& e) {
            fail(where + ": " + e.problem());
        }
        n.params = paramsFromJson(n.kind, j.value("params", nlohmann::json::object()), file);
        if (j.contains("sources")) {
            if (!j["sources"].is_array()) fail(where + ".sources must be an array of paths");
            for (const auto& s : j["sources"]) {
                if (!s.is_string()) fail(where + ".sources must be an array of paths");
                n.sources.emplace_back(s.get<std::string>());
            }
        }
        if (j.contains("hand_edits")) n.edits = handEditsFromJson(j["hand_edits"], file);
        if (j.contains("name")) {
            if (!j["name"].is_string()) fail(where + ".name must be a string");
            n.name = j["name"].get<std::string>();
        }
        if (j.contains("position")) {
            const auto& p = j["position"];
            if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
                fail(where + ".position must be [x, y]");
            n.x = p[0].get<double>();
            n.y = p[1].get<double>();
        }
        return n;
    }

    Connection connection(const PipelineGraph& g, const nlohmann::json& j,
                          std::size_t index) const {
        const std::string where = "graph.connections[" + std::to_string(index) + "]";
        Connection c;
        c.from = id(j, "from", where);
        c.to = id(j, "to", where);
        if (!g.hasNode(c.from) || !g.hasNode(c.to))
            fail(where + " names a node that does not exist");
        const nlohmann::json& fp = at(j, "from_port", where);
        const nlohmann::json& tp = at(j, "to_port", where);
        if (!fp.is_string() || !tp.is_string()) fail(where + ": ports are named by strings");
        c.fromPort = portIndex(outputPorts(g.node(c.from).kind), fp.get<std::string>());
        c.toPort = portIndex(inputPorts(g.node(c.to).kind), tp.get<std::string>());
        if (c.fromPort < 0 || c.toPort < 0) fail(where + " names a port the node does not have");
        return c;
    }
};

} // namespace

nlohmann::json PipelineGraph::toJson() const {
    nlohmann::json nodes = nlohmann::json::array();
    for (const auto& [id, n] : nodes_) {
        nlohmann::json j = {{"id", id},
                            {"kind", toString(n.kind)},
                            {"params", paramsToJson(n.kind, n.params)},
                            {"position", {n.x, n.y}}};
        if (!n.name.empty()) j["name"] = n.name;
        if (n.kind == NodeKind::Import) {
            nlohmann::json sources = nlohmann::json::array();
            for (const auto& s : n.sources)
                sources.push_back(s.generic_string());
            j["sources"] = std::move(sources);
        }
        if (n.kind == NodeKind::Cluster) j["hand_edits"] = handEditsToJson(n.edits);
        nodes.push_back(std::move(j));
    }
    nlohmann::json connections = nlohmann::json::array();
    for (const Connection& c : connections_) {
        connections.push_back({{"from", c.from},
                               {"from_port", outputPorts(node(c.from).kind)[c.fromPort].name},
                               {"to", c.to},
                               {"to_port", inputPorts(node(c.to).kind)[c.toPort].name}});
    }
    return {{"next_id", nextId_}, {"nodes", std::move(nodes)}, {"connections", connections}};
}

PipelineGraph PipelineGraph::fromJson(const nlohmann::json& j, const std::filesystem::path& file) {
    const Reader r{file};
    if (!j.is_object()) r.fail("graph must be an object");
    PipelineGraph g;
    const nlohmann::json& nodes = r.at(j, "nodes", "graph");
    if (!nodes.is_array()) r.fail("graph.nodes must be an array");
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        GraphNode n = r.node(nodes[i], i);
        if (g.hasNode(n.id)) r.fail("graph.nodes: node id " + std::to_string(n.id) + " twice");
        g.insertNode(std::move(n));
    }
    if (j.contains("next_id")) {
        const NodeId next = r.id(j, "next_id", "graph");
        if (next < g.nextId_) r.fail("graph.next_id is smaller than a node id");
        g.nextId_ = next;
    }
    const nlohmann::json& conns = j.value("connections", nlohmann::json::array());
    if (!conns.is_array()) r.fail("graph.connections must be an array");
    for (std::size_t i = 0; i < conns.size(); ++i) {
        const Connection c = r.connection(g, conns[i], i);
        try {
            g.connect(c);
        } catch (const Error& e) {
            r.fail("graph.connections[" + std::to_string(i) + "]: " + e.problem());
        }
    }
    return g;
}

} // namespace hlod
