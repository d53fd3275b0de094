// The bake's per-node atlas step (issue 19): what bakeProxies calls once a node's proxy
// geometry is final and the node keeps it. Kept apart from ProxyBaker.cpp so the bake itself
// only gains a few calls.
//
// Sources: every original instance under the node (leaves of its whole subtree, not the
// children's proxies: sampling a proxy's atlas again would blur twice), placed in the node's
// frame the way the baker places its inputs: a leaf by its quantised placement (linear part
// and offset) in its parent's frame, each inner node's frame by its quantised placement in its
// parent's, composed up to the node (BakeFrame.h). Rigid copies of a cluster so get
// bit-identical sources, hence bit-identical atlases under one cache key.
// Texel size: errorBudget / pixelError = diameter / S (one texel per pixel at the switch).
// Keys: the atlas texels also depend on uvs, texture texels, base colour factors and alpha
// modes, which the geometry keys leave out: leafLookHash adds them to a leaf's key and
// hashAtlasOptions the atlas options to every node's key (only when atlases are on, so the
// keys of a vertex-colour bake are unchanged).
#pragma once

#include <cstdint>
#include <vector>

#include "pipeline/proxy/ContentHash.h"
#include "pipeline/proxy/ProxyBaker.h"
#include "pipeline/proxy/atlas/SourceSurfaces.h"
#include "pipeline/proxy/atlas/TextureMips.h"

namespace hlod {

// The originals under `node`, in its frame (`nodes`: the bake's frames, origin and budget).
SourceSurfaces gatherNodeSources(const Scene& scene, const ClusterTree& tree, Id node,
                                 const std::vector<NodeBake>& nodes);

// `proxy` (node `node`'s final geometry) with its atlas baked.
ProxyMesh bakeNodeAtlas(const ProxyMesh& proxy, const Scene& scene, const ClusterTree& tree,
                        Id node, const std::vector<NodeBake>& nodes, const BakeParams& params,
                        TextureMips& mips);

void hashAtlasOptions(ContentHash& h, const AtlasOptions& options);

// Per scene texture: a hash of its decoded texels (0 when unreadable).
std::vector<std::uint64_t> textureHashes(const Scene& scene);

// What the atlas reads of a leaf beyond its geometry key: uvs, material factor, alpha mode,
// texture texels.
std::uint64_t leafLookHash(const Scene& scene, Id instance,
                           const std::vector<std::uint64_t>& textureHash);

} // namespace hlod
