// The package layout: tiles, leaf groups, content frames and quantisation (see PackageLayout.h).
#include "pipeline/export/PackageLayout.h"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/export/StackedAtlas.h"
#include "pipeline/io/GlbMeshopt.h"
#include "pipeline/proxy/BakeFrame.h"
#include "pipeline/proxy/ProxyEconomy.h"

namespace hlod {

namespace {

// A flat node (a single plane) still needs a box of non-zero thickness for runtimes'
// oriented-box math: 1 mm at least.
constexpr double kMinHalfExtent = 5e-4;
// A shared mesh is instanced when the copies it saves hold at least this many triangles
// (about what a glTF mesh, its accessors and node cost in JSON).
constexpr std::size_t kInstanceTriangles = 256;

// Whether a group stores a mesh its `leaves` show once and instances it (see above).
bool worthInstancing(std::size_t meshTriangles, std::size_t leaves) {
    return leaves >= 2 && meshTriangles * (leaves - 1) >= kInstanceTriangles;
}
// Position grid: 1/64 of the error budget (see the header).
constexpr double kStepsPerBudget = 64.0;
// A leaf's grid: 1/16384 of its diameter, 1/64 of the budget t * D / S at S / t = 256.
constexpr double kLeafStepsPerDiameter = 16384.0;

Aabb thick(Aabb b) {
    if (b.empty()) return b;
    const glm::dvec3 c = b.center();
    const glm::dvec3 h = glm::max(b.extent() * 0.5, glm::dvec3(kMinHalfExtent));
    b.expand(c - h);
    b.expand(c + h);
    return b;
}

double maxAxis(const glm::dvec3& e) { return std::max({e.x, e.y, e.z}); }

// `box` (package frame) grown by what a pad of `pad` on every axis of a frame turned by
// `rotation` can reach: pad times the row sums of |rotation| (exactly `pad` when not turned).
Aabb paddedTurned(Aabb b, double pad, const glm::dmat3& rotation) {
    if (b.empty()) return b;
    for (int r = 0; r < 3; ++r) {
        const double reach =
            pad * (std::abs(rotation[0][r]) + std::abs(rotation[1][r]) + std::abs(rotation[2][r]));
        b.min[r] -= reach;
        b.max[r] += reach;
    }
    return b;
}

// The proxy error made monotone: a parent's error is at least its children's (3D Tiles expects
// geometric error to decrease toward the leaves). Leaves: 0. A root without a proxy draws
// nothing itself: its error is the whole model, so a runtime refines it whenever the model
// covers more than the pixel error.
std::vector<double> monotoneErrors(const ClusterTree& tree, const BakeResult& bake) {
    std::vector<double> err(tree.nodes.size(), 0.0);
    for (Id id : childrenFirst(tree, {tree.root})) {
        const ClusterNode& node = tree.nodes[id];
        if (node.isLeaf()) continue;
        double e = bake.nodes[id].errorBudget;
        for (Id c : node.children)
            e = std::max(e, err[c]);
        err[id] = e;
    }
    if (rootHasNoProxy(tree, bake))
        err[tree.root] = std::max(err[tree.root], tree.nodes[tree.root].box.diagonal());
    return err;
}

class Planner {
public:
    Planner(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
            const LayoutBlocks* blocks = nullptr)
        : scene_(scene), tree_(tree), bake_(bake), blocks_(blocks),
          err_(monotoneErrors(tree, bake)), triangles_(tree.nodes.size(), 0),
          meshCentre_(scene.meshes.size(), glm::dvec3(0.0)) {
        layout_.tileOfNode.assign(tree.nodes.size(), -1);
        for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
            const Aabb b = scene.meshes[m].localBounds();
            if (!b.empty()) meshCentre_[m] = b.center();
        }
        countTriangles(tree.root);
        drawKeys();
    }

