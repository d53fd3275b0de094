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
// Colours of a cluster come from categoryColor(node id): a node keeps its colour on every level
// it appears on. Cell ids: "InstanceId" (colouring, highlight) or "NodeId" (preview).
#pragma once

#include <memory>
#include <vector>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "pipeline/doc/HlodBuild.h"
#include "widgets/MergedGeometry.h"
#include "widgets/StudioModel.h"

namespace hlod::widgets {

inline constexpr const char* kNodeIdArray = "NodeId";

class ClusterColoring {
public:
    explicit ClusterColoring(const Scene& scene);
    // Colours every instance by its cluster at `level`; instances in no leaf turn grey.
    // Returns the cut (the clusters shown).
    std::vector<Id> colorByLevel(const ClusterTree& tree, int level);
    vtkPolyData* polyData() const { return poly_; }

private:
    vtkSmartPointer<vtkPolyData> poly_;
    std::vector<VertexRange> ranges_; // per instance
};

glm::vec3 clusterColor(Id node);

vtkSmartPointer<vtkPolyData> boundsWireframe(const ClusterTree& tree, const std::vector<Id>& nodes,
                                             BoundsShape shape);

// `depths` non-null: tint each drawn node by its depth (StudioModel::depths()).
vtkSmartPointer<vtkPolyData> hlodPreview(const Scene& scene, const HlodBuild& build,
                                         const std::vector<Id>& drawList,
                                         const std::vector<int>* depths,
                                         bool leaveOutTextured = false);

vtkSmartPointer<vtkPolyData> selectionHighlight(const Scene& scene,
                                                const std::vector<Id>& instances);

// Colour of tree depth `depth` in the preview's tint (root red, then through the hues).
glm::vec3 depthColor(int depth);

} // namespace hlod::widgets
