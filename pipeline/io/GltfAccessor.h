// Bounds-checked reading of glTF accessors into an hlod::Mesh (glTF 2.0 spec, section 3.6:
// accessors, buffer views, strides, normalized integer components).
// Failure: throws Error(Malformed) naming the file for any out-of-range or ill-typed accessor,
// Error(TooLarge) for counts above the configured cap (checked before allocating).
#pragma once

#include <filesystem>
#include <optional>

#include <tiny_gltf.h>

#include "pipeline/scene/Scene.h"

namespace hlod {

class GltfAccessorReader {
public:
    GltfAccessorReader(const tinygltf::Model& model, std::filesystem::path file,
                       std::size_t maxElements)
        : model_(model), file_(std::move(file)), maxElements_(maxElements) {}

    // The primitive as a triangle mesh (strips and fans converted), or nullopt for points and
    // lines. Normals stay empty when the file has none (Scene::addMesh computes them).
    std::optional<Mesh> readPrimitive(const tinygltf::Primitive& prim) const;

private:
    // Reads `components` floats per element (normalized integers mapped to [0,1] / [-1,1]).
    std::vector<float> readFloats(int accessor, int components, const char* what) const;
    std::vector<std::uint32_t> readIndices(int accessor) const;
    // Validates the accessor and returns (pointer to first element, stride).
    std::pair<const unsigned char*, std::size_t>
    locate(const tinygltf::Accessor& a, std::size_t elementSize, const std::string& what) const;
    const tinygltf::Accessor& accessor(int index, const std::string& what) const;

    const tinygltf::Model& model_;
    std::filesystem::path file_;
    std::size_t maxElements_;
};

} // namespace hlod