    PackageLayout run() {
        if (tree_.nodes[tree_.root].isLeaf())
            groupTile({tree_.root}, -1, kNoId);
        else
            innerTile(tree_.root, -1);
        finishBoxes();
        return std::move(layout_);
    }

    // The subtree under inner node n alone (planSubtree).
    PackageLayout runSubtree(Id n) {
        innerTile(n, -1);
        finishBoxes();
        return std::move(layout_);
    }

private:
    int addTile(TilePlan t) {
        layout_.tiles.push_back(std::move(t));
        const int index = static_cast<int>(layout_.tiles.size()) - 1;
        const int parent = layout_.tiles.back().parent;
        if (parent >= 0) layout_.tiles[static_cast<std::size_t>(parent)].children.push_back(index);
        return index;
    }

    void finishBoxes() {
        for (std::size_t i = layout_.tiles.size(); i-- > 0;)
            if (i >= given_.size() || !given_[i]) finishBox(layout_.tiles[i]);
    }

    std::size_t countTriangles(Id n) {
        const ClusterNode& node = tree_.nodes[n];
        if (node.isLeaf()) {
            const Id mesh = scene_.instances[node.instance].mesh;
            return triangles_[n] =
                       blocks_ ? blocks_->meshTriangles[mesh] : scene_.meshes[mesh].triangleCount();
        }
        std::size_t sum = 0;
        for (Id c : node.children)
            sum += countTriangles(c);
        return triangles_[n] = sum;
    }

    // Whether inner node n (not the root) is too small to matter: its leaves join its parent's
    // leaf group (see the header).
    bool folded(Id n) const {
        return n != tree_.root && !tree_.nodes[n].isLeaf() &&
               triangles_[n] <= kSmallSubtreeTriangles;
    }

    void innerTile(Id n, int parent) {
        const NodeBake& b = bake_.nodes[n];
        const bool hasContent = b.hasProxy && !b.proxy.empty();
        TilePlan t;
        t.node = n;
        t.parent = parent;
        t.geometricError = err_[n];
        // A proxy's tile sits in its bake frame; the root's is the package frame, its proxy
        // placed by the content's node instead.
        const RigidFrame frame =
            hasContent ? b.frame : RigidFrame{tree_.nodes[n].box.center(), glm::dmat3(1.0)};
        const bool root = n == tree_.root;
        if (!root) t.frame = frame.matrix();
        if (hasContent) {
            ContentPlan c;
            c.proxy = true;
            c.node = n;
            c.proxyOffset = !root ? glm::dvec3(0.0) : frame.origin;
            c.proxyRotation = !root ? glm::dmat3(1.0) : frame.rotation;
            c.positionStep = quantizedBudget(b.errorBudget) / kStepsPerBudget;
            Aabb box, world;
            for (const glm::vec3& p : b.proxy.positions) {
                box.expand(glm::dvec3(p));
                world.expand(frame.origin + frame.rotation * glm::dvec3(p));
            }
            const double step = positionGridStep(maxAxis(box.extent()), c.positionStep);
            c.worldBounds = paddedTurned(world, step, frame.rotation);
            t.content = addContent(std::move(c));
        }
        const int self = addTile(std::move(t));
        layout_.tileOfNode[n] = self;
        // Leaf children and the leaves of folded children: one group, merged per look.
        std::vector<Id> leaves;
        std::vector<std::pair<Id, Id>> folds; // a folded child and its first leaf
        for (Id c : tree_.nodes[n].children) {
            if (tree_.nodes[c].isLeaf()) {
                leaves.push_back(c);
            } else if (folded(c)) {
                const std::size_t first = leaves.size();
                hlod::leavesBelow(tree_, c, leaves);
                folds.emplace_back(c, leaves[first]);
            } else if (const PackageLayout* block = blockOf(c)) {
                spliceBlock(c, *block, self);
            } else {
                innerTile(c, self);
            }
        }
        if (leaves.empty()) return;
        std::vector<std::vector<Id>> groups;
        splitGroup(std::move(leaves), bake_.nodes[n].frame.rotation,
                   tree_.nodes[n].sphere.radius * 2.0 * kGroupSpreadShare, groups);
        for (std::vector<Id>& g : groups)
            groupTile(std::move(g), self, n);
        // A folded node (and every inner node below it) is shown by its first leaf's group.
        for (const auto& [c, first] : folds)
            showInnerBy(c, layout_.tileOfNode[first]);
    }

