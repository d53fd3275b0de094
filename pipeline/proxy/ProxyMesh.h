// The geometry of one proxy (thesis 5.3: "a simplified stand-in mesh for a whole subtree") and
// the proxy methods that produce it.
//
// Units: metres. Positions are stored relative to `origin` (world space, double) so a proxy of a
// small cluster far from the world origin keeps full float precision.
// Colours are linear RGBA quantised to 8 bits: they replace the materials of the meshes the
// proxy stands in for (base colour times texture mean times vertex colour).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "pipeline/scene/RgbaImage.h"

namespace hlod {

// A proxy's baked base-colour atlas (pipeline/proxy/atlas/BakeAtlas.h): the encoded file as it
// is written to the tile (JPEG when opaque, PNG when it carries a cut-out) and the image
// decoded from exactly those bytes (so a cached proxy and a freshly baked one look the same).
struct ProxyAtlas {
    std::vector<std::uint8_t> encoded;
    std::string mimeType;                   // "image/jpeg" or "image/png"
    std::shared_ptr<const RgbaImage> image; // sRGB RGBA, top row first
    bool mask = false;                      // alpha cut-out at 0.5 (glTF alphaMode MASK)
};

struct ProxyMesh {
    glm::dvec3 origin{0.0};
    std::vector<glm::vec3> positions;   // relative to origin
    std::vector<glm::vec3> normals;     // empty, or one per position
    std::vector<glm::u8vec4> colors;    // one per position (linear RGBA, 255 = 1.0)
    std::vector<std::uint32_t> indices; // 3 per triangle, counter-clockwise = front
    // With a baked atlas: one uv per position (v = 0 at the image top, as glTF) and the atlas,
    // which then carries the whole base colour (vertex colours stay for the parents' bakes
    // and the vertex-colour fallback, but are not drawn with it).
    std::vector<glm::vec2> uvs;
    std::shared_ptr<const ProxyAtlas> atlas;
    // How far the proxy may lie from the original meshes it stands for, both ways (metres):
    // every point of it lies within this of them and every point of them within this of it
    // (parts too small to see at the switch point aside, SmallParts.h). A parent baked from
    // this proxy gets only the rest of its own budget for it, so errors never add up past a
    // node's budget (DecimateProxy.h). 0 for an aggregated input of original meshes only.
    float errorBound = 0.0f;
    // How it is drawn besides its base colour (ProxyLook.h, set by the baker from the originals
    // it stands for, not stored in the proxy cache): from both sides, and the linear emissive
    // factor (with an atlas: times the atlas, which is the emissive texture too; without: the
    // emitted colour itself).
    bool doubleSided = false;
    glm::vec3 emissive{0.0f};

    std::size_t triangleCount() const { return indices.size() / 3; }
    std::size_t vertexCount() const { return positions.size(); }
    bool empty() const { return indices.empty(); }
    bool hasAtlas() const { return atlas && atlas->image && uvs.size() == positions.size(); }
};

// How an inner node's proxy is made from its children (see DecimateProxy.h, RemeshProxy.h,
// SloppyProxy.h for what each guarantees).
enum class ProxyMethod { Decimate, Remesh, Sloppy };

const char* toString(ProxyMethod method);
// Parses "decimate", "remesh", "sloppy"; throws Error(InvalidArgument) otherwise.
ProxyMethod proxyMethodFromString(const std::string& text);

// Linear float colour -> 8-bit (clamped to [0,1], rounded).
glm::u8vec4 quantizeColor(const glm::vec4& linear);

} // namespace hlod
