// Turns an hlod::Scene into VTK actors for the viewport.
//
// Two layouts, chosen by instance count:
//  - per instance (up to SceneActorsOptions::mergeAbove instances): one vtkPolyData per unique
//    mesh, shared by one actor per instance that carries the instance's world matrix. Cheap to
//    build and keeps instancing visible to later per-instance highlighting.
//  - merged (more instances): one vtkPolyData per material with every instance's vertices
//    transformed to world in double and stored as float. VTK's per-actor overhead makes
//    thousands of actors slow (TORCS has ~4400 instances); tens of actors render at full speed.
//    With more than maxMergedParts materials, geometry is merged by opacity instead (textured
//    meshes by texture and alpha mode: TORCS has ~4400 materials but 28 textures) and the
//    material colours go per vertex. Each cell keeps the id of the instance it came from in the
//    cell array "InstanceId", so picking can map back to the scene.
//
// Colour: untextured, the material's effective colour (base colour times the texture's mean,
// white for no texture), converted from linear to sRGB since VTK does no colour management;
// vertex colours, when a mesh has them, replace it. Textured (the material's texture decoded
// and the mesh has uvs): base colour factor x vertex colour x texture, the alpha cut-out
// (MASK) honoured, as `hlod bench --shading textured` draws it (VtkSurfaceLook.h). Both:
// back faces culled unless the material is double-sided, emission added. Merged parts share
// one look: materials are merged only with materials that draw alike.
// Threading: build() creates only data objects and may run on a worker thread; actors()
// creates the vtkActors and must run on the GUI thread.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <memory>
#include <vector>

#include <glm/glm.hpp>
#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>

#include "pipeline/scene/Scene.h"
#include "widgets/VtkSurfaceLook.h"

namespace hlod::widgets {

struct SceneActorsOptions {
    std::size_t mergeAbove = 500; // instance count above which geometry is merged per material
    // Merged layout with more materials than this: one opaque and one translucent polydata,
    // with material colours per vertex instead (a part per material would be too many actors).
    std::size_t maxMergedParts = 64;
};

// One drawable piece of the scene.
struct ScenePart {
    vtkSmartPointer<vtkPolyData> polyData; // shared by the parts of one mesh (per-instance layout)
    glm::dmat4 transform{1.0};             // world matrix; identity for merged parts
    Id material = 0;       // kNoId when several materials share the part (colours per vertex)
    Id instance = kNoId;   // the instance drawn; kNoId for merged parts (see "InstanceId")
    glm::vec4 color{1.0f}; // display colour, sRGB, alpha = opacity
    bool vertexColors = false;
    std::shared_ptr<const RgbaImage> texture; // base colour texture (the polydata has uvs)
    VtkMaterialLook look;                     // alpha, sides, emission
};

class SceneActors {
public:
    static constexpr const char* kInstanceIdArray = "InstanceId";

    // Builds the render data of `scene` (a snapshot: later edits of `scene` are not seen).
    static std::shared_ptr<SceneActors> build(const Scene& scene,
                                              const SceneActorsOptions& options = {});

    // One actor per part, created on the first call (GUI thread only).
    const std::vector<vtkSmartPointer<vtkActor>>& actors();

    enum class Layout {
        PerInstance, // one actor per instance
        PerMaterial, // merged, one part per material
        ByOpacity,   // merged, one part per look (texture, alpha, sides, emission; untextured
                     // materials opaque or translucent), colours per vertex
    };

    const std::vector<ScenePart>& parts() const { return parts_; }
    Layout layout() const { return layout_; }
    bool merged() const { return layout_ != Layout::PerInstance; }
    std::size_t instanceCount() const { return instanceCount_; }
    std::size_t triangleCount() const { return triangleCount_; }
    // World bounds as VTK wants them: xmin, xmax, ymin, ymax, zmin, zmax.
    const std::array<double, 6>& bounds() const { return bounds_; }
    // The 8 world-box corners of every instance: what "fit view" frames (tighter than bounds()
    // for sparse scenes: an empty corner of the scene box does not push the camera back).
    const std::vector<glm::dvec3>& fitPoints() const { return fitPoints_; }

    // The scene instance that cell `cell` of part `part` was made from; kNoId when out of range.
    Id instanceOf(std::size_t part, vtkIdType cell) const;

private:
    void buildPerInstance(const Scene& scene);
    void buildMerged(const Scene& scene, std::size_t maxParts);
    void buildByOpacity(const Scene& scene, const std::vector<glm::vec4>& colors,
                        const std::vector<std::shared_ptr<const RgbaImage>>& textures);

    std::vector<ScenePart> parts_;
    std::vector<vtkSmartPointer<vtkActor>> actors_;
    std::map<const RgbaImage*, vtkSmartPointer<vtkTexture>> textures_; // one upload per image
    Layout layout_ = Layout::PerInstance;
    std::size_t instanceCount_ = 0;
    std::size_t triangleCount_ = 0;
    std::array<double, 6> bounds_{0, -1, 0, -1, 0, -1};
    std::vector<glm::dvec3> fitPoints_;
};

// Linear RGB to sRGB display value, per channel, for colours given to VTK.
glm::vec4 linearToDisplay(const glm::vec4& linear);

// The axis (0 = X, 1 = Y, 2 = Z) that points up in `scene`: Z for CAD sources (STEP, IGES,
// BREP are Z up by convention), Y for everything else (glTF and AC3D are Y up).
int suggestedUpAxis(const Scene& scene);

} // namespace hlod::widgets