    // The inner nodes of a folded subtree (at most kSmallSubtreeTriangles, so shallow) are
    // shown by `tile`; its leaves already have theirs.
    void showInnerBy(Id n, int tile) {
        if (tree_.nodes[n].isLeaf()) return;
        layout_.tileOfNode[n] = tile;
        for (Id c : tree_.nodes[n].children)
            showInnerBy(c, tile);
    }

    int addContent(ContentPlan c) {
        layout_.contents.push_back(std::move(c));
        layout_.sources.push_back({});
        return static_cast<int>(layout_.contents.size()) - 1;
    }

    const PackageLayout* blockOf(Id n) const {
        if (!blocks_) return nullptr;
        const auto it = blocks_->byRoot.find(n);
        return it == blocks_->byRoot.end() ? nullptr : it->second;
    }

    // A subtree laid out elsewhere (LayoutBlocks): its tiles and contents as they are, after
    // what is laid out so far, its root tile under `parent`; its boxes are finished.
    void spliceBlock(Id root, const PackageLayout& block, int parent) {
        const int t0 = static_cast<int>(layout_.tiles.size());
        const int c0 = static_cast<int>(layout_.contents.size());
        for (std::size_t i = 0; i < block.contents.size(); ++i) {
            layout_.contents.push_back(block.contents[i]);
            layout_.sources.push_back({root, static_cast<int>(i)});
        }
        given_.resize(layout_.tiles.size(), 0);
        for (std::size_t i = 0; i < block.tiles.size(); ++i) {
            TilePlan t = block.tiles[i];
            t.parent = i == 0 ? parent : t.parent + t0;
            if (t.content >= 0) t.content += c0;
            for (int& c : t.children)
                c += t0;
            layout_.tiles.push_back(std::move(t));
            given_.push_back(1);
        }
        layout_.tiles[static_cast<std::size_t>(parent)].children.push_back(t0);
        for (std::size_t n = 0; n < block.tileOfNode.size(); ++n)
            if (block.tileOfNode[n] >= 0) layout_.tileOfNode[n] = block.tileOfNode[n] + t0;
    }

    const Mesh& meshOf(Id leaf) const {
        return scene_.meshes[scene_.instances[tree_.nodes[leaf].instance].mesh];
    }
    const glm::dmat4& worldOf(Id leaf) const {
        return scene_.instanceTransform(tree_.nodes[leaf].instance);
    }
    std::size_t rawBytes(Id leaf) const {
        const Mesh& m = meshOf(leaf);
        return m.vertexCount() * 32 + m.indices.size() * 4;
    }
    // The grid a leaf asks for: 1/16384 of a diameter D (see the header).
    static double leafStep(double diameter) { return diameter / kLeafStepsPerDiameter; }

    // Where a leaf's geometry is: its mesh's box centre placed by the leaf's world matrix (it
    // turns with the leaf, unlike the centre of the leaf's world box).
    glm::dvec3 anchorOf(Id leaf) const {
        const Id mesh = scene_.instances[tree_.nodes[leaf].instance].mesh;
        return glm::dvec3(worldOf(leaf) * glm::dvec4(meshCentre_[mesh], 1.0));
    }

