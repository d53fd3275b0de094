// glTF 2.0 importer (.gltf / .glb) on tinygltf 2.7, following the glTF 2.0 specification
// (Khronos): node hierarchy with TRS or matrix transforms, every primitive of a mesh becomes
// one hlod::Mesh (one material each), all index component types, non-indexed primitives,
// triangle strips and fans. Points and lines carry no surface and are skipped.
//
// Safety: tinygltf accepts some broken files silently, so every accessor is bounds-checked
// against its buffer view and buffer here, counts are capped before allocating, external
// URIs must stay inside the scene's folder (our own file-system callbacks refuse the rest),
// and the result goes through validateScene().
// EXT_meshopt_compression (gltfpack output, our own packages): decoded with meshoptimizer into a
// plain GLB in memory before tinygltf parses it (GltfMeshopt.h).
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string_view>
#include <tuple>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include "pipeline/core/Error.h"
#include "pipeline/io/GltfAccessor.h"
#include "pipeline/io/GltfMeshopt.h"
#include "pipeline/io/ImageDecode.h"
#include "pipeline/io/Import.h"

namespace hlod {

namespace fs = std::filesystem;

namespace {

struct LoadContext {
    fs::path file;
    fs::path folder;
    std::string refused;           // first external path refused, for the error message
    std::map<int, Texture> images; // decoded by the image callback, by glTF image index
    std::set<fs::path> referenced; // files read besides the scene file (buffers, images)
    TexelBudget texels;            // what this file's images may decode (ImportLimits.h)
};

// tinygltf also probes the bare relative URI ("./scene.bin"): that names the scene's folder too.
fs::path resolved(const std::string& path, const LoadContext& ctx) {
    const fs::path p(path);
    return p.is_absolute() ? p : ctx.folder / p;
}

// The URIs themselves are checked before tinygltf runs (checkExternalUris); what it probes
// besides (the URI relative to the working folder) simply does not exist outside the folder.
bool fileExists(const std::string& path, void* user) {
    auto* ctx = static_cast<LoadContext*>(user);
    if (!isInsideFolder(resolved(path, *ctx), ctx->folder)) return false;
    std::error_code ec;
    return fs::is_regular_file(resolved(path, *ctx), ec);
}

std::string expandPath(const std::string& path, void*) { return path; }

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& pathIn,
                   void* user) {
    auto* ctx = static_cast<LoadContext*>(user);
    const std::string path = resolved(pathIn, *ctx).string();
    if (!isInsideFolder(path, ctx->folder)) {
        if (ctx->refused.empty()) ctx->refused = path;
        if (err) *err += "refused to read '" + path + "' outside the scene folder\n";
        return false;
    }
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) {
        if (err) *err += "cannot open '" + path + "'\n";
        return false;
    }
    const std::streamsize size = in.tellg();
    if (size < 0 || size > (std::streamsize(1) << 32)) {
        if (err) *err += "'" + path + "' is too large\n";
        return false;
    }
    in.seekg(0);
    out->resize(static_cast<std::size_t>(size));
    in.read(reinterpret_cast<char*>(out->data()), size);
    if (in) ctx->referenced.insert(fs::path(path).lexically_normal());
    return static_cast<bool>(in);
}

bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&,
                    void*) {
    if (err) *err += "the importer never writes files\n";
    return false;
}

// Images decoded so far in this process, by content. A package's leaf tiles all reference the
// same few shared texture files: each is decoded once, not once per tile. Bounded by the
// decoded bytes it holds; the key is the bytes' size and hash, the bytes are compared on a hit.
Texture cachedTexture(const unsigned char* bytes, std::size_t size, const std::string& name,
                      TexelBudget& budget) {
    struct Entry {
        std::string bytes;
        Texture texture;
    };
    static std::mutex mutex;
    static std::map<std::pair<std::size_t, std::size_t>, Entry> cache;
    static std::size_t heldBytes = 0;
    constexpr std::size_t kMaxHeldBytes = 256u << 20;
    const std::string_view view(reinterpret_cast<const char*>(bytes), size);
    const std::pair<std::size_t, std::size_t> key{size, std::hash<std::string_view>{}(view)};
    {
        std::lock_guard lock(mutex);
        if (auto it = cache.find(key); it != cache.end() && it->second.bytes == view) {
            Texture t = it->second.texture;
            t.name = name;
            return t;
        }
    }
    Texture texture = textureFromBytes({bytes, size}, name, &budget);
    // A refusal may be this file's budget: another file decodes the same bytes afresh.
    if (!texture.image) return texture;
    const std::size_t decoded = texture.image->pixels.size();
    std::lock_guard lock(mutex);
    if (heldBytes + decoded + size > kMaxHeldBytes) {
        cache.clear();
        heldBytes = 0;
    }
    cache[key] = Entry{std::string(view), texture};
    heldBytes += decoded + size;
    return texture;
}

