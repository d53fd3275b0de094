// Importer for every format assimp 5.2 reads (OBJ, FBX, DAE, 3DS, PLY, STL, AC3D, IFC, ...).
//
// Separate objects stay separate: no mesh-merging post-processing (OptimizeMeshes,
// OptimizeGraph, PreTransformVertices) is requested. Polygons are triangulated, primitives
// sorted by type so lines and points (AC3D line objects, for instance) are dropped, normals
// generated where the file has none (smoothing angle 80°), identical vertices joined.
// assimp's own ValidateDataStructure step is not used: it rejects harmless empty objects
// (TORCS tracks have them); validateScene() checks what matters instead.
//
// Safety: a custom IOSystem only opens files inside the scene's folder (material libraries,
// external textures, includes), and precheckElementCounts() refuses files whose headers
// declare absurd sizes before assimp allocates for them.
#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <map>
#include <set>

#include "pipeline/core/Error.h"
#include "pipeline/core/OnDemand.h"
#include "pipeline/io/Ac3dTextures.h"
#include "pipeline/io/ImageDecode.h"
#include "pipeline/io/Import.h"
#include "pipeline/io/ImportModules.h"
#include "pipeline/io/Precheck.h"

namespace hlod {

namespace fs = std::filesystem;

namespace {

class FolderIOSystem : public Assimp::DefaultIOSystem {
public:
    explicit FolderIOSystem(fs::path folder) : folder_(std::move(folder)) {}
    // Probing is harmless (loaders look for companion files): outside the folder, a file
    // simply does not exist. Opening one is refused and reported.
    bool Exists(const char* file) const override {
        return isInsideFolder(file, folder_) && Assimp::DefaultIOSystem::Exists(file);
    }
    Assimp::IOStream* Open(const char* file, const char* mode) override {
        if (!isInsideFolder(file, folder_)) {
            if (refused_.empty()) refused_ = file;
            return nullptr;
        }
        Assimp::IOStream* stream = Assimp::DefaultIOSystem::Open(file, mode);
        if (stream) opened_.insert(fs::absolute(file).lexically_normal());
        return stream;
    }
    const std::string& refused() const { return refused_; }
    const std::set<fs::path>& opened() const { return opened_; }

private:
    fs::path folder_;
    mutable std::string refused_;
    std::set<fs::path> opened_; // every file a loader read (the scene and its companions)
};

glm::dmat4 toGlm(const aiMatrix4x4& m) {
    // assimp is row-major (a1..a4 is the first row), glm is column-major.
    return glm::dmat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4,
                      m.b4, m.c4, m.d4);
}

// An embedded assimp texture: compressed bytes (PNG, JPEG...; mHeight 0) or raw BGRA texels.
Texture embeddedTexture(const aiTexture* tex, const std::string& name, TexelBudget& budget) {
    if (tex->mHeight == 0) {
        return textureFromBytes({reinterpret_cast<const std::uint8_t*>(tex->pcData), tex->mWidth},
                                name, &budget);
    }
    Texture t;
    t.name = name;
    std::string why;
    if (!budget.charge(tex->mWidth, tex->mHeight, why)) {
        t.error = name + ": " + why;
        return t;
    }
    auto image =
        std::make_shared<RgbaImage>(static_cast<int>(tex->mWidth), static_cast<int>(tex->mHeight));
    const std::size_t n = static_cast<std::size_t>(tex->mWidth) * tex->mHeight;
    for (std::size_t i = 0; i < n; ++i) {
        const aiTexel& c = tex->pcData[i];
        image->set(static_cast<int>(i % tex->mWidth), static_cast<int>(i / tex->mWidth),
                   glm::u8vec4(c.r, c.g, c.b, c.a));
    }
    t.image = std::move(image);
    return t;
}

// Formats without an alpha mode (OBJ, FBX, AC3D...): a texture with translucent texels is a
// cut-out (trees, fences, barriers drawn as textured quads, as TORCS draws them with alpha
// testing); a material with an opacity below 1 blends.
void chooseAlphaMode(Material& mat, bool translucentTexels) {
    if (mat.baseColor.a < 1.0f) {
        mat.alphaMode = AlphaMode::Blend;
    } else if (translucentTexels) {
        mat.alphaMode = AlphaMode::Mask;
        mat.alphaCutoff = 0.5f;
    }
}

// What the format's loader tells beyond assimp's material: for AC3D, the first texture its
// object names (see Ac3dTextures.h) and whether its surfaces are two-sided.
struct FormatHints {
    bool ac3d = false;
    std::string firstTexture; // empty: assimp's texture
    bool twoSided = false;
};

class MaterialReader {
public:
    MaterialReader(const aiScene* s, fs::path folder, Scene& scene, const ImportLimits& limits)
        : scene_(s), folder_(std::move(folder)), out_(scene), texels_(limits) {}

