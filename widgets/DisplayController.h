// Puts the StudioModel's display mode into the Viewport: the original scene, the clusters of a
// level with their bounds, or the HLOD preview; plus the selection highlight, the overlay with
// the frame's counters, and picking. The highlight draws the meshes of the whole selection:
// with several clusters selected (StudioModel::selectedNodes) the union of their meshes.
//
// HLOD preview: right before each frame (Viewport::aboutToRender) the model's LOD selection
// runs for the viewport's camera (its FrontCache: only the change since the last frame is
// walked); when the draw list changed the preview geometry is rebuilt, so the view shows
// exactly what an engine would draw for this camera: proxies of drawn inner nodes, original
// meshes of drawn leaves. Every frame's counters go out through frameStats(). Proxies with a
// baked atlas and leaves with textures are drawn textured (TexturedPreview.h) unless the depth
// tint is on.
// Legend (issue 20 #6): in Clusters mode the shown level's clusters with their colours (the
// largest first) and the selection's colour; in the HLOD preview tinted by depth, the colour of
// every depth drawn; hidden otherwise (ViewportLegend.h).
// Highlight: the selected meshes in one flat colour, drawn in front of the surfaces they lie on
// (polygon offset) so they never fight the mesh for depth; in the HLOD preview a selected
// cluster drawn as a proxy is highlighted as that proxy (what is on screen), not as the
// originals behind it.
// Picking: a click selects the instance (original scene, clusters) or the cluster node (HLOD
// preview; a drawn leaf selects its instance) under the cursor; a click on nothing clears it.
// The controller owns VTK props only; all state it shows comes from the model.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <QObject>
#include <QPoint>
#include <QPointer>
#include <vtkSmartPointer.h>

#include "pipeline/select/Camera.h"
#include "pipeline/select/LodSelection.h"
#include "widgets/ViewportLegend.h"

class vtkActor;
class vtkProp;
class vtkTextActor;

namespace hlod::widgets {

class ClusterColoring;
class TexturedPreview;
class StudioModel;
class Viewport;

// What a frame costs to draw, as a renderer would count it.
struct FrameStats {
    std::uint64_t drawCalls = 0;
    std::uint64_t triangles = 0;
    std::uint64_t nodesVisited = 0; // HLOD preview only: nodes the selection tested
};

class DisplayController : public QObject {
    Q_OBJECT
public:
    DisplayController(StudioModel* model, Viewport* viewport, QObject* parent = nullptr);
    ~DisplayController() override;

    // The selection camera for the viewport's current vtkCamera and size.
    Camera currentCamera() const;
    // Selects what is under `pos` (widget coordinates) in the model.
    void pickAt(const QPoint& pos);

    const FrameStats& lastFrame() const { return last_; }
    // The draw list of the last HLOD preview frame (sorted node ids).
    const std::vector<Id>& drawList() const { return drawList_; }
    // Clusters shown in Clusters mode (the level's cut).
    const std::vector<Id>& shownClusters() const { return cut_; }
    // The overlay's text (empty when hidden).
    QString overlayText() const;
    // The instances the selection highlight draws (sorted; empty when it is hidden).
    std::vector<Id> highlightedInstances() const;
    // The legend's corner (ViewportLegend::Corner) and lines (empty when it is hidden).
    ViewportLegend::Corner legendCorner() const { return legend_.corner(); }
    std::vector<ViewportLegend::Entry> legendEntries() const;

Q_SIGNALS:
    void frameStats(const hlod::widgets::FrameStats& stats);

private:
    void refresh();
    void refreshClusters();
    void refreshHighlight();
    void beforeRender();
    void updatePreview();
    void setOverlay(const QString& text);
    // Clusters mode: the level's node count (as the Statistics' table counts) and the lower
    // nodes the cut carries up.
    QString clustersOverlay() const;
    // Original and Clusters modes: the scene's instances in the view frustum (culled as the
    // HLOD preview culls), and the overlay that gives them next to the whole scene's.
    FrameStats originalFrame();
    QString originalOverlay() const;
    // Puts the legend in the free corner with the fewest meshes under it.
    void placeLegend();
    void updateLegend();
    vtkSmartPointer<vtkActor> makeActor(bool lit) const;

    StudioModel* model_;
    QPointer<Viewport> viewport_; // the viewport may go first when a window closes
    vtkSmartPointer<vtkActor> clusterActor_;
    vtkSmartPointer<vtkActor> boundsActor_;
    vtkSmartPointer<vtkActor> previewActor_;
    vtkSmartPointer<vtkActor> highlightActor_;
    vtkSmartPointer<vtkTextActor> overlay_;
    ViewportLegend legend_;
    std::unique_ptr<ClusterColoring> coloring_;
    std::unique_ptr<TexturedPreview> textured_; // atlas proxies and textured leaves
    const void* coloringFor_ = nullptr;         // the build the colouring was made for
    std::vector<Id> cut_;
    std::vector<Id> drawList_;
    bool previewDirty_ = true;
    std::vector<glm::dvec4> spheres_;  // per instance: bounding sphere (w < 0: no geometry)
    const void* spheresFor_ = nullptr; // the scene spheres_ were made for
    FrameStats last_;
};

} // namespace hlod::widgets

Q_DECLARE_METATYPE(hlod::widgets::FrameStats)
