// Display modes, highlight, overlay and picking in the viewport (see DisplayController.h).
#include "widgets/DisplayController.h"
#include "widgets/TexturedPreview.h"

#include <algorithm>
#include <cmath>

#include <QLocale>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedIntArray.h>

#include "pipeline/view/TreeViews.h"
#include "widgets/ClusterDisplay.h"
#include "widgets/SceneActors.h"
#include "widgets/StudioModel.h"
#include "widgets/Viewport.h"

namespace hlod::widgets {

namespace {

glm::dvec3 toGlm(const double v[3]) { return {v[0], v[1], v[2]}; }

// The id a merged polydata stores for `cell` in `array`; kNoId when there is none.
Id cellId(vtkActor* actor, const char* array, vtkIdType cell) {
    if (!actor || cell < 0) return kNoId;
    auto* poly = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInput());
    if (!poly) return kNoId;
    auto* ids = vtkUnsignedIntArray::SafeDownCast(poly->GetCellData()->GetArray(array));
    if (!ids || cell >= ids->GetNumberOfTuples()) return kNoId;
    return ids->GetValue(cell);
}

QString count(std::uint64_t n) { return QLocale().toString(static_cast<qulonglong>(n)); }

} // namespace

DisplayController::DisplayController(StudioModel* model, Viewport* viewport, QObject* parent)
    : QObject(parent), model_(model), viewport_(viewport) {
    qRegisterMetaType<hlod::widgets::FrameStats>();
    clusterActor_ = makeActor(true);
    previewActor_ = makeActor(true);
    boundsActor_ = makeActor(false);
    boundsActor_->GetProperty()->SetLineWidth(1.5f);
    boundsActor_->PickableOff();
    highlightActor_ = makeActor(true);
    highlightActor_->PickableOff();
    highlightActor_->GetProperty()->SetAmbient(0.45);
    // Drawn over the very surfaces it highlights: pulled towards the camera in depth. The
    // offsets act only with coincident topology resolved by polygon offset, which VTK leaves
    // off unless asked (without it the highlight fought the mesh for every pixel).
    vtkMapper::SetResolveCoincidentTopologyToPolygonOffset();
    highlightActor_->GetMapper()->SetRelativeCoincidentTopologyPolygonOffsetParameters(-2.0, -40.0);
    overlay_ = vtkSmartPointer<vtkTextActor>::New();
    vtkTextProperty* text = overlay_->GetTextProperty();
    text->SetFontSize(15);
    text->SetColor(1.0, 1.0, 1.0);
    text->SetBackgroundColor(0.1, 0.12, 0.16);
    text->SetBackgroundOpacity(0.65);
    text->SetVerticalJustificationToTop();
    text->SetJustificationToLeft();
    overlay_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    overlay_->SetPosition(0.012, 0.975);
    overlay_->PickableOff();
    vtkRenderer* renderer = viewport_->renderer();
    textured_ = std::make_unique<TexturedPreview>(renderer);
    for (vtkProp* prop :
         {static_cast<vtkProp*>(clusterActor_), static_cast<vtkProp*>(previewActor_),
          static_cast<vtkProp*>(boundsActor_), static_cast<vtkProp*>(highlightActor_),
          static_cast<vtkProp*>(overlay_)}) {
        prop->VisibilityOff();
        renderer->AddViewProp(prop);
    }
    legend_.addTo(renderer);

    connect(model_, &StudioModel::viewChanged, this, &DisplayController::refresh);
    connect(model_, &StudioModel::sceneChanged, this, [this] {
        spheresFor_ = nullptr; // a new scene may live where the old one did
        refresh();
    });
    connect(model_, &StudioModel::buildFinished, this, [this] {
        previewDirty_ = true;
        refresh();
    });
    connect(model_, &StudioModel::selectionChanged, this, [this] {
        refreshHighlight();
        if (model_->view().boundsOfSelectionOnly) refreshClusters();
        updateLegend();
        viewport_->update();
    });
    connect(viewport_, &Viewport::aboutToRender, this, &DisplayController::beforeRender);
    connect(viewport_, &Viewport::clicked, this, &DisplayController::pickAt);
    refresh();
}