    // Splits a group in space (median of the leaves' anchors on the longest axis of a frame
    // turned by `rotation`, so turned copies split alike) until each part holds at most
    // kMaxGroupBytes of raw geometry and its anchors spread over at most `maxSpread` (or it
    // has fewer than 2 x kMinPartTriangles triangles). Keeps the leaves' order.
    void splitGroup(std::vector<Id> leaves, const glm::dmat3& rotation, double maxSpread,
                    std::vector<std::vector<Id>>& out) const {
        std::size_t raw = 0, tris = 0;
        for (Id l : leaves) {
            raw += rawBytes(l);
            tris += meshOf(l).triangleCount();
        }
        const glm::dmat3 back = glm::transpose(rotation);
        std::vector<glm::dvec3> at;
        Aabb centres;
        for (Id l : leaves) {
            at.push_back(back * anchorOf(l));
            centres.expand(at.back());
        }
        const glm::dvec3 e = centres.extent();
        const bool tooBig = raw > kMaxGroupBytes;
        const bool wide = std::max({e.x, e.y, e.z}) > maxSpread && tris >= 2 * kMinPartTriangles;
        if ((!tooBig && !wide) || leaves.size() < 2) {
            out.push_back(std::move(leaves));
            return;
        }
        const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
        std::vector<std::pair<double, std::size_t>> keys;
        for (std::size_t i = 0; i < leaves.size(); ++i)
            keys.push_back({at[i][axis], i});
        std::sort(keys.begin(), keys.end());
        // Too many bytes: half the leaves each side. Too wide: half the triangles each side,
        // and only where both halves keep kMinPartTriangles.
        std::vector<char> low(leaves.size(), 0);
        std::size_t lowTris = 0;
        for (std::size_t i = 0; i < keys.size(); ++i) {
            const std::size_t t = meshOf(leaves[keys[i].second]).triangleCount();
            if (tooBig ? i >= keys.size() / 2 : lowTris + t > tris / 2) break;
            low[keys[i].second] = 1;
            lowTris += t;
        }
        // A part may be culled when behind the camera; both cost their draws when in view: a
        // draw is worth kTrianglesPerDraw triangles, so each part must hold that many for
        // every draw the cut adds (a group of many looks is cut only into large parts), and
        // kMinPartTriangles at least.
        const std::size_t extraDraws =
            tooBig ? 0
                   : drawsOf(leaves, [&](std::size_t i) { return low[i] != 0; }) +
                         drawsOf(leaves, [&](std::size_t i) { return low[i] == 0; }) -
                         drawsOf(leaves, [](std::size_t) { return true; });
        const std::size_t minPart = std::max(kMinPartTriangles, kTrianglesPerDraw * extraDraws);
        if (!tooBig &&
            (lowTris < minPart || tris - lowTris < minPart || splitsInstances(leaves, low))) {
            out.push_back(std::move(leaves));
            return;
        }
        std::vector<Id> a, b;
        for (std::size_t i = 0; i < leaves.size(); ++i)
            (low[i] ? a : b).push_back(leaves[i]);
        splitGroup(std::move(a), rotation, maxSpread, out);
        splitGroup(std::move(b), rotation, maxSpread, out);
    }

    // Per scene mesh, the primitive a group merges it into (TileContent.h: one per look, a
    // stacked texture's page standing for the texture; StackedAtlas.h), numbered.
    void drawKeys() {
        const StackedAtlases atlases(scene_, false);
        using Key = std::tuple<long, std::array<float, 4>, int, bool, std::array<float, 3>, bool>;
        std::map<Key, std::uint32_t> number;
        drawKey_.resize(scene_.meshes.size());
        for (std::size_t i = 0; i < scene_.meshes.size(); ++i) {
            const Mesh& mesh = scene_.meshes[i];
            const Material& m = scene_.materials[mesh.material];
            const AtlasBand* band =
                atlases.stacks(static_cast<Id>(i)) ? atlases.band(mesh.material) : nullptr;
            const long image = band ? -1 - band->page : static_cast<long>(m.texture);
            const glm::vec4 c = m.baseColor;
            const Key key{image,
                          {c.r, c.g, c.b, c.a},
                          static_cast<int>(m.alphaMode),
                          m.doubleSided,
                          {m.emissive.r, m.emissive.g, m.emissive.b},
                          mesh.colors.empty()};
            drawKey_[i] =
                number.try_emplace(key, static_cast<std::uint32_t>(number.size())).first->second;
        }
    }