    Material read(const aiMaterial* m, const FormatHints& hints) {
        Material mat;
        aiString name;
        if (m->Get(AI_MATKEY_NAME, name) == AI_SUCCESS) mat.name = name.C_Str();
        aiColor4D c;
        if (m->Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS ||
            m->Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS) {
            mat.baseColor = glm::vec4(c.r, c.g, c.b, 1.0f);
        }
        float opacity = 1.0f;
        if (m->Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && opacity > 0.0f) {
            mat.baseColor.a = std::min(opacity, 1.0f);
        }
        int twoSided = 0;
        mat.doubleSided =
            hints.twoSided || (m->Get(AI_MATKEY_TWOSIDED, twoSided) == AI_SUCCESS && twoSided != 0);
        aiString path;
        TextureRef base;
        if (!hints.firstTexture.empty()) {
            base = readTexture(hints.firstTexture);
        } else if (m->GetTexture(aiTextureType_BASE_COLOR, 0, &path) == AI_SUCCESS ||
                   m->GetTexture(aiTextureType_DIFFUSE, 0, &path) == AI_SUCCESS) {
            base = readTexture(path.C_Str());
        }
        mat.hasTexture = base.exists;
        mat.baseColorTexture = base.file;
        mat.texture = base.texture;
        mat.textureMean = base.mean;
        readEmissive(m, hints, base, mat);
        chooseAlphaMode(mat, mat.texture != kNoId && translucent_[mat.texture]);
        return mat;
    }

private:
    struct TextureRef {
        bool exists = false;
        fs::path file;      // empty when embedded
        Id texture = kNoId; // kNoId when unreadable or outside the folder
        glm::vec4 mean{1.0f};
    };

    // Emission: the emissive colour times the emissive texture. AC3D's `emis` has no texture
    // of its own: OpenGL's modulate mode (AC3D, TORCS) multiplies emission and lighting alike
    // by the object's texture, so the base colour texture is the emissive texture too.
    void readEmissive(const aiMaterial* m, const FormatHints& hints, const TextureRef& base,
                      Material& mat) {
        aiColor4D e;
        if (m->Get(AI_MATKEY_COLOR_EMISSIVE, e) != AI_SUCCESS) return;
        const glm::vec3 emissive(e.r, e.g, e.b);
        if (!(glm::all(glm::greaterThanEqual(emissive, glm::vec3(0.0f))) &&
              glm::all(glm::lessThan(emissive, glm::vec3(1e6f)))))
            return; // negative, NaN or absurd: no emission
        mat.emissive = emissive;
        if (!mat.emits()) return;
        aiString path;
        TextureRef tex;
        if (hints.ac3d)
            tex = base;
        else if (m->GetTexture(aiTextureType_EMISSIVE, 0, &path) == AI_SUCCESS)
            tex = readTexture(path.C_Str());
        mat.emissiveTextureFile = tex.file;
        mat.emissiveTexture = tex.texture;
        mat.emissiveMean = glm::vec3(tex.mean);
    }

    TextureRef readTexture(const std::string& ref) {
        TextureRef out;
        if (ref.empty()) return out;
        out.exists = true;
        if (const aiTexture* tex = scene_->GetEmbeddedTexture(ref.c_str())) {
            useTexture(ref, out, [&] { return embeddedTexture(tex, ref, texels_); });
            return out;
        }
        std::string rel = ref;
        for (char& ch : rel) {
            if (ch == '\\') ch = '/';
        }
        const fs::path p = (folder_ / rel).lexically_normal();
        // A texture outside the scene folder is not read (no reading of arbitrary files);
        // the material keeps its base colour.
        if (!isInsideFolder(p, folder_)) return out;
        out.file = p;
        useTexture(p.string(), out, [&] { return loadTexture(p, &texels_); });
        return out;
    }

    // One Texture per distinct reference, decoded once; its mean colour and whether it has
    // transparent texels computed once.
    template <class Load> void useTexture(const std::string& key, TextureRef& ref, Load load) {
        auto it = cache_.find(key);
        if (it == cache_.end()) {
            Texture t = load();
            const glm::vec4 mean = t.image ? meanLinearColor(*t.image) : glm::vec4(1.0f);
            const bool translucent = t.image && t.image->hasTranslucentTexels();
            const Id id = out_.addTexture(std::move(t));
            translucent_[id] = translucent;
            it = cache_.emplace(key, std::make_pair(id, mean)).first;
        }
        ref.texture = it->second.first;
        ref.mean = it->second.second;
    }