DisplayController::~DisplayController() {
    if (!viewport_) return;
    vtkRenderer* renderer = viewport_->renderer();
    for (vtkProp* prop : {static_cast<vtkProp*>(clusterActor_),
                          static_cast<vtkProp*>(previewActor_), static_cast<vtkProp*>(boundsActor_),
                          static_cast<vtkProp*>(highlightActor_), static_cast<vtkProp*>(overlay_)})
        renderer->RemoveViewProp(prop);
    legend_.removeFrom(renderer);
}

vtkSmartPointer<vtkActor> DisplayController::makeActor(bool lit) const {
    auto actor = vtkSmartPointer<vtkActor>::New();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(vtkNew<vtkPolyData>());
    mapper->SetScalarVisibility(true);
    mapper->SetColorModeToDirectScalars();
    actor->SetMapper(mapper);
    vtkProperty* property = actor->GetProperty();
    if (lit) {
        property->SetInterpolationToPhong();
        property->SetAmbient(0.1);
        property->SetDiffuse(0.8);
        property->SetSpecular(0.12);
        property->SetSpecularPower(24.0);
    } else {
        property->LightingOff();
    }
    return actor;
}

void DisplayController::refresh() {
    const bool built = model_->hasBuild() && model_->scene();
    const DisplayMode mode = built ? model_->view().mode : DisplayMode::Original;
    viewport_->setSceneActorsVisible(mode == DisplayMode::Original);
    clusterActor_->SetVisibility(mode == DisplayMode::Clusters);
    boundsActor_->SetVisibility(mode == DisplayMode::Clusters &&
                                model_->view().bounds != BoundsShape::None);
    previewActor_->SetVisibility(mode == DisplayMode::Hlod);
    if (mode != DisplayMode::Hlod) textured_->hide();
    if (mode == DisplayMode::Clusters) refreshClusters();
    if (mode == DisplayMode::Hlod) previewDirty_ = true;
    if (!built) {
        coloring_.reset();
        coloringFor_ = nullptr;
        cut_.clear();
        drawList_.clear();
        previewActor_->GetMapper()->SetInputDataObject(vtkNew<vtkPolyData>());
    }
    refreshHighlight();
    updateLegend();
    viewport_->update();
}

void DisplayController::updateLegend() {
    using Entry = ViewportLegend::Entry;
    std::vector<Entry> entries;
    const bool built = model_->hasBuild() && model_->scene();
    const DisplayMode mode = built ? model_->view().mode : DisplayMode::Original;
    if (mode == DisplayMode::Clusters) {
        entries.push_back({tr("Level %1: one colour per cluster").arg(model_->view().level),
                           glm::vec3(1.0f), false});
        // Clusters before single meshes, the largest first; the rest in one line.
        const ClusterTree& tree = *model_->built().build->tree;
        std::vector<Id> shown = cut_;
        const auto& triangles = model_->subtreeTriangles();
        std::stable_sort(shown.begin(), shown.end(), [&](Id a, Id b) {
            const bool leafA = tree.nodes[a].isLeaf(), leafB = tree.nodes[b].isLeaf();
            if (leafA != leafB) return leafB;
            return a < triangles.size() && b < triangles.size() && triangles[a] > triangles[b];
        });
        const std::size_t listed = std::min<std::size_t>(shown.size(), 6);
        const std::vector<int>& labels = model_->clusterLabels();
        const Scene& scene = *model_->scene();
        for (std::size_t i = 0; i < listed; ++i) {
            const Id n = shown[i];
            QString text;
            if (const ClusterNode& node = tree.nodes[n]; node.isLeaf()) {
                const MeshInstance& instance = scene.instances[node.instance];
                text = QString::fromStdString(scene.nodes[instance.node].name);
                if (text.isEmpty()) text = tr("Mesh %1").arg(node.instance);
            } else {
                text = tr("Cluster %1").arg(n < labels.size() ? labels[n] : static_cast<int>(n));
            }
            entries.push_back({text, clusterColorOf(n, &labels)});
        }
        if (shown.size() > listed)
            entries.push_back({shown.size() - listed == 1
                                   ? tr("1 more cluster")
                                   : tr("%1 more clusters").arg(shown.size() - listed),
                               glm::vec3(0.6f), false});
    } else if (mode == DisplayMode::Hlod && model_->view().tintByDepth) {
        entries.push_back({tr("Tint: depth in the tree"), glm::vec3(1.0f), false});
        std::vector<int> depths;
        for (Id n : drawList_)
            if (n < model_->depths().size()) depths.push_back(model_->depths()[n]);
        std::sort(depths.begin(), depths.end());
        depths.erase(std::unique(depths.begin(), depths.end()), depths.end());
        for (int d : depths)
            entries.push_back(
                {d == 0 ? tr("Depth 0 (root)") : tr("Depth %1").arg(d), depthColor(d)});
    }
    if (!entries.empty() && !model_->selection().instances.empty())
        entries.push_back({tr("Selected"), highlightColor()});
    legend_.setEntries(std::move(entries), viewport_->devicePixelRatioF());
}

