// How the package's tiles and files are laid out (README "The package", docs/architecture.md;
// issue 18 "a compact package"), before anything is encoded:
//
// - Every inner node of the tree is a tile; its content is its proxy (none for a root without
//   one, ProxyEconomy.h). Geometric errors and REPLACE refinement as before, so a runtime
//   switches where Algorithm 5 does (Package.h).
// - The leaf children of an inner node are not a tile each: they form one leaf-group tile under
//   it (geometric error 0, drawn whenever the node is refined, exactly when Algorithm 5 draws
//   its leaves), split in space into several when their raw geometry exceeds kMaxGroupBytes
//   or they spread wider than kGroupSpreadShare of the node's diameter. No small file per
//   leaf. Why the spread: at eye level the camera stands inside the nodes around it, and a
//   group is drawn whole, so the part of it behind the camera costs triangles the original
//   culls mesh by mesh (torcs-spring ground drive: 21.5K triangles drawn against the
//   original's 17.1K with groups whole, 17.0K with the cut). A cut costs draws (each part one
//   per look it holds, TileContent.h), so it is made at the triangle median only where each
//   part keeps kMinPartTriangles and kTrianglesPerDraw for every draw it adds, and never
//   where it would store an instanced mesh twice.
// - A node (not the root) whose whole subtree holds at most kSmallSubtreeTriangles original
//   triangles is too small to matter: it gets no tiles of its own. Its leaves join its
//   parent's leaf group, drawn from the parent's switch on at full detail (a few hundred
//   triangles at most instead of its proxies), merged per look with its siblings' leaves, so
//   its proxies' small files cost nothing and it adds a draw only for a look the group lacks
//   (a tile of its own per small subtree drew one per look each: torcs-spring 560 draws on
//   the automatic path against 243 with these merged). Every tile that remains switches where
//   Algorithm 5 switches the node it shows.
// - Frames: a tile's content is stored in the tile's own frame and the tile's 3D Tiles
//   `transform` (any rigid motion) places it, so content that is the same in its own frame is
//   the same file: proxies of rigid copies (same key: the bake's own frame, BakeFrame.h) and
//   leaf groups that are rigid copies share one GLB. A proxy's frame is its node's bake frame
//   (NodeBake::frame: position and rotation). A group's frame has the rotation of its parent
//   node's bake frame and sits at the centre of its leaves (their meshes' box centres, in that
//   frame); its leaves are placed in it by their linear parts and offsets quantised as the bake
//   quantises them (BakeFrame.h: offsets on a power-of-two grid below 1/1024 of the finest
//   position step, linear parts column by column at 2^-32 of their length), so copies agree to
//   the bit. The root's frame is the package frame (no transform without --geo): a root proxy
//   in a turned frame is placed by its GLB node. Tile boxes stay axis-aligned in the package
//   frame (a turned tile writes that box as an oriented box in its own frame), so no box is
//   inflated by the turn of a frame below it. Content bounds are exact (every vertex placed),
//   padded by the quantisation.
// - Inside a group, a mesh that several of its leaves show, and that is large enough for a
//   second copy to outweigh a glTF node, is stored once and instanced by nodes; every other
//   leaf is merged, in the group's frame, into one primitive per material (few draw calls, no
//   per-mesh JSON), its vertex and index ranges recorded in hlod.json.
// - Quantisation (compressed packages): a proxy's position grid is 1/64 of its error budget
//   (at the switch distance one pixel covers the budget / pixel error, so the grid is below
//   1/64 px); a leaf's is 1/16384 of its own diameter D: 1/64 of the budget t * D / S it would
//   have as a node at S / t = 256 px (the default is 300), fixed so that a change of the screen
//   parameters leaves the leaves' files as they were. A merged primitive takes the finest of
//   its leaves' grids. Never finer than 16 bits span (GlbMeshopt.h). A decoded position is off
//   by at most half a grid step per axis.
//
// Units: metres, package frame = the scene's world frame (Y up). Contract: tree and bake belong
// together (bake.nodes parallel to tree.nodes). Deterministic: the same input gives the same
// layout. Failure: none beyond bad_alloc.
#pragma once

