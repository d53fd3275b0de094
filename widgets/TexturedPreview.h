// The textured part of the HLOD preview: drawn proxies that carry a baked atlas, and drawn
// leaves whose material has a decoded texture (and whose mesh has uvs), each as its own
// textured actor (VtkSurfaceLook.h), so the preview shows what `hlod bench --shading textured`
// and an engine show. Everything else stays in the controller's merged preview geometry.
//
// Actors are made on first use and kept for the build they were made for (a new build drops
// them); per frame only visibility changes. Picking maps an actor back to its node.
// GUI thread only.
#pragma once

#include <map>
#include <vector>

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>

#include "pipeline/graph/PipelineGraph.h"
#include "pipeline/scene/Scene.h"

namespace hlod::widgets {

class TexturedPreview {
public:
    explicit TexturedPreview(vtkRenderer* renderer) : renderer_(renderer) {}
    ~TexturedPreview();
    TexturedPreview(const TexturedPreview&) = delete;
    TexturedPreview& operator=(const TexturedPreview&) = delete;

    // True when node `n` of `build` is drawn here (an atlas proxy or a textured leaf).
    static bool draws(const Scene& scene, const NodeOutput& build, Id n);

    // Shows exactly the nodes of `drawList` this class draws (none when `enabled` is false).
    void show(const Scene& scene, const NodeOutput& build, const std::vector<Id>& drawList,
              bool enabled);
    void hide();

    // The node `actor` draws, kNoId when it is none of ours.
    Id nodeOf(const vtkActor* actor) const;

private:
    vtkActor* actorFor(const Scene& scene, const NodeOutput& build, Id n);
    vtkTexture* textureFor(const RgbaImage& image);
    void clear();

    vtkSmartPointer<vtkRenderer> renderer_; // kept alive: the viewport may go first
    const NodeOutput* builtFor_ = nullptr;
    std::map<Id, vtkSmartPointer<vtkActor>> actors_;
    std::map<const vtkActor*, Id> nodes_;
    std::map<const RgbaImage*, vtkSmartPointer<vtkTexture>> textures_;
    std::map<const Mesh*, vtkSmartPointer<vtkPolyData>> meshes_;
    std::vector<Id> shown_;
};

} // namespace hlod::widgets