std::vector<ViewportLegend::Entry> DisplayController::legendEntries() const {
    return legend_.visible() ? legend_.entries() : std::vector<ViewportLegend::Entry>{};
}

void DisplayController::refreshClusters() {
    if (!model_->hasBuild() || model_->view().mode != DisplayMode::Clusters) return;
    const BuiltHlod& built = model_->built();
    if (!coloring_ || coloringFor_ != built.build.get()) {
        coloring_ = std::make_unique<ClusterColoring>(*built.scene);
        coloringFor_ = built.build.get();
        clusterActor_->GetMapper()->SetInputDataObject(coloring_->polyData());
    }
    const ClusterTree& tree = *built.build->tree;
    cut_ = coloring_->colorByLevel(tree, model_->view().level, &model_->clusterLabels());
    std::vector<Id> bounded = cut_;
    if (model_->view().boundsOfSelectionOnly) {
        // The selected clusters and the level's clusters inside them.
        const std::vector<Id>& selected = model_->selectedNodes();
        bounded = selected;
        for (Id n : cut_) {
            if (std::binary_search(selected.begin(), selected.end(), n)) continue;
            for (Id s : selected)
                if (isInSubtree(tree, n, s)) {
                    bounded.push_back(n);
                    break;
                }
        }
    }
    boundsActor_->GetMapper()->SetInputDataObject(
        boundsWireframe(tree, bounded, model_->view().bounds, &model_->clusterLabels()));
    boundsActor_->SetVisibility(model_->view().bounds != BoundsShape::None);
    coloring_->polyData()->Modified();
    updateLegend();
}

void DisplayController::refreshHighlight() {
    const auto& scene = model_->scene();
    const StudioSelection& selection = model_->selection();
    if (!scene || selection.instances.empty()) {
        highlightActor_->VisibilityOff();
        return;
    }
    // In the HLOD preview the selection is lit as drawn (a proxy, not the originals behind it).
    const bool preview = model_->hasBuild() && model_->view().mode == DisplayMode::Hlod;
    highlightActor_->GetMapper()->SetInputDataObject(
        preview ? previewHighlight(*scene, *model_->built().build, drawList_, selection.instances)
                : selectionHighlight(*scene, selection.instances));
    highlightActor_->VisibilityOn();
}

