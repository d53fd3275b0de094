// `hlod info [SCENE...] [--json] [--deflection R] [--brep-unit M] [--max-triangles N ...]`:
// counts, bounds and file size of a scene, what the importers noted, and the import limits.
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "Args.h"
#include "Commands.h"
#include "SceneInput.h"
#include "pipeline/export/DiskUsage.h"

namespace hlod::cli {

namespace {

std::string nodePath(const Scene& s, Id node) {
    std::string path;
    for (Id n = node; n != kNoId && n != 0; n = s.nodes[n].parent) {
        path = "/" + s.nodes[n].name + path;
    }
    return path.empty() ? "/" : path;
}

const char* alphaModeName(AlphaMode mode) {
    return mode == AlphaMode::Mask ? "MASK" : mode == AlphaMode::Blend ? "BLEND" : "OPAQUE";
}

// Every material as authored (Scene.h): the glTF names of its properties; textures by index
// into "textures".
nlohmann::json materialsJson(const Scene& s) {
    nlohmann::json out = nlohmann::json::array();
    for (Id i = 0; i < s.materials.size(); ++i) {
        const Material& m = s.materials[i];
        const glm::vec4& c = m.baseColor;
        nlohmann::json mj = {{"id", i},
                             {"name", m.name},
                             {"base_color_factor", {c.r, c.g, c.b, c.a}},
                             {"alpha_mode", alphaModeName(m.alphaMode)},
                             {"double_sided", m.doubleSided},
                             {"emissive_factor", {m.emissive.r, m.emissive.g, m.emissive.b}}};
        if (m.alphaMode == AlphaMode::Mask) mj["alpha_cutoff"] = m.alphaCutoff;
        if (m.texture != kNoId) mj["base_color_texture"] = m.texture;
        if (m.emissiveTexture != kNoId) mj["emissive_texture"] = m.emissiveTexture;
        out.push_back(std::move(mj));
    }
    return out;
}

nlohmann::json toJson(const LoadedScene& loaded, const ImportLimits& limits) {
    const Scene& s = loaded.scene;
    const SceneStats st = s.stats();
    const Aabb b = s.worldBounds();
    nlohmann::json j;
    j["inputs"] = loaded.inputs;
    j["file_bytes"] = loaded.fileBytes;
    j["counts"] = {{"nodes", st.nodes},
                   {"meshes", st.meshes},
                   {"instances", st.instances},
                   {"draw_calls", st.drawCalls},
                   {"triangles", st.triangles},
                   {"vertices", st.vertices},
                   {"unique_triangles", st.uniqueTriangles},
                   {"unique_vertices", st.uniqueVertices},
                   {"materials", st.materials},
                   {"depth", st.depth}};
    j["bounds"] = {{"min", {b.min.x, b.min.y, b.min.z}},
                   {"max", {b.max.x, b.max.y, b.max.z}},
                   {"size", {b.extent().x, b.extent().y, b.extent().z}},
                   {"unit", "m"}};
    nlohmann::json instances = nlohmann::json::array();
    for (Id i = 0; i < s.instances.size(); ++i) {
        const MeshInstance& inst = s.instances[i];
        const Mesh& m = s.meshes[inst.mesh];
        instances.push_back({{"id", i},
                             {"name", s.nodes[inst.node].name},
                             {"path", nodePath(s, inst.node)},
                             {"mesh", inst.mesh},
                             {"mesh_name", m.name},
                             {"material", s.materials[m.material].name},
                             {"triangles", m.triangleCount()}});
    }
    j["instances"] = std::move(instances);
    j["materials"] = materialsJson(s);
    nlohmann::json textures = nlohmann::json::array();
    for (const Texture& t : s.textures) {
        nlohmann::json tj = {{"name", t.name}, {"file", t.file.string()}};
        if (t.image) tj["size"] = {t.image->width, t.image->height};
        if (!t.error.empty()) tj["error"] = t.error;
        textures.push_back(std::move(tj));
    }
    j["textures"] = std::move(textures);
    j["import_notes"] = s.importNotes;
    j["import_limits"] = {{"max_triangles", limits.maxTriangles},
                          {"max_unique_triangles", limits.maxUniqueTriangles},
                          {"max_instances", limits.maxInstances},
                          {"max_texels", limits.maxTexels},
                          {"max_image_texels", limits.maxImageTexels},
                          {"max_elements", limits.maxElements}};
    if (loaded.package) {
        const PackageInfo& p = *loaded.package;
        const DiskFootprint disk = filesFootprint({p.dir});
        j["package"] = {{"tree_nodes", p.tree.nodes.size()},
                        {"leaves", p.tree.leafCount()},
                        {"height", p.tree.height()},
                        {"leaf_triangles", p.leafTriangles},
                        {"proxy_triangles", p.proxyTriangles},
                        {"volume", toString(p.tree.volume)},
                        {"files", disk.files},
                        {"bytes_on_disk", disk.bytesOnDisk},
                        {"source", p.manifest.value("source", nlohmann::json::object())}};
    }
    return j;
}

void printText(const LoadedScene& loaded, const ImportLimits& limits) {
    const Scene& s = loaded.scene;
    const SceneStats st = s.stats();
    const Aabb b = s.worldBounds();
    std::printf("scene:      ");
    for (const auto& in : loaded.inputs)
        std::printf("%s ", in.c_str());
    std::printf("\nfile size:  %.2f MiB\n", static_cast<double>(loaded.fileBytes) / 1048576.0);
    std::printf("nodes:      %zu (depth %zu)\n", st.nodes, st.depth);
    std::printf("meshes:     %zu unique, %zu instances (%zu draw calls)\n", st.meshes, st.instances,
                st.drawCalls);
    std::printf("triangles:  %zu (%zu unique)\n", st.triangles, st.uniqueTriangles);
    std::printf("vertices:   %zu (%zu unique)\n", st.vertices, st.uniqueVertices);
    std::printf("materials:  %zu\n", st.materials);
    std::size_t unreadable = 0;
    for (const Texture& t : s.textures)
        unreadable += t.image ? 0 : 1;
    std::printf("textures:   %zu (%zu unreadable)\n", s.textures.size(), unreadable);
    std::printf("bounds:     [%.3f, %.3f, %.3f] .. [%.3f, %.3f, %.3f] m\n", b.min.x, b.min.y,
                b.min.z, b.max.x, b.max.y, b.max.z);
    const glm::dvec3 e = b.extent();
    std::printf("size:       %.3f x %.3f x %.3f m\n", e.x, e.y, e.z);
    // What the importers changed on the way in (a CAD face coarsened by the triangle budget).
    for (const std::string& note : s.importNotes)
        std::printf("note:       %s\n", note.c_str());
    // The import budget the scene was loaded under (ImportLimits.h; --max-* flags raise it).
    std::printf("limits:     %llu triangles (%llu unique), %llu instances, %llu texels\n",
                static_cast<unsigned long long>(limits.maxTriangles),
                static_cast<unsigned long long>(limits.maxUniqueTriangles),
                static_cast<unsigned long long>(limits.maxInstances),
                static_cast<unsigned long long>(limits.maxTexels));
    if (loaded.package) {
        const PackageInfo& p = *loaded.package;
        std::printf("package:    %zu tree nodes (%zu leaves, height %d, %s), %zu proxy triangles\n",
                    p.tree.nodes.size(), p.tree.leafCount(), p.tree.height(),
                    toString(p.tree.volume), p.proxyTriangles);
        const DiskFootprint disk = filesFootprint({p.dir});
        std::printf("on disk:    %.2f MB in %zu files\n",
                    static_cast<double>(disk.bytesOnDisk) / 1.0e6, disk.files);
    }
}

} // namespace

int runInfo(const CommandArgs& argv) {
    const Args args(argv, command("info"));
    const ImportOptions options = importOptionsFromArgs(args);
    const LoadedScene loaded = loadSceneArgs(args.positionals(), options);
    // Unreadable textures are not fatal (the material keeps its colour), but they are named.
    for (const Texture& t : loaded.scene.textures) {
        if (!t.error.empty()) std::fprintf(stderr, "hlod info: warning: %s\n", t.error.c_str());
    }
    if (args.has("--json")) {
        std::cout << toJson(loaded, options.limits).dump(2) << "\n";
    } else {
        printText(loaded, options.limits);
    }
    return 0;
}

} // namespace hlod::cli
