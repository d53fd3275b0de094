// World-space triangle soup for one VTK actor, merged from scene meshes and HLOD proxies: what
// the cluster colouring, the HLOD preview and the selection highlight draw.
//
// Why merged: VTK pays per actor, and these views show hundreds to thousands of meshes at once
// (SceneActors.h explains the same choice for the original scene). Positions are transformed to
// world in double and stored as float; normals go through the inverse transpose.
// Colours: RGB per vertex, display (sRGB) values. A mesh gives its vertex colours or its
// material's effective colour, a proxy its baked colours (both linear, converted here), unless
// the caller passes a colour that replaces them (cluster and depth tints). Emission cannot be
// added after lighting per vertex in one actor: it is added to the colour instead (what a
// surface facing the light shows), so emissive materials are not drawn dark. Both sides are
// drawn (one actor for all).
// Ids: every triangle carries the id it was added with in the cell array named at construction
// ("InstanceId", "NodeId"), so a picked cell maps back to the scene or the cluster tree.
// Each add returns the vertex range it wrote, so colours can be rewritten later in place.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "pipeline/proxy/BakeFrame.h"
#include "pipeline/proxy/ProxyMesh.h"
#include "pipeline/scene/Scene.h"

namespace hlod::widgets {

struct VertexRange {
    std::size_t first = 0;
    std::size_t count = 0;
};

class MergedGeometry {
public:
    explicit MergedGeometry(std::string idArrayName);

    // Instance `instance` of `scene`, in world space.
    VertexRange addInstance(const Scene& scene, Id instance, Id id,
                            std::optional<glm::vec3> color = std::nullopt);
    // `proxy` placed by its node's frame (NodeBake::frame).
    VertexRange addProxy(const ProxyMesh& proxy, const RigidFrame& frame, Id id,
                         std::optional<glm::vec3> color = std::nullopt);

    std::size_t vertexCount() const { return positions_.size() / 3; }
    std::size_t triangleCount() const { return ids_.size(); }

    // The polydata (points, "Normals", "Colors" as active scalars, the id cell array). The
    // builder is left empty.
    vtkSmartPointer<vtkPolyData> finish();

private:
    void appendTriangles(const std::vector<std::uint32_t>& indices, std::size_t base, Id id);

    std::string idArrayName_;
    std::vector<float> positions_;
    std::vector<float> normals_;
    std::vector<unsigned char> colors_;
    std::vector<vtkIdType> connectivity_;
    std::vector<unsigned> ids_;
};

// Display colour (sRGB, 0..1) of a linear RGBA colour, alpha dropped.
glm::vec3 displayColor(const glm::vec4& linear);

// Rewrites the colours of `range` in `poly` (made by MergedGeometry) to `color` (display RGB).
void recolor(vtkPolyData& poly, const VertexRange& range, const glm::vec3& color);

// Distinct, stable colours for categories (clusters by node id, depths): golden-ratio hue
// steps at fixed saturation and value, so neighbouring ids differ clearly. Hues 346°..267°
// only: magenta and pink are kept for the selection highlight (ClusterDisplay.h).
glm::vec3 categoryColor(std::uint32_t index);

} // namespace hlod::widgets