    const aiScene* scene_;
    fs::path folder_;
    Scene& out_;
    std::map<std::string, std::pair<Id, glm::vec4>> cache_;
    std::map<Id, bool> translucent_;
    TexelBudget texels_;
};

// For AC3D files: per assimp material, the first texture its object names (see
// Ac3dTextures.h), found by walking assimp's node tree and the file's object tree together,
// and whether its surfaces are two-sided. Default hints where nothing is known (other formats,
// or the trees do not pair up).
std::vector<FormatHints> formatHints(const aiScene* as, const fs::path& file) {
    std::vector<FormatHints> out(as->mNumMaterials);
    if (!isAc3dPath(file)) return out;
    for (FormatHints& h : out)
        h.ac3d = true;
    const std::optional<Ac3dFile> ac = readAc3dFile(file);
    if (!ac) return out;
    if (const auto sides = ac3dTwoSidedMaterials(*ac, out.size()))
        for (std::size_t m = 0; m < out.size(); ++m)
            out[m].twoSided = (*sides)[m];
    if (ac->objects.size() != 1) return out; // assimp adds a root for several
    std::vector<std::pair<const aiNode*, const Ac3dObject*>> stack{
        {as->mRootNode, &ac->objects.front()}};
    while (!stack.empty()) {
        auto [node, object] = stack.back();
        stack.pop_back();
        for (unsigned i = 0; node->mMeshes && i < node->mNumMeshes; ++i) {
            const unsigned m = node->mMeshes[i];
            if (m >= as->mNumMeshes || !as->mMeshes[m]) continue;
            const unsigned mat = as->mMeshes[m]->mMaterialIndex;
            if (mat < out.size()) out[mat].firstTexture = object->firstTexture;
        }
        if (node->mNumChildren != object->kids.size()) continue; // trees differ: keep assimp's
        for (unsigned c = 0; c < node->mNumChildren; ++c)
            stack.push_back({node->mChildren[c], &object->kids[c]});
    }
    return out;
}

Mesh convertMesh(const aiMesh* am) {
    Mesh mesh;
    mesh.name = am->mName.C_Str();
    const std::size_t n = am->mNumVertices;
    mesh.positions.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        mesh.positions[i] = {am->mVertices[i].x, am->mVertices[i].y, am->mVertices[i].z};
    }
    if (am->mNormals) {
        mesh.normals.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            glm::vec3 v(am->mNormals[i].x, am->mNormals[i].y, am->mNormals[i].z);
            const float len = glm::length(v);
            mesh.normals[i] = len > 0.0f && std::isfinite(len) ? v / len : glm::vec3(0, 0, 1);
        }
    }
    if (am->mTextureCoords[0]) {
        mesh.uvs.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            mesh.uvs[i] = {am->mTextureCoords[0][i].x, 1.0f - am->mTextureCoords[0][i].y};
        }
    }
    if (am->mColors[0]) {
        mesh.colors.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const aiColor4D& c = am->mColors[0][i];
            mesh.colors[i] = {c.r, c.g, c.b, c.a};
        }
    }
    mesh.indices.reserve(static_cast<std::size_t>(am->mNumFaces) * 3);
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
        const aiFace& face = am->mFaces[f];
        if (face.mNumIndices != 3) continue; // points/lines left after SortByPType
        mesh.indices.insert(mesh.indices.end(), face.mIndices, face.mIndices + 3);
    }
    return mesh;
}

// A node graph with more nodes than placements allowed is refused, not cut short: it is
// either a format's own instancing expanded by its loader or a graph that loops.
void importNodes(const aiScene* as, const std::vector<Id>& meshIds, Scene& scene,
                 const fs::path& file, const ImportLimits& limits) {
    std::vector<std::pair<const aiNode*, Id>> stack{{as->mRootNode, 0}};
    std::uint64_t count = 0;
    while (!stack.empty()) {
        auto [an, parent] = stack.back();
        stack.pop_back();
        if (++count > limits.maxInstances) {
            throwOverLimit(file,
                           "its node graph holds more than " + std::to_string(count - 1) + " nodes",
                           limits.maxInstances, "--max-instances");
        }
        const std::string name = an->mName.length ? an->mName.C_Str() : "node";
        const Id id = scene.addNode(name, parent, toGlm(an->mTransformation));
        for (unsigned i = 0; an->mMeshes && i < an->mNumMeshes; ++i) {
            const unsigned m = an->mMeshes[i];
            if (m < meshIds.size() && meshIds[m] != kNoId) scene.addInstance(meshIds[m], id);
        }
        for (unsigned c = an->mNumChildren; c-- > 0;)
            stack.push_back({an->mChildren[c], id});
    }
}

