// What the plan, the shards and the lean final step of a distributed bake share (LeanFinal.h):
// the plan folder's file names and the JSON of the values a layout and a bake decision hold
// (doubles written so that they read back exactly). Internal to pipeline/graph.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/export/Placement.h"
#include "pipeline/proxy/ProxyLook.h"
#include "pipeline/scene/Scene.h"

namespace hlod::lean {

using nlohmann::json;

inline constexpr const char* kTopScene = "top.scene";
inline constexpr const char* kSizes = "sizes.bin";
inline std::string tilesName(int index) { return "shard-" + std::to_string(index) + ".tiles"; }

json vec3(const glm::dvec3& v);
glm::dvec3 vec3(const json& j);
json mat3(const glm::dmat3& m); // column-major
glm::dmat3 mat3(const json& j);
json mat4(const glm::dmat4& m);
glm::dmat4 mat4(const json& j);
json box(const Aabb& b); // null when empty
Aabb box(const json& j);
json look(const ProxyLookSums& s);
ProxyLookSums look(const json& j);
json idJson(Id id); // null for kNoId
Id idFrom(const json& j);
json placementJson(const Placement& p);
Placement placementFrom(const json& j);

// A file's path, size and content hash ({"path", "bytes", "hash"}; bytes -1 when unreadable),
// read in pieces (a scene file may be large).
json fingerprint(const std::filesystem::path& file);
// The scene's source files and the files they reference.
std::vector<std::filesystem::path> filesOf(const Scene& scene);
json sourcesJson(const std::vector<std::filesystem::path>& sources);

// Original triangles below each node of `childrenFirst` (other entries 0); `scene` needs the
// meshes of those nodes' leaves.
std::vector<std::size_t> subtreeTriangles(const Scene& scene, const ClusterTree& tree,
                                          const std::vector<Id>& childrenFirst);

} // namespace hlod::lean