    // The draws `leaves` cost merged (their distinct primitives), with `pick` choosing which.
    template <class Pick> std::size_t drawsOf(const std::vector<Id>& leaves, Pick&& pick) const {
        std::set<std::uint32_t> keys;
        for (std::size_t i = 0; i < leaves.size(); ++i)
            if (pick(i))
                keys.insert(drawKey_[scene_.instances[tree_.nodes[leaves[i]].instance].mesh]);
        return keys.size();
    }

    // Whether cutting `leaves` into the `low` ones and the rest would store a mesh twice that
    // the whole group instances (groupTile: shown by several leaves, its copies worth a node).
    bool splitsInstances(const std::vector<Id>& leaves, const std::vector<char>& low) const {
        std::map<Id, std::array<std::size_t, 2>> sides; // mesh -> leaves showing it per side
        for (std::size_t i = 0; i < leaves.size(); ++i)
            ++sides[scene_.instances[tree_.nodes[leaves[i]].instance].mesh][low[i] ? 0 : 1];
        for (const auto& [mesh, n] : sides)
            if (n[0] > 0 && n[1] > 0 &&
                worthInstancing(scene_.meshes[mesh].triangleCount(), n[0] + n[1]))
                return true;
        return false;
    }

    // The exact bounds of a mesh placed by `m` (every vertex transformed).
    Aabb placedBounds(const Mesh& mesh, const glm::dmat4& m) const {
        Aabb b;
        for (const glm::vec3& p : mesh.positions)
            b.expand(glm::dvec3(m * glm::dvec4(glm::dvec3(p), 1.0)));
        return b;
    }

    // The finest grid the leaves ask for (leafStep of their diameters).
    double finestStep(const std::vector<Id>& leaves) const {
        double finest = 0.0;
        for (Id l : leaves) {
            const double s = leafStep(nodeDiameter(tree_.nodes[l]));
            finest = finest > 0.0 && finest < s ? finest : s;
        }
        return finest;
    }

    // Leaves placed in the group's frame (`frame`, at `centre` of the node frame `node`, every
    // placement quantised in `node` on the grid of `step`): shared meshes instanced, the rest
    // merged.
    void groupLeaves(const std::vector<Id>& leaves, const RigidFrame& node,
                     const glm::dvec3& centre, double step, const glm::dmat4& frame,
                     ContentPlan& c) const {
        std::map<Id, std::size_t> uses;
        for (Id l : leaves)
            ++uses[scene_.instances[tree_.nodes[l].instance].mesh];
        const glm::dmat3 turn(frame);
        Aabb mergedBox, mergedWorld;
        double coarsestMerged = 0.0;
        for (Id l : leaves) {
            LeafSlot s;
            s.leaf = l;
            s.instance = tree_.nodes[l].instance;
            const glm::dmat4& world = worldOf(l);
            const PartPlacement p =
                placeInFrame(node, glm::dmat3(world), glm::dvec3(world[3]), step);
            glm::dmat4 m(p.linear);
            m[3] = glm::dvec4(p.offset - centre, 1.0);
            const Mesh& mesh = meshOf(l);
            const std::size_t n = uses[scene_.instances[s.instance].mesh];
            const std::optional<Trs> trs = decomposeTrs(m);
            s.merged = !(trs && worthInstancing(mesh.triangleCount(), n));
            if (s.merged) {
                s.matrix = m;
                s.positionStep = leafStep(nodeDiameter(tree_.nodes[l]));
                coarsestMerged = std::max(coarsestMerged, s.positionStep);
                mergedBox.expand(placedBounds(mesh, m));
                mergedWorld.expand(placedBounds(mesh, frame * m));
            } else {
                s.trs = *trs;
                const Aabb local = mesh.localBounds();
                s.positionStep = leafStep(local.diagonal());
                const double grid = positionGridStep(maxAxis(local.extent()), s.positionStep);
                const glm::dvec3 scale = glm::abs(trs->scale);
                c.worldBounds.expand(paddedTurned(placedBounds(mesh, frame * m),
                                                  grid * std::max({scale.x, scale.y, scale.z}),
                                                  turn * glm::mat3_cast(trs->rotation)));
            }
            c.leaves.push_back(s);
        }
        // Any merged primitive's grid is at most this (its extent and finest ask are bounded
        // by all merged leaves' together).
        const double pad = positionGridStep(maxAxis(mergedBox.extent()), coarsestMerged);
        c.worldBounds.expand(paddedTurned(mergedWorld, pad, turn));
    }

