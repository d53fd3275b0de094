// World-space merged geometry for VTK (see MergedGeometry.h).
#include "widgets/MergedGeometry.h"

#include <algorithm>
#include <cmath>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnsignedIntArray.h>

#include "widgets/SceneActors.h"

namespace hlod::widgets {

namespace {

unsigned char toByte(float c) {
    return static_cast<unsigned char>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

glm::dvec3 unitOr(const glm::dvec3& v, const glm::dvec3& fallback) {
    const double length = glm::length(v);
    return length > 0.0 ? v / length : fallback;
}

} // namespace

glm::vec3 displayColor(const glm::vec4& linear) { return glm::vec3(linearToDisplay(linear)); }

glm::vec3 categoryColor(std::uint32_t index) {
    // Hue steps by the golden ratio conjugate: consecutive ids land far apart on the wheel.
    // The hues span red through blue-violet (346°..267°) only: magenta and pink are the
    // selection highlight's (issue 31 #9), which no category colour comes near.
    const double turn = std::fmod(0.13 + index * 0.6180339887498949, 1.0);
    const double hue = std::fmod(0.961 + turn * 0.78, 1.0) * 6.0;
    const double s = 0.62, v = 0.92;
    const int sector = static_cast<int>(hue) % 6;
    const double f = hue - std::floor(hue);
    const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    const double rgb[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
    return glm::vec3(glm::dvec3(rgb[sector][0], rgb[sector][1], rgb[sector][2]));
}

MergedGeometry::MergedGeometry(std::string idArrayName) : idArrayName_(std::move(idArrayName)) {}

void MergedGeometry::appendTriangles(const std::vector<std::uint32_t>& indices, std::size_t base,
                                     Id id) {
    const std::size_t vertices = vertexCount() - base;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        // Importers validate indices; a proxy never holds bad ones. Skip rather than read out
        // of bounds if either ever did.
        if (indices[t] >= vertices || indices[t + 1] >= vertices || indices[t + 2] >= vertices)
            continue;
        for (int k = 0; k < 3; ++k)
            connectivity_.push_back(static_cast<vtkIdType>(base + indices[t + k]));
        ids_.push_back(id);
    }
}

VertexRange MergedGeometry::addInstance(const Scene& scene, Id instance, Id id,
                                        std::optional<glm::vec3> color) {
    const MeshInstance& inst = scene.instances[instance];
    const Mesh& mesh = scene.meshes[inst.mesh];
    const glm::dmat4& world = scene.instanceTransform(instance);
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
    const Id material = mesh.material < scene.materials.size() ? mesh.material : 0;
    const Material& m = scene.materials[material];
    const glm::vec4 emitted(m.effectiveEmissive(), 0.0f);
    const glm::vec3 materialColor = displayColor(m.effectiveColor() + emitted);
    const std::size_t base = vertexCount();
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::dvec3 p = glm::dvec3(world * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0));
        const glm::dvec3 local =
            i < mesh.normals.size() ? glm::dvec3(mesh.normals[i]) : glm::dvec3(0, 0, 1);
        const glm::dvec3 n = unitOr(normalMatrix * local, {0, 0, 1});
        const glm::vec3 c = color                    ? *color
                            : i < mesh.colors.size() ? displayColor(mesh.colors[i] + emitted)
                                                     : materialColor;
        for (int k = 0; k < 3; ++k) {
            positions_.push_back(static_cast<float>(p[k]));
            normals_.push_back(static_cast<float>(n[k]));
            colors_.push_back(toByte(c[k]));
        }
    }
    appendTriangles(mesh.indices, base, id);
    return {base, vertexCount() - base};
}

namespace {

// A proxy's vertex colour with its emission added (ProxyMesh.h: relative to the colour when
// it has an atlas, whose texels the colours approximate; the emitted colour itself without).
glm::vec4 withEmission(const ProxyMesh& proxy, const glm::vec4& c) {
    const glm::vec3 e = proxy.hasAtlas() ? proxy.emissive * glm::vec3(c) : proxy.emissive;
    return c + glm::vec4(e, 0.0f);
}

} // namespace