bool loadImage(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
               const unsigned char* bytes, int size, void* user) {
    auto* ctx = static_cast<LoadContext*>(user);
    const std::string name =
        !image->uri.empty() && image->uri.rfind("data:", 0) != 0
            ? image->uri
            : (image->name.empty() ? "image " + std::to_string(index) : image->name);
    Texture texture =
        cachedTexture(bytes, static_cast<std::size_t>(std::max(size, 0)), name, ctx->texels);
    if (!texture.error.empty()) texture.error = ctx->file.string() + ": " + texture.error;
    ctx->images[index] = std::move(texture);
    image->image.clear();
    return true; // an undecodable texture must not fail the whole scene: see Scene.h Texture
}

glm::dmat4 nodeTransform(const tinygltf::Node& n) {
    if (n.matrix.size() == 16) return glm::make_mat4(n.matrix.data());
    glm::dmat4 m(1.0);
    if (n.translation.size() == 3) {
        m = glm::translate(m, glm::dvec3(n.translation[0], n.translation[1], n.translation[2]));
    }
    if (n.rotation.size() == 4) {
        const glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
        m = m * glm::mat4_cast(glm::normalize(q));
    }
    if (n.scale.size() == 3) m = glm::scale(m, glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
    return m;
}

void checkRequiredExtensions(const tinygltf::Model& model, const fs::path& file) {
    static const std::set<std::string> supported{"KHR_materials_unlit",
                                                 "KHR_texture_transform",
                                                 "KHR_materials_emissive_strength",
                                                 "KHR_materials_ior",
                                                 "KHR_materials_specular",
                                                 "KHR_materials_transmission",
                                                 "KHR_materials_volume",
                                                 "KHR_materials_clearcoat",
                                                 "KHR_materials_sheen",
                                                 "KHR_materials_pbrSpecularGlossiness",
                                                 "KHR_mesh_quantization"};
    for (const std::string& ext : model.extensionsRequired) {
        if (!supported.count(ext)) {
            throw Error(ErrorCode::Malformed, file,
                        "requires glTF extension " + ext + ", which HLOD Studio does not decode");
        }
    }
}

AlphaMode alphaModeOf(const std::string& mode) {
    if (mode == "MASK") return AlphaMode::Mask;
    if (mode == "BLEND") return AlphaMode::Blend;
    return AlphaMode::Opaque;
}

// The scene texture of glTF texture `tex` (each image added once; its mean colour computed
// once), with the image's file when it has one.
class GltfTextures {
public:
    GltfTextures(const tinygltf::Model& model, LoadContext& ctx, Scene& scene)
        : model_(model), ctx_(ctx), scene_(scene) {}

    struct Ref {
        bool exists = false;  // the texture names an image
        fs::path file;        // empty when embedded
        Id texture = kNoId;   // kNoId when the image could not be decoded
        glm::vec4 mean{1.0f}; // linear mean of the decoded image
    };

    Ref get(int tex) {
        Ref ref;
        if (tex < 0 || tex >= static_cast<int>(model_.textures.size())) return ref;
        const int img = model_.textures[static_cast<std::size_t>(tex)].source;
        if (img < 0 || img >= static_cast<int>(model_.images.size())) return ref;
        ref.exists = true;
        const std::string& uri = model_.images[static_cast<std::size_t>(img)].uri;
        if (!uri.empty() && uri.rfind("data:", 0) != 0)
            ref.file = fs::absolute(ctx_.folder / uri).lexically_normal();
        const auto it = ctx_.images.find(img);
        if (it == ctx_.images.end()) return ref;
        auto [known, added] = textureOfImage_.try_emplace(img, kNoId);
        if (added) {
            it->second.file = ref.file;
            known->second = scene_.addTexture(it->second);
            if (const auto& image = it->second.image)
                means_[known->second] = meanLinearColor(*image);
        }
        ref.texture = known->second;
        if (auto mean = means_.find(ref.texture); mean != means_.end()) ref.mean = mean->second;
        return ref;
    }

private:
    const tinygltf::Model& model_;
    LoadContext& ctx_;
    Scene& scene_;
    std::map<int, Id> textureOfImage_;
    std::map<Id, glm::vec4> means_;
};

// KHR_materials_emissive_strength: the factor that scales emissiveFactor (1 without it).
double emissiveStrength(const tinygltf::Material& m) {
    const auto ext = m.extensions.find("KHR_materials_emissive_strength");
    if (ext == m.extensions.end() || !ext->second.Has("emissiveStrength")) return 1.0;
    const tinygltf::Value& v = ext->second.Get("emissiveStrength");
    const double strength = v.IsNumber() ? v.GetNumberAsDouble() : 1.0;
    return std::isfinite(strength) && strength >= 0.0 ? strength : 1.0;
}

std::vector<Id> importMaterials(const tinygltf::Model& model, LoadContext& ctx, Scene& scene) {
    std::vector<Id> ids;
    GltfTextures textures(model, ctx, scene);
    for (const tinygltf::Material& m : model.materials) {
        Material mat;
        mat.name = m.name;
        const auto& f = m.pbrMetallicRoughness.baseColorFactor;
        if (f.size() == 4) mat.baseColor = glm::vec4(f[0], f[1], f[2], f[3]);
        mat.alphaMode = alphaModeOf(m.alphaMode);
        mat.alphaCutoff = static_cast<float>(m.alphaCutoff);
        mat.doubleSided = m.doubleSided;
        const GltfTextures::Ref base = textures.get(m.pbrMetallicRoughness.baseColorTexture.index);
        mat.hasTexture = base.exists;
        mat.baseColorTexture = base.file;
        mat.texture = base.texture;
        mat.textureMean = base.mean;
        const auto& e = m.emissiveFactor;
        if (e.size() == 3) {
            const double strength = emissiveStrength(m);
            mat.emissive = glm::vec3(glm::dvec3(e[0], e[1], e[2]) * strength);
        }
        const GltfTextures::Ref emissive = textures.get(m.emissiveTexture.index);
        if (emissive.exists && mat.emits()) {
            mat.emissiveTextureFile = emissive.file;
            mat.emissiveTexture = emissive.texture;
            mat.emissiveMean = glm::vec3(emissive.mean);
        }
        ids.push_back(scene.addMaterial(std::move(mat)));
    }
    return ids;
}

// Triangles a primitive declares (from its index or POSITION accessor count, before reading):
// count / 3 for triangle lists, count - 2 for strips and fans, 0 for points and lines.
std::uint64_t declaredTriangles(const tinygltf::Model& model, const tinygltf::Primitive& prim) {
    int accessor = prim.indices;
    if (accessor < 0) {
        const auto pos = prim.attributes.find("POSITION");
        accessor = pos == prim.attributes.end() ? -1 : pos->second;
    }
    if (accessor < 0 || accessor >= static_cast<int>(model.accessors.size())) return 0;
    const std::uint64_t count = model.accessors[static_cast<std::size_t>(accessor)].count;
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode == TINYGLTF_MODE_TRIANGLES) return count / 3;
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN)
        return count > 2 ? count - 2 : 0;
    return 0;
}

