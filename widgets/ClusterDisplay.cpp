// VTK data for the Clusters and HLOD preview modes (see ClusterDisplay.h).
#include "widgets/ClusterDisplay.h"
#include "widgets/TexturedPreview.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include "pipeline/view/TreeViews.h"
#include "widgets/SceneActors.h"

namespace hlod::widgets {

namespace {

// Segments per great circle of a bounding sphere: round enough at any zoom, cheap for the
// thousands of spheres of a large level.
constexpr int kCircleSegments = 48;

const glm::vec3 kUnclusteredColor{0.6f, 0.6f, 0.6f};
// Saturated magenta: a hue no cluster or depth colour takes (categoryColor, depthColor), at
// full saturation where they have 0.62 (issue 31 #9: the orange it replaces was close to a
// cluster colour and to depth 1's).
const glm::vec3 kHighlightColor{1.0f, 0.0f, 0.85f};

struct LineBuilder {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    vtkNew<vtkUnsignedCharArray> colors;

    LineBuilder() {
        colors->SetName("Colors");
        colors->SetNumberOfComponents(3);
    }
    vtkIdType point(const glm::dvec3& p, const glm::vec3& c) {
        const unsigned char rgb[3] = {static_cast<unsigned char>(std::lround(c.r * 255.0f)),
                                      static_cast<unsigned char>(std::lround(c.g * 255.0f)),
                                      static_cast<unsigned char>(std::lround(c.b * 255.0f))};
        colors->InsertNextTypedTuple(rgb);
        return points->InsertNextPoint(p.x, p.y, p.z);
    }
    void segment(vtkIdType a, vtkIdType b) {
        const vtkIdType ids[2] = {a, b};
        lines->InsertNextCell(2, ids);
    }
    void sphere(const Sphere& s, const glm::vec3& c) {
        // One circle in each coordinate plane through the centre.
        for (int axis = 0; axis < 3; ++axis) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            vtkIdType first = -1, previous = -1;
            for (int i = 0; i < kCircleSegments; ++i) {
                const double a = 2.0 * std::numbers::pi * i / kCircleSegments;
                glm::dvec3 p = s.center;
                p[u] += s.radius * std::cos(a);
                p[v] += s.radius * std::sin(a);
                const vtkIdType id = point(p, c);
                if (previous >= 0) segment(previous, id);
                if (first < 0) first = id;
                previous = id;
            }
            segment(previous, first);
        }
    }
    void box(const Aabb& b, const glm::vec3& c) {
        std::array<vtkIdType, 8> corner{};
        for (int i = 0; i < 8; ++i)
            corner[i] = point({(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                               (i & 4) ? b.max.z : b.min.z},
                              c);
        // Corners differing in exactly one bit share an edge.
        for (int i = 0; i < 8; ++i)
            for (int bit : {1, 2, 4})
                if (!(i & bit)) segment(corner[i], corner[i | bit]);
    }
    vtkSmartPointer<vtkPolyData> finish() {
        auto poly = vtkSmartPointer<vtkPolyData>::New();
        poly->SetPoints(points);
        poly->SetLines(lines);
        poly->GetPointData()->SetScalars(colors);
        return poly;
    }
};

} // namespace

glm::vec3 clusterColor(Id label) { return categoryColor(label); }

glm::vec3 clusterColorOf(Id node, const std::vector<int>* labels) {
    if (labels && node < labels->size() && (*labels)[node] >= 0)
        return clusterColor(static_cast<Id>((*labels)[node]));
    return clusterColor(node);
}

glm::vec3 highlightColor() { return kHighlightColor; }

glm::vec3 depthColor(int depth) {
    // 8 colours, then repeat; each depth's hue is far from the depths next to it (issue 31 #9:
    // a rainbow order made adjacent depths look alike) and from the highlight's magenta.
    static constexpr std::array<std::array<float, 3>, 8> kColors{{{0.90f, 0.22f, 0.20f},
                                                                  {0.25f, 0.50f, 0.90f},
                                                                  {0.93f, 0.85f, 0.20f},
                                                                  {0.55f, 0.35f, 0.85f},
                                                                  {0.45f, 0.80f, 0.25f},
                                                                  {0.95f, 0.55f, 0.15f},
                                                                  {0.20f, 0.75f, 0.70f},
                                                                  {0.78f, 0.88f, 0.30f}}};
    const auto& c = kColors[static_cast<std::size_t>(std::max(depth, 0)) % kColors.size()];
    return {c[0], c[1], c[2]};
}

ClusterColoring::ClusterColoring(const Scene& scene) {
    MergedGeometry geometry(SceneActors::kInstanceIdArray);
    ranges_.reserve(scene.instances.size());
    for (Id i = 0; i < scene.instances.size(); ++i)
        ranges_.push_back(geometry.addInstance(scene, i, i, kUnclusteredColor));
    poly_ = geometry.finish();
}

std::vector<Id> ClusterColoring::colorByLevel(const ClusterTree& tree, int level,
                                              const std::vector<int>* labels) {
    const std::vector<Id> cut = nodesAtLevel(tree, level);
    const std::vector<int> cluster = clusterOfInstances(tree, cut, ranges_.size());
    for (std::size_t i = 0; i < ranges_.size(); ++i)
        recolor(*poly_, ranges_[i],
                cluster[i] < 0 ? kUnclusteredColor : clusterColorOf(cut[cluster[i]], labels));
    return cut;
}

vtkSmartPointer<vtkPolyData> boundsWireframe(const ClusterTree& tree, const std::vector<Id>& nodes,
                                             BoundsShape shape, const std::vector<int>* labels) {
    LineBuilder lines;
    for (Id n : nodes) {
        if (n >= tree.nodes.size()) continue;
        const ClusterNode& node = tree.nodes[n];
        if (shape == BoundsShape::Spheres && node.sphere.radius > 0.0)
            lines.sphere(node.sphere, clusterColorOf(n, labels));
        else if (shape == BoundsShape::Boxes && !node.box.empty())
            lines.box(node.box, clusterColorOf(n, labels));
    }
    return lines.finish();
}

vtkSmartPointer<vtkPolyData> hlodPreview(const Scene& scene, const NodeOutput& build,
                                         const std::vector<Id>& drawList,
                                         const std::vector<int>* depths, bool leaveOutTextured) {
    MergedGeometry geometry(kNodeIdArray);
    const ClusterTree& tree = *build.tree;
    for (Id n : drawList) {
        if (n >= tree.nodes.size()) continue;
        if (leaveOutTextured && TexturedPreview::draws(scene, build, n)) continue;
        std::optional<glm::vec3> tint;
        if (depths && n < depths->size()) tint = depthColor((*depths)[n]);
        const ClusterNode& node = tree.nodes[n];
        if (node.isLeaf()) {
            if (node.instance < scene.instances.size())
                geometry.addInstance(scene, node.instance, n, tint);
        } else if (n < build.bake->nodes.size()) {
            geometry.addProxy(build.bake->nodes[n].proxy, build.bake->nodes[n].frame, n, tint);
        }
    }
    return geometry.finish();
}

vtkSmartPointer<vtkPolyData> selectionHighlight(const Scene& scene,
                                                const std::vector<Id>& instances) {
    MergedGeometry geometry(SceneActors::kInstanceIdArray);
    for (Id i : instances)
        if (i < scene.instances.size()) geometry.addInstance(scene, i, i, kHighlightColor);
    return geometry.finish();
}

} // namespace hlod::widgets

namespace hlod::widgets {

vtkSmartPointer<vtkPolyData> previewHighlight(const Scene& scene, const NodeOutput& build,
                                              const std::vector<Id>& drawList,
                                              const std::vector<Id>& instances) {
    MergedGeometry geometry(kNodeIdArray);
    const ClusterTree& tree = *build.tree;
    for (Id n : drawList) {
        if (n >= tree.nodes.size()) continue;
        const std::vector<Id> below = instancesBelow(tree, n);
        const bool touched = std::any_of(below.begin(), below.end(), [&](Id i) {
            return std::binary_search(instances.begin(), instances.end(), i);
        });
        if (!touched) continue;
        const ClusterNode& node = tree.nodes[n];
        if (node.isLeaf()) {
            if (node.instance < scene.instances.size())
                geometry.addInstance(scene, node.instance, n, kHighlightColor);
        } else if (n < build.bake->nodes.size()) {
            geometry.addProxy(build.bake->nodes[n].proxy, build.bake->nodes[n].frame, n,
                              kHighlightColor);
        }
    }
    return geometry.finish();
}

} // namespace hlod::widgets
