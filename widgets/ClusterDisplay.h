// VTK data for the editor's Clusters and HLOD preview display modes and its selection
// highlight, built from pipeline results (scene, cluster tree, proxies) with MergedGeometry.
//
// - ClusterColoring: every instance of the scene once, coloured by the cluster it belongs to
//   at a level of the tree (TreeViews.h nodesAtLevel); changing the level only rewrites colours.
// - boundsWireframe: the bounding spheres (three great circles each) or boxes (12 edges) of a
//   set of cluster nodes as lines, each in its node's cluster colour.
// - hlodPreview: what an engine draws for a draw list: the proxy of every drawn inner node and
//   the original mesh of every drawn leaf, optionally tinted by tree depth.
// - selectionHighlight: the selected instances in one flat highlight colour.
// Colours of a cluster come from categoryColor(label): a node keeps its colour on every level
// it appears on, and across rebuilds while its meshes are the same (the labels of
// StudioModel::clusterLabels(); node ids when none are given). Cell ids: "InstanceId" (colouring,
// highlight) or "NodeId" (preview).
#pragma once

#include <memory>
#include <vector>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "pipeline/graph/PipelineGraph.h"
#include "widgets/MergedGeometry.h"
#include "widgets/StudioModel.h"

namespace hlod::widgets {

inline constexpr const char* kNodeIdArray = "NodeId";

class ClusterColoring {
public:
    explicit ClusterColoring(const Scene& scene);
    // Colours every instance by its cluster at `level`; instances in no leaf turn grey.
    // Returns the cut (the clusters shown).
    std::vector<Id> colorByLevel(const ClusterTree& tree, int level,
                                 const std::vector<int>* labels = nullptr);
    vtkPolyData* polyData() const { return poly_; }

private:
    vtkSmartPointer<vtkPolyData> poly_;
    std::vector<VertexRange> ranges_; // per instance
};

glm::vec3 clusterColor(Id label);
// The colour of `node`: by its label when `labels` has one.
glm::vec3 clusterColorOf(Id node, const std::vector<int>* labels);

vtkSmartPointer<vtkPolyData> boundsWireframe(const ClusterTree& tree, const std::vector<Id>& nodes,
                                             BoundsShape shape,
                                             const std::vector<int>* labels = nullptr);

// The flat colour of the selection highlight: saturated magenta, a hue no cluster or depth
// colour takes.
glm::vec3 highlightColor();

// `depths` non-null: tint each drawn node by its depth (StudioModel::depths()).
vtkSmartPointer<vtkPolyData> hlodPreview(const Scene& scene, const NodeOutput& build,
                                         const std::vector<Id>& drawList,
                                         const std::vector<int>* depths,
                                         bool leaveOutTextured = false);

vtkSmartPointer<vtkPolyData> selectionHighlight(const Scene& scene,
                                                const std::vector<Id>& instances);
// The highlight of the HLOD preview: of the drawn nodes (`drawList`), those holding a selected
// instance (`instances`, sorted), as drawn (the proxy of an inner node, the mesh of a leaf) in
// the highlight colour. Cell ids: "NodeId".
vtkSmartPointer<vtkPolyData> previewHighlight(const Scene& scene, const NodeOutput& build,
                                              const std::vector<Id>& drawList,
                                              const std::vector<Id>& instances);

// Colour of tree depth `depth` in the preview's tint (root red, then blue, yellow, violet,
// green, orange, teal, lime, repeating): adjacent depths differ in hue by 60° or more.
glm::vec3 depthColor(int depth);

} // namespace hlod::widgets