// Each glTF mesh maps to the hlod meshes of its triangle primitives.
std::vector<std::vector<Id>> importMeshes(const tinygltf::Model& model,
                                          const std::vector<Id>& materials,
                                          const ImportOptions& options, const fs::path& file,
                                          Scene& scene) {
    std::vector<std::vector<Id>> out(model.meshes.size());
    GltfAccessorReader reader(model, file, options.limits.maxElements);
    std::uint64_t triangles = 0;
    using PrimitiveKey = std::tuple<std::map<std::string, int>, int, int, int>;
    std::map<PrimitiveKey, Id> read;
    for (std::size_t mi = 0; mi < model.meshes.size(); ++mi) {
        const tinygltf::Mesh& gm = model.meshes[mi];
        for (std::size_t pi = 0; pi < gm.primitives.size(); ++pi) {
            const tinygltf::Primitive& prim = gm.primitives[pi];
            // A primitive identical to one read before (same accessors, mode and material) is
            // the same mesh placed again, not a copy: 12,000 primitives reading one accessor of
            // 10,000 triangles would otherwise be 120 M triangles (10 GB) from an 840 KB file.
            const PrimitiveKey key{prim.attributes, prim.indices, prim.mode, prim.material};
            if (auto seen = read.find(key); seen != read.end()) {
                out[mi].push_back(seen->second);
                continue;
            }
            // Distinct primitives may still share or overlap accessors: the total is bounded
            // before it is allocated.
            triangles += declaredTriangles(model, prim);
            if (triangles > options.limits.maxUniqueTriangles) {
                throwOverLimit(file,
                               "its mesh primitives declare " + std::to_string(triangles) +
                                   " triangles or more",
                               options.limits.maxUniqueTriangles, "--max-unique-triangles");
            }
            std::optional<Mesh> mesh = reader.readPrimitive(prim);
            if (!mesh) continue; // points or lines
            mesh->name = gm.primitives.size() > 1 ? gm.name + "#" + std::to_string(pi) : gm.name;
            if (prim.material >= 0) {
                if (prim.material >= static_cast<int>(materials.size())) {
                    throw Error(ErrorCode::Malformed, file,
                                "mesh " + std::to_string(mi) + " uses material " +
                                    std::to_string(prim.material) + ", which does not exist");
                }
                mesh->material = materials[static_cast<std::size_t>(prim.material)];
            }
            const Id id = scene.addMesh(std::move(*mesh));
            read.emplace(key, id);
            out[mi].push_back(id);
        }
    }
    return out;
}