std::vector<Id> DisplayController::highlightedInstances() const {
    std::vector<Id> out;
    if (!highlightActor_->GetVisibility()) return out;
    auto* poly = vtkPolyData::SafeDownCast(highlightActor_->GetMapper()->GetInput());
    if (!poly) return out;
    if (auto* ids = vtkUnsignedIntArray::SafeDownCast(
            poly->GetCellData()->GetArray(SceneActors::kInstanceIdArray)))
        for (vtkIdType cell = 0; cell < ids->GetNumberOfTuples(); ++cell)
            out.push_back(ids->GetValue(cell));
    // The preview's highlight names drawn nodes: their instances.
    if (auto* nodes =
            vtkUnsignedIntArray::SafeDownCast(poly->GetCellData()->GetArray(kNodeIdArray));
        nodes && model_->hasBuild()) {
        std::vector<Id> seen;
        for (vtkIdType cell = 0; cell < nodes->GetNumberOfTuples(); ++cell)
            seen.push_back(nodes->GetValue(cell));
        std::sort(seen.begin(), seen.end());
        seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
        for (Id n : seen) {
            const std::vector<Id> below = instancesBelow(*model_->built().build->tree, n);
            out.insert(out.end(), below.begin(), below.end());
        }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

Camera DisplayController::currentCamera() const {
    vtkCamera* vc = viewport_->camera();
    Camera camera;
    camera.eye = toGlm(vc->GetPosition());
    camera.target = toGlm(vc->GetFocalPoint());
    camera.up = toGlm(vc->GetViewUp());
    camera.fovY = vc->GetViewAngle() * 3.14159265358979323846 / 180.0;
    const int h = std::max(viewport_->frameHeight(), 1);
    camera.viewportHeight = h;
    camera.aspect =
        viewport_->height() > 0 ? double(viewport_->width()) / viewport_->height() : 1.0;
    // Depth never culls in the preview: everything in front of the eye may be drawn.
    const double distance = vc->GetDistance();
    camera.nearPlane = std::max(distance * 1e-6, 1e-6);
    camera.farPlane = std::max(distance * 1e6, 1e6);
    return camera;
}

void DisplayController::placeLegend() {
    // The free corner (bottom right, bottom left, top right) the fewest meshes' bounding
    // spheres reach into:
    // the legend covers as little of the scene as it can from this camera (issue 31 #9).
    if (!legend_.visible() || !model_->scene() || spheresFor_ != model_->scene().get()) return;
    const Camera camera = currentCamera();
    const glm::dmat4 clip = camera.projection() * camera.view();
    const double H = viewport_->frameHeight();
    const double W = viewport_->height() > 0 ? H * viewport_->width() / viewport_->height() : H;
    const QSize box = legend_.pixelSize();
    const double pixelsPerUnit = H / (2.0 * std::tan(camera.fovY / 2.0));
    const double bw = box.width() + 16.0, bh = box.height() + 16.0;
    using Corner = ViewportLegend::Corner;
    const Corner corners[3] = {Corner::BottomRight, Corner::BottomLeft, Corner::TopRight};
    std::size_t under[3] = {0, 0, 0};
    for (const glm::dvec4& s : spheres_) {
        if (s.w < 0.0) continue;
        const glm::dvec4 p = clip * glm::dvec4(glm::dvec3(s), 1.0);
        if (p.w <= 0.0) continue;
        const double x = (p.x / p.w * 0.5 + 0.5) * W, y = (p.y / p.w * 0.5 + 0.5) * H; // y up
        // The sphere's radius on screen (p.w is the depth in front of the eye).
        const double r = s.w * pixelsPerUnit / p.w;
        const bool left = (x - r) < bw;
        const bool right = (x + r) > W - bw;
        const bool low = (y - r) < bh;
        const bool high = (y + r) > H - bh;
        under[0] += right && low;
        under[1] += left && low;
        under[2] += right && high;
    }
    int best = 0;
    for (int c = 1; c < 3; ++c)
        if (under[c] < under[best]) best = c;
    legend_.setCorner(corners[best]);
}

void DisplayController::beforeRender() {
    const DisplayMode mode = model_->hasBuild() ? model_->view().mode : DisplayMode::Original;
    FrameStats stats;
    if (mode == DisplayMode::Hlod) {
        updatePreview();
        return; // updatePreview reports the frame
    }
    if (model_->scene()) stats = originalFrame();
    placeLegend();
    last_ = stats;
    setOverlay(mode == DisplayMode::Clusters ? clustersOverlay() : originalOverlay());
    Q_EMIT frameStats(stats);
}

FrameStats DisplayController::originalFrame() {
    // The original scene (also under the cluster colours): one draw per instance in the view,
    // culled as the HLOD preview culls (issue 31 #8: Algorithm 5's frustum test on bounding
    // spheres), so the two overlays compare.
    const Scene& scene = *model_->scene();
    if (spheresFor_ != &scene) {
        spheres_.clear();
        spheres_.reserve(scene.instances.size());
        for (Id i = 0; i < scene.instances.size(); ++i) {
            const Aabb box = scene.instanceBounds(i);
            spheres_.push_back(box.empty() ? glm::dvec4(0.0, 0.0, 0.0, -1.0)
                                           : glm::dvec4(box.center(), 0.5 * box.diagonal()));
        }
        spheresFor_ = &scene;
    }
    const Frustum frustum = Frustum::fromCamera(currentCamera());
    FrameStats stats;
    for (Id i = 0; i < scene.instances.size(); ++i) {
        const glm::dvec4& s = spheres_[i];
        if (s.w < 0.0 || !frustum.intersectsSphere(glm::dvec3(s), s.w)) continue;
        ++stats.drawCalls;
        stats.triangles += scene.meshes[scene.instances[i].mesh].triangleCount();
    }
    return stats;
}

QString DisplayController::originalOverlay() const {
    if (!model_->scene()) return {};
    const SceneStats all = model_->scene()->stats();
    return tr("Draw calls: %1 in view (of %2)\nTriangles: %3 in view (of %4)")
        .arg(count(last_.drawCalls), count(all.drawCalls), count(last_.triangles),
             count(all.triangles));
}

QString DisplayController::clustersOverlay() const {
    // Counted as the Statistics' per-level table counts (ClusterNode::level exactly L), so the
    // two agree; the cut also holds lower nodes no level-L cluster holds, said apart.
    const int level = model_->view().level;
    const ClusterTree& tree = *model_->built().build->tree;
    const auto atLevel = static_cast<std::size_t>(std::count_if(
        cut_.begin(), cut_.end(), [&](Id n) { return tree.nodes[n].level == level; }));
    QString text = atLevel == 1
                       ? tr("Level %1 of %2: 1 level-%1 node").arg(level).arg(model_->maxLevel())
                       : tr("Level %1 of %2: %3 level-%1 nodes")
                             .arg(level)
                             .arg(model_->maxLevel())
                             .arg(count(atLevel));
    if (const std::size_t lower = cut_.size() - atLevel; lower > 0)
        text += QLatin1Char('\n') + tr("+ %1 lower clusters and meshes in no level-%2 cluster")
                                        .arg(count(lower))
                                        .arg(level);
    return text;
}

void DisplayController::updatePreview() {
    const BuiltHlod& built = model_->built();
    const SelectionResult result = model_->selectLod(currentCamera());
    if (previewDirty_ || result.drawList != drawList_) {
        drawList_ = result.drawList;
        const std::vector<int>* depths = model_->view().tintByDepth ? &model_->depths() : nullptr;
        const bool textured = depths == nullptr;
        previewActor_->GetMapper()->SetInputDataObject(
            hlodPreview(*built.scene, *built.build, drawList_, depths, textured));
        textured_->show(*built.scene, *built.build, drawList_, textured);
        previewDirty_ = false;
        refreshHighlight(); // lit as drawn: follows the draw list
        updateLegend();
    }
    last_ = {result.drawCalls, result.triangles, result.nodesVisited};
    if (model_->scene() && spheresFor_ != model_->scene().get()) originalFrame();
    placeLegend();
    setOverlay(tr("Draw calls: %1\nTriangles: %2\nNodes visited: %3")
                   .arg(count(last_.drawCalls), count(last_.triangles), count(last_.nodesVisited)));
    Q_EMIT frameStats(last_);
}

void DisplayController::setOverlay(const QString& text) {
    overlay_->SetVisibility(!text.isEmpty());
    const QByteArray utf8 = text.toUtf8();
    if (utf8 != overlay_->GetInput()) overlay_->SetInput(utf8.constData());
}

QString DisplayController::overlayText() const {
    if (!overlay_->GetVisibility() || !overlay_->GetInput()) return {};
    return QString::fromUtf8(overlay_->GetInput());
}

void DisplayController::pickAt(const QPoint& pos) {
    const Viewport::PickResult hit = viewport_->pick(pos);
    if (!hit.prop) {
        model_->clearSelection();
        return;
    }
    auto* actor = vtkActor::SafeDownCast(hit.prop);
    if (const Id node = textured_->nodeOf(actor); node != kNoId) {
        const BuiltHlod& built = model_->built();
        if (built.build->tree->nodes[node].isLeaf())
            model_->selectInstance(built.build->tree->nodes[node].instance);
        else
            model_->selectClusterNode(node);
        return;
    }
    if (actor == previewActor_.Get()) {
        const Id node = cellId(actor, kNodeIdArray, hit.cell);
        const BuiltHlod& built = model_->built();
        if (node < built.build->tree->nodes.size() && built.build->tree->nodes[node].isLeaf())
            model_->selectInstance(built.build->tree->nodes[node].instance);
        else
            model_->selectClusterNode(node);
        return;
    }
    if (actor == clusterActor_.Get()) {
        model_->selectInstance(cellId(actor, SceneActors::kInstanceIdArray, hit.cell));
        return;
    }
    const auto& sceneActors = viewport_->sceneActors();
    if (!sceneActors) return;
    const auto& actors = sceneActors->actors();
    for (std::size_t part = 0; part < actors.size(); ++part)
        if (actors[part].Get() == actor) {
            model_->selectInstance(sceneActors->instanceOf(part, hit.cell));
            return;
        }
}

} // namespace hlod::widgets