#include <cstddef>
#include <map>
#include <vector>

#include <glm/glm.hpp>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/io/GltfTrs.h"
#include "pipeline/proxy/ErrorBudget.h"
#include "pipeline/proxy/ProxyBaker.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

// Subtrees with at most this many original triangles are shown by their leaves (see above).
inline constexpr std::size_t kSmallSubtreeTriangles = 256;

// A group's raw geometry (32 bytes per vertex, 4 per index) above which it is split in space.
inline constexpr std::size_t kMaxGroupBytes = 4u << 20;

// A group wider than this share of its node's diameter (its leaves' anchors) is split in
// space, into parts of at least kMinPartTriangles (see above).
inline constexpr double kGroupSpreadShare = 0.125;
inline constexpr std::size_t kMinPartTriangles = 512;
// What a draw call is worth in triangles when deciding a cut (see above).
inline constexpr std::size_t kTrianglesPerDraw = 256;

// One leaf inside a leaf-group content.
struct LeafSlot {
    Id leaf = kNoId;           // tree node
    Id instance = kNoId;       // scene instance
    bool merged = false;       // merged into the group's primitive of its material (else instanced)
    Trs trs;                   // instanced: the mesh's frame in the content's frame
    glm::dmat4 matrix{1.0};    // merged: the mesh's frame in the content's frame (quantised)
    double positionStep = 0.0; // requested grid in the content's frame (merged) or the mesh's
};

struct ContentPlan {
    bool proxy = false; // a proxy (of `node`) or a leaf group
    Id node = kNoId;    // proxy: the inner node; group: the parent of its leaves (or kNoId)
    std::vector<LeafSlot> leaves;
    glm::dvec3 proxyOffset{0.0};   // proxy: where its positions' origin sits in the content frame
    glm::dmat3 proxyRotation{1.0}; // proxy: how its positions turn into the content frame
    double positionStep = 0.0;     // proxy: requested grid (metres)
    Aabb worldBounds;              // content placed by its tile, package frame, padded by the
                                   // quantisation
};

struct TilePlan {
    Id node = kNoId;  // the inner node; kNoId for a leaf-group tile
    int content = -1; // index into PackageLayout::contents, -1 = no content
    int parent = -1;  // tile index, -1 for the root tile
    std::vector<int> children;
    glm::dmat4 frame{1.0}; // the tile's (and its content's) frame: a rigid motion
    double geometricError = 0.0;
    Aabb worldBox; // everything below the tile (content and children), package frame
};

// Where a content of the layout comes from: laid out here (block kNoId), or content `index` of
// the block of subtree root `block` (LayoutBlocks).
struct ContentSource {
    Id block = kNoId;
    int index = -1;
};

struct PackageLayout {
    std::vector<ContentPlan> contents;
    std::vector<ContentSource> sources; // parallel to contents
    std::vector<TilePlan> tiles;        // tiles[0] is the root; parents before children
    std::vector<int> tileOfNode;        // per tree node: the tile showing it (leaves: their group)
};

PackageLayout planPackage(const Scene& scene, const ClusterTree& tree, const BakeResult& bake);

// The layout of the subtree under inner node `node` (not the root) exactly as planPackage lays
// it out below its parent: tiles[0] is the node's (parent -1), boxes finished; tileOfNode is
// filled for the subtree's nodes only. What a shard of a distributed bake lays out and encodes
// (BakePlan.h); `scene` needs only the subtree's meshes.
PackageLayout planSubtree(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                          Id node);

// Subtrees laid out elsewhere (planSubtree, ids renumbered into `tree`'s), by root: planPackage
// takes their tiles and contents as they are instead of laying them out, so it reads no mesh
// below them. meshTriangles: per scene mesh its triangles (the scene's meshes below the blocks
// may be empty).
struct LayoutBlocks {
    std::map<Id, const PackageLayout*> byRoot;
    std::vector<std::size_t> meshTriangles;
};
PackageLayout planPackage(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                          const LayoutBlocks& blocks);

} // namespace hlod