void importNodes(const tinygltf::Model& model, const std::vector<std::vector<Id>>& meshes,
                 const fs::path& file, Scene& scene) {
    std::vector<int> roots;
    if (!model.scenes.empty()) {
        const int s =
            model.defaultScene >= 0 && model.defaultScene < static_cast<int>(model.scenes.size())
                ? model.defaultScene
                : 0;
        roots = model.scenes[static_cast<std::size_t>(s)].nodes;
    } else {
        std::vector<char> isChild(model.nodes.size(), 0);
        for (const auto& n : model.nodes) {
            for (int c : n.children) {
                if (c >= 0 && c < static_cast<int>(isChild.size())) isChild[c] = 1;
            }
        }
        for (std::size_t i = 0; i < model.nodes.size(); ++i) {
            if (!isChild[i]) roots.push_back(static_cast<int>(i));
        }
    }
    std::vector<char> visited(model.nodes.size(), 0);
    std::vector<std::pair<int, Id>> stack; // (gltf node, hlod parent)
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
        stack.push_back({*it, 0});
    while (!stack.empty()) {
        auto [gi, parent] = stack.back();
        stack.pop_back();
        if (gi < 0 || gi >= static_cast<int>(model.nodes.size())) {
            throw Error(ErrorCode::Malformed, file,
                        "node index " + std::to_string(gi) + " out of range");
        }
        if (visited[static_cast<std::size_t>(gi)]) {
            throw Error(ErrorCode::Malformed, file,
                        "node " + std::to_string(gi) +
                            " is reached twice (a cycle or a node with two parents)");
        }
        visited[static_cast<std::size_t>(gi)] = 1;
        const tinygltf::Node& gn = model.nodes[static_cast<std::size_t>(gi)];
        const std::string name = gn.name.empty() ? "node" + std::to_string(gi) : gn.name;
        const Id id = scene.addNode(name, parent, nodeTransform(gn));
        if (gn.mesh >= static_cast<int>(meshes.size())) {
            throw Error(ErrorCode::Malformed, file,
                        "node " + std::to_string(gi) + " uses mesh " + std::to_string(gn.mesh) +
                            ", which does not exist");
        }
        if (gn.mesh >= 0) {
            for (Id m : meshes[static_cast<std::size_t>(gn.mesh)])
                scene.addInstance(m, id);
        }
        for (auto c = gn.children.rbegin(); c != gn.children.rend(); ++c) {
            stack.push_back({*c, id});
        }
    }
}

