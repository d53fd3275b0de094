// The lean final step's shared files and JSON (see LeanParts.h).
#include "pipeline/graph/LeanParts.h"

#include <fstream>

#include "pipeline/proxy/ContentHash.h"

namespace hlod::lean {

namespace fs = std::filesystem;

json vec3(const glm::dvec3& v) { return {v.x, v.y, v.z}; }
glm::dvec3 vec3(const json& j) {
    return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

namespace {

// A square matrix, column-major.
template <int N> json matrix(const glm::mat<N, N, double>& m) {
    json a = json::array();
    for (int c = 0; c < N; ++c)
        for (int r = 0; r < N; ++r)
            a.push_back(m[c][r]);
    return a;
}
template <int N> glm::mat<N, N, double> matrix(const json& j) {
    glm::mat<N, N, double> m(1.0);
    for (int c = 0; c < N; ++c)
        for (int r = 0; r < N; ++r)
            m[c][r] = j.at(static_cast<std::size_t>(c * N + r)).get<double>();
    return m;
}
} // namespace

json mat3(const glm::dmat3& m) { return matrix<3>(m); }
glm::dmat3 mat3(const json& j) { return matrix<3>(j); }
json mat4(const glm::dmat4& m) { return matrix<4>(m); }
glm::dmat4 mat4(const json& j) { return matrix<4>(j); }
json box(const Aabb& b) {
    if (b.empty()) return nullptr;
    return {b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z};
}
Aabb box(const json& j) {
    Aabb b;
    if (j.is_null()) return b;
    b.expand(glm::dvec3(j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()));
    b.expand(glm::dvec3(j.at(3).get<double>(), j.at(4).get<double>(), j.at(5).get<double>()));
    return b;
}
json look(const ProxyLookSums& s) {
    return {s.doubleSided ? 1 : 0, s.area, vec3(s.emissiveOverBase), vec3(s.emissive)};
}
ProxyLookSums look(const json& j) {
    ProxyLookSums s;
    s.doubleSided = j.at(0).get<int>() != 0;
    s.area = j.at(1).get<double>();
    s.emissiveOverBase = vec3(j.at(2));
    s.emissive = vec3(j.at(3));
    return s;
}
json idJson(Id id) { return id == kNoId ? json() : json(id); }
Id idFrom(const json& j) { return j.is_null() ? kNoId : j.get<Id>(); }

json placementJson(const Placement& p) {
    return {{"center", vec3(p.center)},    {"radius", p.radius},       {"sceneUp", vec3(p.sceneUp)},
            {"eye", vec3(p.eye)},          {"target", vec3(p.target)}, {"up", vec3(p.up)},
            {"fovYDegrees", p.fovYDegrees}};
}
Placement placementFrom(const json& j) {
    Placement p;
    p.center = vec3(j.at("center"));
    p.radius = j.at("radius").get<double>();
    p.sceneUp = vec3(j.at("sceneUp"));
    p.eye = vec3(j.at("eye"));
    p.target = vec3(j.at("target"));
    p.up = vec3(j.at("up"));
    p.fovYDegrees = j.at("fovYDegrees").get<double>();
    return p;
}

json fingerprint(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return {{"path", file.string()}, {"bytes", -1}, {"hash", ""}};
    std::vector<char> buf(4u << 20);
    std::uint64_t h = 0, bytes = 0;
    while (in) {
        in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
        const auto n = static_cast<std::size_t>(in.gcount());
        if (n == 0) break;
        h = hashBytes(buf.data(), n, h);
        bytes += n;
    }
    return {{"path", file.string()}, {"bytes", bytes}, {"hash", toHex(h)}};
}

std::vector<fs::path> filesOf(const Scene& scene) {
    std::vector<fs::path> files = scene.sourceFiles;
    files.insert(files.end(), scene.referencedFiles.begin(), scene.referencedFiles.end());
    return files;
}

json sourcesJson(const std::vector<fs::path>& sources) {
    json a = json::array();
    for (const fs::path& p : sources)
        a.push_back(p.lexically_normal().string());
    return a;
}

std::vector<std::size_t> subtreeTriangles(const Scene& scene, const ClusterTree& tree,
                                          const std::vector<Id>& childrenFirst) {
    std::vector<std::size_t> triangles(tree.nodes.size(), 0);
    for (Id id : childrenFirst) {
        const ClusterNode& node = tree.nodes[id];
        if (node.isLeaf() && node.instance != kNoId)
            triangles[id] = scene.meshes[scene.instances[node.instance].mesh].triangleCount();
        for (Id c : node.children)
            triangles[id] += triangles[c];
    }
    return triangles;
}

} // namespace hlod::lean