// assimp's post-processing steps trust the loaders' output and crash on out-of-range indices
// (seen with Quake 3 maps), so the raw scene is checked before any of them runs. This is the
// part of assimp's ValidateDataStructure that matters, without its refusal of empty meshes.
void checkRawScene(const aiScene* as, const fs::path& file) {
    for (unsigned m = 0; m < as->mNumMeshes; ++m) {
        const aiMesh* mesh = as->mMeshes ? as->mMeshes[m] : nullptr;
        const std::string what = "mesh " + std::to_string(m);
        if (!mesh) throw Error(ErrorCode::Malformed, file, what + " is missing");
        if (mesh->mNumVertices > 0 && !mesh->mVertices) {
            throw Error(ErrorCode::Malformed, file, what + " has no vertex positions");
        }
        if (mesh->mNumFaces > 0 && !mesh->mFaces) {
            throw Error(ErrorCode::Malformed, file, what + " has no face list");
        }
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices > 0 && !face.mIndices) {
                throw Error(ErrorCode::Malformed, file, what + " has a face without indices");
            }
            for (unsigned i = 0; i < face.mNumIndices; ++i) {
                if (face.mIndices[i] >= mesh->mNumVertices) {
                    throw Error(ErrorCode::Malformed, file,
                                what + ", face " + std::to_string(f) + ": index " +
                                    std::to_string(face.mIndices[i]) + " out of range (" +
                                    std::to_string(mesh->mNumVertices) + " vertices)");
                }
            }
        }
    }
}

} // namespace

Scene importAssimpHere(const fs::path& file, const ImportOptions& options) {
    precheckElementCounts(file, options.limits);
    const fs::path folder = fs::absolute(file).parent_path();
    Assimp::Importer importer;
    auto* io = new FolderIOSystem(folder); // owned by the importer
    importer.SetIOHandler(io);
    importer.SetPropertyBool(AI_CONFIG_FBX_CONVERT_TO_M, true);
    importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, 80.0f);
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const unsigned flags = aiProcess_Triangulate | aiProcess_SortByPType |
                           aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices;
    const aiScene* as = nullptr;
    try {
        as = importer.ReadFile(fs::absolute(file).string(), 0);
        if (as && as->mRootNode) {
            checkRawScene(as, file);
            as = importer.ApplyPostProcessing(flags);
        }
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(ErrorCode::Malformed, file, std::string("assimp failed: ") + e.what());
    }
    if (!io->refused().empty()) {
        throw Error(ErrorCode::UnsafePath, file,
                    "refers to '" + io->refused() + "' outside the scene's folder");
    }
    if (!as || !as->mRootNode) {
        std::string why = importer.GetErrorString();
        if (why.empty()) why = "unreadable or unsupported content";
        throw Error(ErrorCode::Malformed, file, why);
    }
    Scene scene;
    scene.sourceFiles.push_back(file);
    for (const fs::path& f : io->opened()) {
        if (f != fs::absolute(file).lexically_normal()) scene.referencedFiles.push_back(f);
    }
    MaterialReader materials(as, folder, scene, options.limits);
    const std::vector<FormatHints> hints = formatHints(as, file);
    std::vector<Id> materialIds;
    for (unsigned i = 0; i < as->mNumMaterials; ++i)
        materialIds.push_back(scene.addMaterial(materials.read(as->mMaterials[i], hints[i])));
    std::vector<Id> meshIds(as->mNumMeshes, kNoId);
    for (unsigned i = 0; i < as->mNumMeshes; ++i) {
        Mesh mesh = convertMesh(as->mMeshes[i]);
        if (mesh.indices.empty()) continue;
        const unsigned mat = as->mMeshes[i]->mMaterialIndex;
        mesh.material = mat < materialIds.size() ? materialIds[mat] : 0;
        meshIds[i] = scene.addMesh(std::move(mesh));
    }
    importNodes(as, meshIds, scene, file, options.limits);
    validateScene(scene, file);
    return scene;
}

} // namespace hlod

HLOD_MODULE_ENTRY(hlod::AssimpModule, assimp, &hlod::importAssimpHere)