std::vector<std::uint8_t> readFileBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary | std::ios::ate);
    if (!in) throw Error(ErrorCode::Io, file, "cannot open the file");
    const std::streamsize size = in.tellg();
    if (size < 0 || size > (std::streamsize(1) << 32))
        throw Error(ErrorCode::TooLarge, file, "larger than 4 GiB");
    in.seekg(0);
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
    in.read(reinterpret_cast<char*>(bytes.data()), size);
    if (!in) throw Error(ErrorCode::Io, file, "cannot read the file");
    return bytes;
}

// RFC 4648 base64 (the payload of a data: URI); nullopt on a character outside the alphabet.
std::optional<std::vector<std::uint8_t>> decodeBase64(std::string_view text) {
    std::vector<std::uint8_t> out;
    std::uint32_t acc = 0;
    int bits = 0;
    for (char c : text) {
        int v;
        if (c >= 'A' && c <= 'Z')
            v = c - 'A';
        else if (c >= 'a' && c <= 'z')
            v = c - 'a' + 26;
        else if (c >= '0' && c <= '9')
            v = c - '0' + 52;
        else if (c == '+')
            v = 62;
        else if (c == '/')
            v = 63;
        else if (c == '=')
            break;
        else
            return std::nullopt;
        acc = (acc << 6) | static_cast<std::uint32_t>(v);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(static_cast<std::uint8_t>(acc >> bits));
        }
    }
    return out;
}

// The bytes of every buffer of a meshopt-compressed document (fallback buffers stay empty):
// the GLB chunk, data: URIs, or files inside the scene's folder.
std::vector<std::vector<std::uint8_t>>
meshoptBuffers(const nlohmann::json& gltf, std::vector<std::uint8_t> glbChunk, LoadContext& ctx) {
    std::vector<std::vector<std::uint8_t>> out;
    const nlohmann::json& buffers = gltf.value("buffers", nlohmann::json::array());
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        out.emplace_back();
        if (isMeshoptFallback(gltf, i)) continue;
        const std::string uri =
            buffers[i].is_object() ? buffers[i].value("uri", std::string()) : std::string();
        const std::string name = "buffer " + std::to_string(i);
        if (uri.empty()) {
            if (i != 0 || glbChunk.empty())
                throw Error(ErrorCode::Malformed, ctx.file, name + " has no data");
            out.back() = std::move(glbChunk);
        } else if (uri.rfind("data:", 0) == 0) {
            const auto comma = uri.find(";base64,");
            auto bytes = comma == std::string::npos
                             ? std::nullopt
                             : decodeBase64(std::string_view(uri).substr(comma + 8));
            if (!bytes) throw Error(ErrorCode::Malformed, ctx.file, name + ": bad data URI");
            out.back() = std::move(*bytes);
        } else {
            const fs::path p = (ctx.folder / uri).lexically_normal();
            if (!isInsideFolder(p, ctx.folder))
                throw Error(ErrorCode::UnsafePath, ctx.file,
                            "refers to '" + uri + "' outside the scene's folder");
            std::error_code ec;
            if (!fs::is_regular_file(p, ec))
                throw Error(ErrorCode::Malformed, ctx.file,
                            name + " '" + uri + "' is missing next to the scene");
            out.back() = readFileBytes(p);
            ctx.referenced.insert(p);
        }
    }
    return out;
}

// %XX escapes of a URI decoded (RFC 3986), as tinygltf does before opening the file.
std::string percentDecoded(const std::string& uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            out.push_back(static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16)));
            i += 2;
        } else {
            out.push_back(uri[i]);
        }
    }
    return out;
}

