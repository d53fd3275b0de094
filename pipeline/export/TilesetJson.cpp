// tileset.json after OGC 3D Tiles 1.1 (sections 5.1 tiles, 5.5 bounding volumes "box", 5.7
// geometric error, 5.8 refinement). See Package.h for the axis convention and why the
// geometric error is the proxy error.
#include <algorithm>

#include "pipeline/export/Package.h"
#include "pipeline/proxy/ProxyEconomy.h"

namespace hlod {

namespace {

// A flat node (a single plane) still needs a box of non-zero thickness for runtimes'
// oriented-box math: 1 mm at least.
constexpr double kMinHalfExtent = 5e-4;

// Our content is Y up; tiles are Z up: (x, y, z) -> (x, -z, y).
nlohmann::json boxVolume(const Aabb& b) {
    const glm::dvec3 c = b.center();
    const glm::dvec3 h = glm::max(b.extent() * 0.5, glm::dvec3(kMinHalfExtent));
    return nlohmann::json::array({c.x, -c.z, c.y, h.x, 0.0, 0.0, 0.0, h.z, 0.0, 0.0, 0.0, h.y});
}

// Nodes in an order where every parent comes before its children.
std::vector<Id> preOrder(const ClusterTree& tree) {
    std::vector<Id> order{tree.root};
    for (std::size_t i = 0; i < order.size(); ++i) {
        for (Id c : tree.nodes[order[i]].children)
            order.push_back(c);
    }
    return order;
}

// Tile boxes that nest by construction (3D Tiles 1.1, 5.5: a tile's volume encloses its
// children's and its content): the node's box padded to the minimum thickness, grown by its
// proxy's vertices (a proxy may stray up to its error budget outside the originals) and by
// its children's tile boxes, bottom-up.
std::vector<Aabb> tileBoxes(const ClusterTree& tree, const BakeResult& bake) {
    std::vector<Aabb> boxes(tree.nodes.size());
    const std::vector<Id> order = preOrder(tree);
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        const ClusterNode& node = tree.nodes[*it];
        Aabb b = node.box;
        const glm::dvec3 c = b.center();
        const glm::dvec3 h = glm::max(b.extent() * 0.5, glm::dvec3(kMinHalfExtent));
        b.expand(c - h);
        b.expand(c + h);
        if (*it < bake.nodes.size()) {
            const ProxyMesh& proxy = bake.nodes[*it].proxy;
            for (const glm::vec3& p : proxy.positions)
                b.expand(proxy.origin + glm::dvec3(p));
        }
        for (Id child : node.children)
            b.expand(boxes[child]);
        boxes[*it] = b;
    }
    return boxes;
}

// The proxy error made monotone: a parent's error is at least its children's (3D Tiles
// expects geometric error to decrease toward the leaves). Leaves: 0.
std::vector<double> monotoneErrors(const ClusterTree& tree, const BakeResult& bake) {
    std::vector<double> err(tree.nodes.size(), 0.0);
    std::vector<Id> order{tree.root}, post;
    while (!order.empty()) {
        const Id n = order.back();
        order.pop_back();
        post.push_back(n);
        for (Id c : tree.nodes[n].children)
            order.push_back(c);
    }
    for (auto it = post.rbegin(); it != post.rend(); ++it) {
        const ClusterNode& node = tree.nodes[*it];
        if (node.isLeaf()) continue;
        double e = *it < bake.nodes.size() ? bake.nodes[*it].errorBudget : 0.0;
        for (Id c : node.children)
            e = std::max(e, err[c]);
        err[*it] = e;
    }
    return err;
}

nlohmann::json tile(const ClusterTree& tree, Id n, const std::vector<double>& err,
                    const std::vector<Aabb>& boxes, const std::vector<bool>& hasContent) {
    const ClusterNode& node = tree.nodes[n];
    nlohmann::json t;
    t["boundingVolume"] = {{"box", boxVolume(boxes[n])}};
    t["geometricError"] = err[n];
    if (hasContent[n]) t["content"] = {{"uri", "tiles/" + std::to_string(n) + ".glb"}};
    if (!node.isLeaf()) {
        nlohmann::json children = nlohmann::json::array();
        for (Id c : node.children)
            children.push_back(tile(tree, c, err, boxes, hasContent));
        t["children"] = std::move(children);
    }
    return t;
}

} // namespace

nlohmann::json buildTileset(const ClusterTree& tree, const BakeResult& bake,
                            const std::vector<bool>& hasContent,
                            const std::optional<GeoLocation>& geo) {
    std::vector<double> err = monotoneErrors(tree, bake);
    const std::vector<Aabb> boxes = tileBoxes(tree, bake);
    // A root without a proxy (ProxyEconomy.h) draws nothing itself: its error is the whole
    // model, so a runtime refines it whenever the model covers more than the pixel error.
    if (rootHasNoProxy(tree, bake)) err[tree.root] = std::max(err[tree.root], boxes[tree.root].diagonal());
    nlohmann::json root = tile(tree, tree.root, err, boxes, hasContent);
    root["refine"] = "REPLACE"; // inherited by every descendant
    if (geo) {
        const glm::dmat4 m = enuToEcef(*geo);
        nlohmann::json t = nlohmann::json::array();
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r)
                t.push_back(m[c][r]);
        }
        root["transform"] = std::move(t);
    }
    // Error when nothing is drawn: the whole model's size, so a runtime shows the root as soon
    // as the tileset is in view.
    const double top = std::max(boxes[tree.root].diagonal(), err[tree.root] * 2.0);
    return {
        {"asset", {{"version", "1.1"}, {"generator", std::string("HLOD Studio ") + HLOD_VERSION}}},
        {"geometricError", std::max(top, 1e-3)},
        {"root", std::move(root)}};
}

} // namespace hlod
