// Straightforward tagged binary layout: magic, version, then each vector as a 64-bit count
// followed by its elements. Plain-old-data arrays are copied in one block.
#include "pipeline/scene/SceneBinary.h"

#include <cstring>
#include <type_traits>

#include "pipeline/core/Error.h"

namespace hlod {

namespace {

constexpr std::uint32_t kMagic = 0x534c4448; // "HDLS"
constexpr std::uint32_t kVersion = 4;        // 4: doubleSided and emissive

class Writer {
public:
    template <typename T> void pod(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        out.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    template <typename T> void array(const std::vector<T>& v) {
        pod<std::uint64_t>(v.size());
        out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
    }
    void str(const std::string& s) {
        pod<std::uint64_t>(s.size());
        out.append(s);
    }
    std::string out;
};

class Reader {
public:
    Reader(const std::string& b, const std::filesystem::path& o) : bytes(b), origin(o) {}
    template <typename T> T pod() {
        T v;
        need(sizeof v);
        std::memcpy(&v, bytes.data() + pos, sizeof v);
        pos += sizeof v;
        return v;
    }
    std::uint64_t count(std::size_t elementSize) {
        const auto n = pod<std::uint64_t>();
        if (elementSize > 0 && n > (bytes.size() - pos) / elementSize) fail();
        return n;
    }
    template <typename T> std::vector<T> array() {
        const std::uint64_t n = count(sizeof(T));
        std::vector<T> v(n);
        // An empty vector's data() may be null, which memcpy must not get even for 0 bytes
        // (found by fuzz_scene under UBSan).
        if (n > 0) std::memcpy(v.data(), bytes.data() + pos, n * sizeof(T));
        pos += n * sizeof(T);
        return v;
    }
    std::string str() {
        const std::uint64_t n = count(1);
        std::string s = bytes.substr(pos, n);
        pos += n;
        return s;
    }
    [[noreturn]] void fail() const {
        throw Error(ErrorCode::Malformed, origin, "scene data is truncated or inconsistent");
    }

private:
    void need(std::size_t n) const {
        if (bytes.size() - pos < n) fail();
    }
    const std::string& bytes;
    const std::filesystem::path& origin;
    std::size_t pos = 0;
};

} // namespace

std::string writeSceneBinary(const Scene& s) {
    Writer w;
    w.pod(kMagic);
    w.pod(kVersion);
    w.pod<std::uint64_t>(s.nodes.size());
    for (const Node& n : s.nodes) {
        w.str(n.name);
        w.pod(n.parent);
        w.array(n.children);
        w.pod(n.local);
    }
    w.pod<std::uint64_t>(s.meshes.size());
    for (const Mesh& m : s.meshes) {
        w.str(m.name);
        w.array(m.positions);
        w.array(m.normals);
        w.array(m.uvs);
        w.array(m.colors);
        w.array(m.indices);
        w.pod(m.material);
    }
    w.pod<std::uint64_t>(s.materials.size());
    for (const Material& m : s.materials) {
        w.str(m.name);
        w.pod(m.baseColor);
        w.str(m.baseColorTexture.string());
        w.pod<std::uint8_t>(m.hasTexture ? 1 : 0);
        w.pod(m.textureMean);
        w.pod(m.texture);
        w.pod(m.alphaMode);
        w.pod(m.alphaCutoff);
        w.pod<std::uint8_t>(m.doubleSided ? 1 : 0);
        w.pod(m.emissive);
        w.str(m.emissiveTextureFile.string());
        w.pod(m.emissiveTexture);
        w.pod(m.emissiveMean);
    }
    w.pod<std::uint64_t>(s.textures.size());
    for (const Texture& t : s.textures) {
        w.str(t.name);
        w.str(t.file.string());
        w.str(t.error);
        const bool image = t.image != nullptr;
        w.pod<std::int32_t>(image ? t.image->width : -1);
        w.pod<std::int32_t>(image ? t.image->height : -1);
        if (image) w.array(t.image->pixels);
    }
    w.array(s.instances);
    w.pod<std::uint64_t>(s.sourceFiles.size());
    for (const auto& f : s.sourceFiles)
        w.str(f.string());
    w.pod<std::uint64_t>(s.referencedFiles.size());
    for (const auto& f : s.referencedFiles)
        w.str(f.string());
    w.pod<std::uint64_t>(s.importNotes.size());
    for (const auto& n : s.importNotes)
        w.str(n);
    return std::move(w.out);
}

Scene readSceneBinary(const std::string& bytes, const std::filesystem::path& origin) {
    Reader r(bytes, origin);
    if (r.pod<std::uint32_t>() != kMagic || r.pod<std::uint32_t>() != kVersion) r.fail();
    Scene s;
    s.nodes.resize(r.count(16));
    for (Node& n : s.nodes) {
        n.name = r.str();
        n.parent = r.pod<Id>();
        n.children = r.array<Id>();
        n.local = r.pod<glm::dmat4>();
    }
    s.meshes.resize(r.count(16));
    for (Mesh& m : s.meshes) {
        m.name = r.str();
        m.positions = r.array<glm::vec3>();
        m.normals = r.array<glm::vec3>();
        m.uvs = r.array<glm::vec2>();
        m.colors = r.array<glm::vec4>();
        m.indices = r.array<std::uint32_t>();
        m.material = r.pod<Id>();
    }
    s.materials.resize(r.count(16));
    for (Material& m : s.materials) {
        m.name = r.str();
        m.baseColor = r.pod<glm::vec4>();
        m.baseColorTexture = r.str();
        m.hasTexture = r.pod<std::uint8_t>() != 0;
        m.textureMean = r.pod<glm::vec4>();
        m.texture = r.pod<Id>();
        m.alphaMode = r.pod<AlphaMode>();
        m.alphaCutoff = r.pod<float>();
        if (m.alphaMode > AlphaMode::Blend) r.fail();
        m.doubleSided = r.pod<std::uint8_t>() != 0;
        m.emissive = r.pod<glm::vec3>();
        m.emissiveTextureFile = r.str();
        m.emissiveTexture = r.pod<Id>();
        m.emissiveMean = r.pod<glm::vec3>();
    }
    s.textures.resize(r.count(24));
    for (Texture& t : s.textures) {
        t.name = r.str();
        t.file = r.str();
        t.error = r.str();
        const auto w = r.pod<std::int32_t>(), h = r.pod<std::int32_t>();
        if (w < 0) continue;
        auto image = std::make_shared<RgbaImage>();
        image->width = w;
        image->height = h;
        image->pixels = r.array<std::uint8_t>();
        if (image->pixels.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4)
            r.fail();
        t.image = std::move(image);
    }
    for (const Material& m : s.materials) {
        if (m.texture != kNoId && m.texture >= s.textures.size()) r.fail();
        if (m.emissiveTexture != kNoId && m.emissiveTexture >= s.textures.size()) r.fail();
    }
    s.instances = r.array<MeshInstance>();
    s.sourceFiles.resize(r.count(8));
    for (auto& f : s.sourceFiles)
        f = r.str();
    s.referencedFiles.resize(r.count(8));
    for (auto& f : s.referencedFiles)
        f = r.str();
    s.importNotes.resize(r.count(8));
    for (auto& n : s.importNotes)
        n = r.str();
    // Consistent links make the walk from the root finite: every child names its parent.
    if (s.nodes.empty() || s.nodes[0].parent != kNoId) r.fail();
    for (Id i = 0; i < s.nodes.size(); ++i) {
        for (Id c : s.nodes[i].children) {
            if (c >= s.nodes.size() || c == 0 || s.nodes[c].parent != i) r.fail();
        }
    }
    s.updateWorldTransforms();
    return s;
}

} // namespace hlod
