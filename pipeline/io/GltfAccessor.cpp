// Accessor reading per the glTF 2.0 specification (section 3.6 "Binary Data Storage" and the
// normalized-integer conversion table of section 3.11 "Animations"/KHR_mesh_quantization).
#include "pipeline/io/GltfAccessor.h"

#include <cstring>

#include "pipeline/core/Error.h"

namespace hlod {

namespace {

std::size_t componentSize(int type) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    default:
        return 0;
    }
}

float readComponent(const unsigned char* p, int type, bool normalized) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float f;
        std::memcpy(&f, p, 4);
        return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? p[0] / 255.0f : p[0];
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const auto v = static_cast<float>(static_cast<signed char>(p[0]));
        return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? v / 65535.0f : static_cast<float>(v);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(v / 32767.0f, -1.0f) : static_cast<float>(v);
    }
    default:
        return 0.0f;
    }
}

} // namespace

const tinygltf::Accessor& GltfAccessorReader::accessor(int index, const std::string& what) const {
    if (index < 0 || index >= static_cast<int>(model_.accessors.size())) {
        throw Error(ErrorCode::Malformed, file_,
                    what + " accessor " + std::to_string(index) + " does not exist");
    }
    return model_.accessors[static_cast<std::size_t>(index)];
}

std::pair<const unsigned char*, std::size_t>
GltfAccessorReader::locate(const tinygltf::Accessor& a, std::size_t elementSize,
                           const std::string& what) const {
    if (a.sparse.isSparse) {
        throw Error(ErrorCode::Malformed, file_, what + " uses a sparse accessor (unsupported)");
    }
    if (a.count > maxElements_) {
        throw Error(ErrorCode::TooLarge, file_,
                    what + " declares " + std::to_string(a.count) + " elements (limit " +
                        std::to_string(maxElements_) + ")");
    }
    if (a.bufferView < 0 || a.bufferView >= static_cast<int>(model_.bufferViews.size())) {
        throw Error(ErrorCode::Malformed, file_, what + " has no valid buffer view");
    }
    const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (view.buffer < 0 || view.buffer >= static_cast<int>(model_.buffers.size())) {
        throw Error(ErrorCode::Malformed, file_, what + ": buffer view points to no buffer");
    }
    const tinygltf::Buffer& buffer = model_.buffers[static_cast<std::size_t>(view.buffer)];
    const std::size_t stride = view.byteStride ? view.byteStride : elementSize;
    if (stride < elementSize) {
        throw Error(ErrorCode::Malformed, file_, what + ": byte stride smaller than the element");
    }
    // All arithmetic in 64 bits on values already capped above: no overflow.
    const std::uint64_t viewEnd = std::uint64_t(view.byteOffset) + view.byteLength;
    const std::uint64_t need =
        a.count == 0 ? 0 : std::uint64_t(a.byteOffset) + stride * (a.count - 1) + elementSize;
    if (viewEnd > buffer.data.size() || need > view.byteLength) {
        throw Error(ErrorCode::Malformed, file_,
                    what + " reads past the end of its buffer (truncated or corrupt data)");
    }
    return {buffer.data.data() + view.byteOffset + a.byteOffset, stride};
}

std::vector<float> GltfAccessorReader::readFloats(int index, int components,
                                                  const char* what) const {
    const tinygltf::Accessor& a = accessor(index, what);
    const int have = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    const std::size_t csize = componentSize(a.componentType);
    // Colours may be RGB (alpha then stays 1); every other attribute must match exactly.
    const int minHave = components == 4 ? 3 : components;
    if (have <= 0 || csize == 0 || have < minHave || have > components) {
        throw Error(ErrorCode::Malformed, file_, std::string(what) + " has an unusable type");
    }
    auto [base, stride] = locate(a, csize * static_cast<std::size_t>(have), what);
    std::vector<float> out(a.count * static_cast<std::size_t>(components), 1.0f);
    for (std::size_t i = 0; i < a.count; ++i) {
        const unsigned char* e = base + i * stride;
        for (int c = 0; c < std::min(have, components); ++c) {
            out[i * components + c] = readComponent(e + c * csize, a.componentType, a.normalized);
        }
    }
    return out;
}