    // A leaf group's tile under tile `parent` (-1: the tree is one leaf) showing leaves of
    // inner node `parentNode`.
    int groupTile(std::vector<Id> leaves, int parent, Id parentNode) {
        ContentPlan c;
        c.node = parentNode;
        TilePlan t;
        t.parent = parent;
        const RigidFrame node = parentNode == kNoId ? RigidFrame{} : bake_.nodes[parentNode].frame;
        const double step = finestStep(leaves);
        glm::dvec3 centre(0.0);
        if (parent >= 0) {
            // The leaves' centre in the node's frame, on the placements' grid: offsets from it
            // stay exact multiples of the grid, the same for turned copies.
            const glm::dmat3 back = glm::transpose(node.rotation);
            Aabb anchors;
            for (Id l : leaves)
                anchors.expand(back * (anchorOf(l) - node.origin));
            centre = quantizeOffset(anchors.center(), offsetGrid(step));
        }
        const RigidFrame frame =
            parent < 0 ? RigidFrame{}
                       : RigidFrame{node.origin + node.rotation * centre, node.rotation};
        t.frame = frame.matrix();
        groupLeaves(leaves, node, centre, step, t.frame, c);
        t.content = addContent(std::move(c));
        const int self = addTile(std::move(t));
        for (Id l : leaves)
            layout_.tileOfNode[l] = self;
        return self;
    }

    // The tile's box in the package frame: its content and its children's boxes (children
    // come later in `tiles`, so they are finished first when walking backwards).
    void finishBox(TilePlan& t) const {
        Aabb box;
        if (t.content >= 0)
            box.expand(thick(layout_.contents[static_cast<std::size_t>(t.content)].worldBounds));
        if (t.node != kNoId) box.expand(tree_.nodes[t.node].box);
        for (int c : t.children)
            box.expand(layout_.tiles[static_cast<std::size_t>(c)].worldBox);
        t.worldBox = thick(box);
    }

    const Scene& scene_;
    const ClusterTree& tree_;
    const BakeResult& bake_;
    const LayoutBlocks* blocks_ = nullptr;
    std::vector<char> given_; // per tile: taken finished from a block
    std::vector<double> err_;
    std::vector<std::size_t> triangles_; // original triangles below each node
    std::vector<glm::dvec3> meshCentre_; // per scene mesh: the centre of its local box
    std::vector<std::uint32_t> drawKey_; // per scene mesh: which merged primitive it joins
    PackageLayout layout_;
};

} // namespace

PackageLayout planPackage(const Scene& scene, const ClusterTree& tree, const BakeResult& bake) {
    return Planner(scene, tree, bake).run();
}

PackageLayout planSubtree(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                          Id node) {
    return Planner(scene, tree, bake).runSubtree(node);
}

PackageLayout planPackage(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                          const LayoutBlocks& blocks) {
    return Planner(scene, tree, bake, &blocks).run();
}

} // namespace hlod