// Buffer and image URIs must name files inside the scene's folder (data: URIs aside).
void checkExternalUris(const nlohmann::json& doc, const LoadContext& ctx) {
    for (const char* list : {"buffers", "images"}) {
        if (!doc.contains(list) || !doc[list].is_array()) continue;
        for (const auto& item : doc[list]) {
            if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) continue;
            const std::string uri = item["uri"].get<std::string>();
            if (uri.rfind("data:", 0) == 0) continue;
            const fs::path p(percentDecoded(uri));
            if (p.is_absolute() || !isInsideFolder(ctx.folder / p, ctx.folder))
                throw Error(ErrorCode::UnsafePath, ctx.file,
                            "refers to '" + uri + "' outside the scene's folder");
        }
    }
}

// Parses the file with tinygltf; a document using EXT_meshopt_compression is decoded into a
// plain GLB first. False with `err` set when tinygltf refuses the file.
bool loadModel(tinygltf::TinyGLTF& loader, tinygltf::Model& model, std::string& err,
               LoadContext& ctx, const ImportOptions& options) {
    std::string ext = ctx.file.extension().string();
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const bool glb = ext == ".glb";
    std::vector<std::uint8_t> bytes = readFileBytes(ctx.file);
    GlbChunks chunks;
    if (glb)
        chunks = splitGlb(bytes, ctx.file);
    else
        chunks.json.assign(bytes.begin(), bytes.end());
    const std::string folder = ctx.folder.string();
    std::string warn;
    nlohmann::json doc = nlohmann::json::parse(chunks.json, nullptr, false);
    if (!doc.is_discarded()) checkExternalUris(doc, ctx);
    if (!doc.is_discarded() && usesMeshopt(doc)) {
        auto buffers = meshoptBuffers(doc, std::move(chunks.bin), ctx);
        const std::vector<std::uint8_t> plain =
            decodeMeshoptGltf(std::move(doc), buffers, ctx.file, options.limits.maxElements);
        return loader.LoadBinaryFromMemory(&model, &err, &warn, plain.data(),
                                           static_cast<unsigned>(plain.size()), folder);
    }
    if (glb)
        return loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                           static_cast<unsigned>(bytes.size()), folder);
    return loader.LoadASCIIFromString(&model, &err, &warn,
                                      reinterpret_cast<const char*>(bytes.data()),
                                      static_cast<unsigned>(bytes.size()), folder);
}

} // namespace

Scene importGltf(const fs::path& file, const ImportOptions& options) {
    LoadContext ctx;
    ctx.file = file;
    ctx.folder = fs::absolute(file).parent_path();
    ctx.texels = TexelBudget(options.limits);
    tinygltf::TinyGLTF loader;
    tinygltf::FsCallbacks fsCallbacks{&fileExists, &expandPath, &readWholeFile, &writeWholeFile,
                                      &ctx};
    loader.SetFsCallbacks(fsCallbacks);
    loader.SetImageLoader(&loadImage, &ctx);
    tinygltf::Model model;
    std::string err;
    bool ok = false;
    try {
        ok = loadModel(loader, model, err, ctx, options);
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(ErrorCode::Malformed, file, std::string("glTF parse failed: ") + e.what());
    }
    if (!ctx.refused.empty()) {
        throw Error(ErrorCode::UnsafePath, file,
                    "refers to '" + ctx.refused + "' outside the scene's folder");
    }
    if (!ok) {
        if (err.empty()) err = "unknown tinygltf error";
        throw Error(ErrorCode::Malformed, file, "not a valid glTF: " + err);
    }
    checkRequiredExtensions(model, file);
    Scene scene;
    scene.sourceFiles.push_back(file);
    scene.referencedFiles.assign(ctx.referenced.begin(), ctx.referenced.end());
    const std::vector<Id> materials = importMaterials(model, ctx, scene);
    const auto meshes = importMeshes(model, materials, options, file, scene);
    importNodes(model, meshes, file, scene);
    validateScene(scene, file);
    return scene;
}

} // namespace hlod