std::vector<std::uint32_t> GltfAccessorReader::readIndices(int index) const {
    const tinygltf::Accessor& a = accessor(index, "index");
    const std::size_t csize = componentSize(a.componentType);
    if (a.type != TINYGLTF_TYPE_SCALAR || csize == 0 ||
        a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        throw Error(ErrorCode::Malformed, file_, "index accessor has an unusable type");
    }
    auto [base, stride] = locate(a, csize, "index");
    std::vector<std::uint32_t> out(a.count);
    for (std::size_t i = 0; i < a.count; ++i) {
        const unsigned char* e = base + i * stride;
        if (csize == 1) {
            out[i] = e[0];
        } else if (csize == 2) {
            std::uint16_t v;
            std::memcpy(&v, e, 2);
            out[i] = v;
        } else {
            std::memcpy(&out[i], e, 4);
        }
    }
    return out;
}

namespace {

std::vector<std::uint32_t> toTriangleList(const std::vector<std::uint32_t>& idx, int mode) {
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        std::vector<std::uint32_t> out(idx.begin(), idx.end() - idx.size() % 3);
        return out;
    }
    std::vector<std::uint32_t> out;
    for (std::size_t i = 2; i < idx.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            // Alternate winding so every triangle keeps the strip's orientation.
            if (i % 2 == 0)
                out.insert(out.end(), {idx[i - 2], idx[i - 1], idx[i]});
            else
                out.insert(out.end(), {idx[i - 1], idx[i - 2], idx[i]});
        } else {
            out.insert(out.end(), {idx[0], idx[i - 1], idx[i]});
        }
    }
    return out;
}

} // namespace

std::optional<Mesh> GltfAccessorReader::readPrimitive(const tinygltf::Primitive& prim) const {
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        return std::nullopt;
    }
    auto attr = [&](const char* name) {
        auto it = prim.attributes.find(name);
        return it == prim.attributes.end() ? -1 : it->second;
    };
    const int posIndex = attr("POSITION");
    if (posIndex < 0) throw Error(ErrorCode::Malformed, file_, "primitive has no POSITION");
    Mesh mesh;
    const std::vector<float> pos = readFloats(posIndex, 3, "POSITION");
    const std::size_t n = pos.size() / 3;
    mesh.positions.resize(n);
    std::memcpy(mesh.positions.data(), pos.data(), pos.size() * sizeof(float));
    auto sameCount = [&](const std::vector<float>& v, int c, const char* what) {
        if (v.size() != n * static_cast<std::size_t>(c)) {
            throw Error(ErrorCode::Malformed, file_,
                        std::string(what) + " count differs from POSITION count");
        }
    };
    if (int i = attr("NORMAL"); i >= 0) {
        const std::vector<float> v = readFloats(i, 3, "NORMAL");
        sameCount(v, 3, "NORMAL");
        mesh.normals.resize(n);
        std::memcpy(mesh.normals.data(), v.data(), v.size() * sizeof(float));
    }
    if (int i = attr("TEXCOORD_0"); i >= 0) {
        const std::vector<float> v = readFloats(i, 2, "TEXCOORD_0");
        sameCount(v, 2, "TEXCOORD_0");
        mesh.uvs.resize(n);
        std::memcpy(mesh.uvs.data(), v.data(), v.size() * sizeof(float));
    }
    if (int i = attr("COLOR_0"); i >= 0) {
        const std::vector<float> v = readFloats(i, 4, "COLOR_0");
        sameCount(v, 4, "COLOR_0");
        mesh.colors.resize(n);
        std::memcpy(mesh.colors.data(), v.data(), v.size() * sizeof(float));
    }
    std::vector<std::uint32_t> idx;
    if (prim.indices >= 0) {
        idx = readIndices(prim.indices);
    } else {
        idx.resize(n);
        for (std::size_t i = 0; i < n; ++i)
            idx[i] = static_cast<std::uint32_t>(i);
    }
    mesh.indices = toTriangleList(idx, mode);
    for (std::uint32_t i : mesh.indices) {
        if (i >= n) {
            throw Error(ErrorCode::Malformed, file_,
                        "index " + std::to_string(i) + " out of range (" + std::to_string(n) +
                            " vertices)");
        }
    }
    return mesh;
}

} // namespace hlod