VertexRange MergedGeometry::addProxy(const ProxyMesh& proxy, const RigidFrame& frame, Id id,
                                     std::optional<glm::vec3> color) {
    const std::size_t base = vertexCount();
    for (std::size_t i = 0; i < proxy.positions.size(); ++i) {
        const glm::dvec3 p = frame.origin + frame.rotation * glm::dvec3(proxy.positions[i]);
        const glm::dvec3 n = i < proxy.normals.size()
                                 ? frame.rotation * unitOr(glm::dvec3(proxy.normals[i]), {0, 0, 1})
                                 : glm::dvec3(0, 0, 1);
        const glm::vec3 c =
            color ? *color
            : i < proxy.colors.size()
                ? displayColor(withEmission(proxy, glm::vec4(proxy.colors[i]) / 255.0f))
                : glm::vec3(0.8f);
        for (int k = 0; k < 3; ++k) {
            positions_.push_back(static_cast<float>(p[k]));
            normals_.push_back(static_cast<float>(n[k]));
            colors_.push_back(toByte(c[k]));
        }
    }
    appendTriangles(proxy.indices, base, id);
    return {base, vertexCount() - base};
}

vtkSmartPointer<vtkPolyData> MergedGeometry::finish() {
    const auto vertices = static_cast<vtkIdType>(vertexCount());
    const auto triangles = static_cast<vtkIdType>(triangleCount());
    vtkNew<vtkFloatArray> points;
    points->SetNumberOfComponents(3);
    points->SetNumberOfTuples(vertices);
    std::copy(positions_.begin(), positions_.end(), points->GetPointer(0));
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(vertices);
    std::copy(normals_.begin(), normals_.end(), normals->GetPointer(0));
    vtkNew<vtkUnsignedCharArray> colors;
    colors->SetName("Colors");
    colors->SetNumberOfComponents(3);
    colors->SetNumberOfTuples(vertices);
    std::copy(colors_.begin(), colors_.end(), colors->GetPointer(0));
    vtkNew<vtkIdTypeArray> offsets;
    offsets->SetNumberOfTuples(triangles + 1);
    for (vtkIdType t = 0; t <= triangles; ++t)
        offsets->SetValue(t, 3 * t);
    vtkNew<vtkIdTypeArray> connectivity;
    connectivity->SetNumberOfTuples(triangles * 3);
    std::copy(connectivity_.begin(), connectivity_.end(), connectivity->GetPointer(0));
    vtkNew<vtkUnsignedIntArray> ids;
    ids->SetName(idArrayName_.c_str());
    ids->SetNumberOfTuples(triangles);
    std::copy(ids_.begin(), ids_.end(), ids->GetPointer(0));

    auto poly = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> pts;
    pts->SetData(points);
    poly->SetPoints(pts);
    vtkNew<vtkCellArray> cells;
    cells->SetData(offsets, connectivity);
    poly->SetPolys(cells);
    poly->GetPointData()->SetNormals(normals);
    poly->GetPointData()->SetScalars(colors);
    poly->GetCellData()->AddArray(ids); // not active: the mapper colours by the vertex colours
    positions_.clear();
    normals_.clear();
    colors_.clear();
    connectivity_.clear();
    ids_.clear();
    return poly;
}

void recolor(vtkPolyData& poly, const VertexRange& range, const glm::vec3& color) {
    auto* colors = vtkUnsignedCharArray::SafeDownCast(poly.GetPointData()->GetScalars());
    if (!colors || colors->GetNumberOfComponents() != 3) return;
    const auto end = static_cast<vtkIdType>(range.first + range.count);
    if (end > colors->GetNumberOfTuples()) return;
    unsigned char* rgb = colors->GetPointer(0);
    const unsigned char c[3] = {toByte(color.r), toByte(color.g), toByte(color.b)};
    for (std::size_t v = range.first; v < range.first + range.count; ++v)
        for (int k = 0; k < 3; ++k)
            rgb[3 * v + k] = c[k];
    colors->Modified();
}

} // namespace hlod::widgets
