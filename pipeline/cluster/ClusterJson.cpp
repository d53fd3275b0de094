// Cluster tree -> JSON (schema in ClusterJson.h).
#include "pipeline/cluster/ClusterJson.h"

#include <array>
#include <cmath>

namespace hlod {

namespace {

nlohmann::json vec(const glm::dvec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

nlohmann::json idOrNull(Id id) {
    return id == kNoId ? nlohmann::json(nullptr) : nlohmann::json(id);
}

// Text the way nlohmann's serializer writes it with an indent of 2 (serializer.hpp: objects
// and arrays one member a line, keys in std::map order, "[]" for an empty array).
class Writer {
public:
    explicit Writer(std::string& out) : out_(out) {}

    void indent(int depth) { out_.append(static_cast<std::size_t>(2 * depth), ' '); }
    void key(int depth, const char* k) {
        indent(depth);
        out_ += '"';
        out_ += k;
        out_ += "\": ";
    }
    void number(double x) {
        if (!std::isfinite(x)) {
            out_ += "null";
            return;
        }
        std::array<char, 64> buf{};
        char* end = nlohmann::detail::to_chars(buf.data(), buf.data() + buf.size(), x);
        out_.append(buf.data(), end);
    }
    void integer(long long v) { out_ += std::to_string(v); }
    void id(Id v) {
        if (v == kNoId)
            out_ += "null";
        else
            integer(v);
    }
    void vec(int depth, const glm::dvec3& v) {
        out_ += "[\n";
        for (int k = 0; k < 3; ++k) {
            indent(depth + 1);
            number(v[k]);
            out_ += k < 2 ? ",\n" : "\n";
        }
        indent(depth);
        out_ += ']';
    }
    void text(const char* s) { out_ += s; }

private:
    std::string& out_;
};

// One node object at `depth` (its members at depth + 1), keys in sorted order as std::map
// holds them: box, children, cost, fill, id, instance, level, locked, parent, sphere.
void appendNode(Writer& w, const ClusterNode& n, std::size_t i, int depth) {
    const int d = depth + 1;
    w.text("{\n");
    w.key(d, "box");
    w.text("{\n");
    w.key(d + 1, "max");
    w.vec(d + 1, n.box.max);
    w.text(",\n");
    w.key(d + 1, "min");
    w.vec(d + 1, n.box.min);
    w.text("\n");
    w.indent(d);
    w.text("},\n");
    w.key(d, "children");
    if (n.children.empty()) {
        w.text("[]");
    } else {
        w.text("[\n");
        for (std::size_t c = 0; c < n.children.size(); ++c) {
            w.indent(d + 1);
            w.integer(n.children[c]);
            w.text(c + 1 < n.children.size() ? ",\n" : "\n");
        }
        w.indent(d);
        w.text("]");
    }
    w.text(",\n");
    w.key(d, "cost");
    w.number(n.cost);
    w.text(",\n");
    w.key(d, "fill");
    w.number(n.fill);
    w.text(",\n");
    w.key(d, "id");
    w.integer(static_cast<long long>(i));
    w.text(",\n");
    w.key(d, "instance");
    w.id(n.instance);
    w.text(",\n");
    w.key(d, "level");
    w.integer(n.level);
    w.text(",\n");
    w.key(d, "locked");
    w.text(n.locked ? "true" : "false");
    w.text(",\n");
    w.key(d, "parent");
    w.id(n.parent);
    w.text(",\n");
    w.key(d, "sphere");
    w.text("{\n");
    w.key(d + 1, "center");
    w.vec(d + 1, n.sphere.center);
    w.text(",\n");
    w.key(d + 1, "radius");
    w.number(n.sphere.radius);
    w.text("\n");
    w.indent(d);
    w.text("}\n");
    w.indent(depth);
    w.text("}");
}

} // namespace

void appendClusterTreeJson(std::string& out, const ClusterTree& tree, int depth) {
    // A node takes about 700 characters at depth 3.
    out.reserve(out.size() + 1024 + tree.nodes.size() * 720);
    Writer w(out);
    const int d = depth + 1;
    w.text("{\n");
    w.key(d, "k");
    w.number(tree.k);
    w.text(",\n");
    w.key(d, "nodes");
    if (tree.nodes.empty()) {
        w.text("[]");
    } else {
        w.text("[\n");
        for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
            w.indent(d + 1);
            appendNode(w, tree.nodes[i], i, d + 1);
            w.text(i + 1 < tree.nodes.size() ? ",\n" : "\n");
        }
        w.indent(d);
        w.text("]");
    }
    w.text(",\n");
    w.key(d, "root");
    w.id(tree.root);
    w.text(",\n");
    w.key(d, "volume");
    w.text("\"");
    w.text(toString(tree.volume));
    w.text("\"\n");
    w.indent(depth);
    w.text("}");
}

nlohmann::json clusterTreeToJson(const ClusterTree& tree) {
    nlohmann::json nodes = nlohmann::json::array();
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        const ClusterNode& n = tree.nodes[i];
        nodes.push_back({
            {"id", i},
            {"parent", idOrNull(n.parent)},
            {"children", n.children},
            {"instance", idOrNull(n.instance)},
            {"box", {{"min", vec(n.box.min)}, {"max", vec(n.box.max)}}},
            {"sphere", {{"center", vec(n.sphere.center)}, {"radius", n.sphere.radius}}},
            {"fill", n.fill},
            {"cost", n.cost},
            {"level", n.level},
            {"locked", n.locked},
        });
    }
    return {{"volume", toString(tree.volume)},
            {"k", tree.k},
            {"root", idOrNull(tree.root)},
            {"nodes", std::move(nodes)}};
}

nlohmann::json treeMetricsToJson(const TreeMetrics& m) {
    return {{"nodes", m.nodes},
            {"leaves", m.leaves},
            {"innerNodes", m.innerNodes},
            {"depth", m.depth},
            {"meanLeafDepth", m.meanLeafDepth},
            {"minChildren", m.minChildren},
            {"meanChildren", m.meanChildren},
            {"maxChildren", m.maxChildren},
            {"totalSphereVolume", m.totalSphereVolume},
            {"totalBoxVolume", m.totalBoxVolume},
            {"meanFill", m.meanFill},
            {"meanSpread", m.meanSpread},
            {"maxSpread", m.maxSpread}};
}

} // namespace hlod
