// COLLADA 1.4/1.5 node graph (Khronos COLLADA specification: <node>, <instance_node>,
// <instance_geometry>, <instance_controller>) scanned tag by tag; see DaeInstancing.h.
#include "pipeline/io/DaeInstancing.h"

#include <cstdint>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/core/Error.h"
#include "pipeline/io/InstancingGraph.h"

namespace hlod {

namespace {

struct DaeNode {
    std::string id;
    std::vector<std::size_t> children; // nested <node> elements
    std::vector<std::string> refs;     // <instance_node url="#id">, without the '#'
    std::uint64_t geometries = 0;      // <instance_geometry>, <instance_controller>
};

// The value of attribute `name` in the tag text `tag` ("node id=\"a\" name=\"b\""), or "".
std::string attribute(std::string_view tag, std::string_view name) {
    for (std::size_t at = tag.find(name); at != std::string_view::npos;
         at = tag.find(name, at + 1)) {
        const bool startsWord = at > 0 && (tag[at - 1] == ' ' || tag[at - 1] == '\t' ||
                                           tag[at - 1] == '\n' || tag[at - 1] == '\r');
        std::size_t p = at + name.size();
        while (p < tag.size() && (tag[p] == ' ' || tag[p] == '\t'))
            ++p;
        if (!startsWord || p >= tag.size() || tag[p] != '=') continue;
        ++p;
        while (p < tag.size() && (tag[p] == ' ' || tag[p] == '\t'))
            ++p;
        if (p >= tag.size() || (tag[p] != '"' && tag[p] != '\'')) continue;
        const std::size_t end = tag.find(tag[p], p + 1);
        if (end == std::string_view::npos) return {};
        return std::string(tag.substr(p + 1, end - p - 1));
    }
    return {};
}

// Nodes of the document; index 0 is a virtual root holding the top-level nodes of every
// <visual_scene> (the nodes of <library_nodes> are only reached through references).
std::vector<DaeNode> scanNodes(const std::string& text) {
    std::vector<DaeNode> nodes(1);
    std::vector<std::size_t> open; // enclosing <node>s
    bool inVisualScene = false, inLibraryNodes = false;
    for (std::size_t p = text.find('<'); p != std::string::npos; p = text.find('<', p + 1)) {
        if (text.compare(p, 4, "<!--") == 0) {
            p = text.find("-->", p);
            if (p == std::string::npos) break;
            continue;
        }
        const std::size_t end = text.find('>', p);
        if (end == std::string::npos) break;
        const std::string_view tag(text.data() + p + 1, end - p - 1);
        const bool closing = !tag.empty() && tag[0] == '/';
        const bool selfClosing = !tag.empty() && tag.back() == '/';
        std::string_view name = closing ? tag.substr(1) : tag;
        name = name.substr(0, name.find_first_of(" \t\r\n/"));
        if (name == "visual_scene") inVisualScene = !closing && !selfClosing;
        if (name == "library_nodes") inLibraryNodes = !closing && !selfClosing;
        if (name == "node") {
            if (closing) {
                if (!open.empty()) open.pop_back();
            } else {
                const std::size_t index = nodes.size();
                nodes.push_back(DaeNode{attribute(tag, "id"), {}, {}, 0});
                if (!open.empty())
                    nodes[open.back()].children.push_back(index);
                else if (inVisualScene && !inLibraryNodes)
                    nodes[0].children.push_back(index);
                if (!selfClosing) open.push_back(index);
            }
        } else if (!closing && !open.empty()) {
            if (name == "instance_node") {
                std::string url = attribute(tag, "url");
                if (!url.empty() && url[0] == '#') nodes[open.back()].refs.push_back(url.substr(1));
            } else if (name == "instance_geometry" || name == "instance_controller") {
                ++nodes[open.back()].geometries;
            }
        }
        p = end;
    }
    return nodes;
}

struct Expansion {
    std::uint64_t nodes = 0;
    std::uint64_t geometries = 0;
};

// What the visual scenes (vertex 0) expand to: nodes (each counts itself) and placed
// geometries, through nested nodes and <instance_node> references alike.
Expansion expand(std::vector<DaeNode>& nodes, const std::filesystem::path& file) {
    std::map<std::string, std::size_t> byId;
    for (std::size_t i = 1; i < nodes.size(); ++i) {
        if (!nodes[i].id.empty()) byId.emplace(nodes[i].id, i);
    }
    InstancingGraph graph;
    graph.vertices.resize(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        auto& places = graph.vertices[i].places;
        places = nodes[i].children;
        for (const std::string& r : nodes[i].refs) {
            // Unknown ids are dropped, as assimp does.
            if (auto it = byId.find(r); it != byId.end()) places.push_back(it->second);
        }
    }
    const auto name = [&](std::size_t i) {
        return "node '" + (nodes[i].id.empty() ? std::string("(unnamed)") : nodes[i].id) + "'";
    };
    Expansion e;
    for (std::size_t i = 0; i < nodes.size(); ++i)
        graph.vertices[i].own = i == 0 ? 0 : 1;
    e.nodes = expandInstancing(graph, {0}, file, name)[0];
    for (std::size_t i = 0; i < nodes.size(); ++i)
        graph.vertices[i].own = nodes[i].geometries;
    e.geometries = expandInstancing(graph, {0}, file, name)[0];
    return e;
}

} // namespace

void checkDaeInstancing(const std::filesystem::path& file, const ImportLimits& limits) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return; // the reader reports it
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.find("instance_node") == std::string::npos) return; // nothing to expand
    std::vector<DaeNode> nodes = scanNodes(text);
    const Expansion e = expand(nodes, file);
    if (e.nodes > limits.maxInstances) {
        throwOverLimit(
            file, "its <instance_node> references expand to " + std::to_string(e.nodes) + " nodes",
            limits.maxInstances, "--max-instances");
    }
    if (e.geometries > limits.maxInstances) {
        throwOverLimit(file,
                       "its <instance_node> references place " + std::to_string(e.geometries) +
                           " geometries",
                       limits.maxInstances, "--max-instances");
    }
}

} // namespace hlod
