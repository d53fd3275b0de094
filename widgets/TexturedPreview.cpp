// Per-node textured actors for the HLOD preview, see TexturedPreview.h.
#include "widgets/TexturedPreview.h"

#include <algorithm>

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>

#include "widgets/SceneActors.h"
#include "widgets/VtkSurfaceLook.h"

namespace hlod::widgets {

namespace {

// Positions, normals, uvs and (optional) display colours of one drawable.
vtkSmartPointer<vtkPolyData> makePoly(const std::vector<glm::vec3>& positions,
                                      const std::vector<glm::vec3>& normals,
                                      const std::vector<glm::vec2>& uvs,
                                      const std::vector<std::uint32_t>& indices,
                                      const std::vector<glm::vec4>* colors, glm::vec4 tint) {
    const auto nv = static_cast<vtkIdType>(positions.size());
    const auto nt = static_cast<vtkIdType>(indices.size() / 3);
    vtkNew<vtkFloatArray> p;
    p->SetNumberOfComponents(3);
    p->SetNumberOfTuples(nv);
    std::copy_n(&positions[0].x, nv * 3, p->GetPointer(0));
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> points;
    points->SetData(p);
    poly->SetPoints(points);
    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfTuples(nt + 1);
    connectivity->SetNumberOfTuples(nt * 3);
    for (vtkIdType t = 0; t <= nt; ++t)
        offsets->SetValue(t, t * 3);
    for (vtkIdType i = 0; i < nt * 3; ++i)
        connectivity->SetValue(i, indices[static_cast<std::size_t>(i)]);
    vtkNew<vtkCellArray> cells;
    cells->SetData(offsets, connectivity);
    poly->SetPolys(cells);
    if (normals.size() == positions.size()) {
        vtkNew<vtkFloatArray> n;
        n->SetNumberOfComponents(3);
        n->SetNumberOfTuples(nv);
        std::copy_n(&normals[0].x, nv * 3, n->GetPointer(0));
        poly->GetPointData()->SetNormals(n);
    }
    vtkNew<vtkFloatArray> t;
    t->SetNumberOfComponents(2);
    t->SetNumberOfTuples(nv);
    std::copy_n(&uvs[0].x, nv * 2, t->GetPointer(0));
    poly->GetPointData()->SetTCoords(t);
    if (colors && colors->size() == positions.size()) {
        vtkNew<vtkUnsignedCharArray> c;
        c->SetNumberOfComponents(3);
        c->SetNumberOfTuples(nv);
        for (vtkIdType i = 0; i < nv; ++i) {
            const glm::vec4 d = linearToDisplay(tint * (*colors)[static_cast<std::size_t>(i)]);
            for (int k = 0; k < 3; ++k)
                c->SetValue(i * 3 + k, static_cast<unsigned char>(std::lround(d[k] * 255.0f)));
        }
        poly->GetPointData()->SetScalars(c);
    }
    return poly;
}

vtkSmartPointer<vtkMatrix4x4> toVtk(const glm::dmat4& m) {
    auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col)
            matrix->SetElement(row, col, m[col][row]);
    return matrix;
}

} // namespace

TexturedPreview::~TexturedPreview() { clear(); }

bool TexturedPreview::draws(const Scene& scene, const NodeOutput& build, Id n) {
    if (n >= build.tree->nodes.size()) return false;
    const ClusterNode& node = build.tree->nodes[n];
    if (!node.isLeaf())
        return n < build.bake->nodes.size() && build.bake->nodes[n].proxy.hasAtlas();
    if (node.instance >= scene.instances.size()) return false;
    const Mesh& mesh = scene.meshes[scene.instances[node.instance].mesh];
    return mesh.uvs.size() == mesh.positions.size() && !mesh.indices.empty() &&
           scene.textureImage(mesh.material) != nullptr;
}

vtkTexture* TexturedPreview::textureFor(const RgbaImage& image) {
    auto& texture = textures_[&image];
    if (!texture) texture = makeVtkTexture(image);
    return texture;
}

vtkActor* TexturedPreview::actorFor(const Scene& scene, const NodeOutput& build, Id n) {
    auto& actor = actors_[n];
    if (actor) return actor;
    actor = vtkSmartPointer<vtkActor>::New();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetColorModeToDirectScalars();
    const ClusterNode& node = build.tree->nodes[n];
    if (node.isLeaf()) {
        const MeshInstance& inst = scene.instances[node.instance];
        const Mesh& mesh = scene.meshes[inst.mesh];
        const Material& m = scene.materials[mesh.material];
        auto& poly = meshes_[&mesh];
        if (!poly)
            poly = makePoly(mesh.positions, mesh.normals, mesh.uvs, mesh.indices,
                            mesh.colors.empty() ? nullptr : &mesh.colors, m.baseColor);
        mapper->SetInputData(poly);
        mapper->SetScalarVisibility(!mesh.colors.empty());
        actor->SetUserMatrix(toVtk(scene.instanceTransform(node.instance)));
        const glm::vec4 c = linearToDisplay(m.baseColor);
        actor->GetProperty()->SetColor(c.r, c.g, c.b);
        actor->SetTexture(textureFor(*scene.textureImage(mesh.material)));
        applyMaterialLook(*actor, materialLookOf(scene, mesh.material, true));
    } else {
        const ProxyMesh& proxy = build.bake->nodes[n].proxy;
        mapper->SetInputData(
            makePoly(proxy.positions, proxy.normals, proxy.uvs, proxy.indices, nullptr, {}));
        mapper->SetScalarVisibility(false);
        actor->SetUserMatrix(toVtk(build.bake->nodes[n].frame.matrix()));
        actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
        actor->SetTexture(textureFor(*proxy.atlas->image));
        VtkMaterialLook look;
        look.alphaMode = proxy.atlas->mask ? AlphaMode::Mask : AlphaMode::Opaque;
        look.doubleSided = proxy.doubleSided;
        look.emissive = proxy.emissive; // relative to the atlas (ProxyLook.h)
        look.emissiveTimesTexture = true;
        applyMaterialLook(*actor, look);
    }
    actor->SetMapper(mapper);
    vtkProperty* p = actor->GetProperty();
    p->SetInterpolationToPhong();
    p->SetAmbient(0.1);
    p->SetDiffuse(0.8);
    p->SetSpecular(0.12);
    p->SetSpecularPower(24.0);
    actor->VisibilityOff();
    renderer_->AddActor(actor);
    nodes_[actor.Get()] = n;
    return actor;
}

void TexturedPreview::show(const Scene& scene, const NodeOutput& build,
                           const std::vector<Id>& drawList, bool enabled) {
    if (builtFor_ != &build) {
        clear();
        builtFor_ = &build;
    }
    hide();
    if (!enabled) return;
    for (Id n : drawList) {
        if (!draws(scene, build, n)) continue;
        actorFor(scene, build, n)->VisibilityOn();
        shown_.push_back(n);
    }
}

void TexturedPreview::hide() {
    for (Id n : shown_)
        if (auto it = actors_.find(n); it != actors_.end()) it->second->VisibilityOff();
    shown_.clear();
}

Id TexturedPreview::nodeOf(const vtkActor* actor) const {
    const auto it = nodes_.find(actor);
    return it == nodes_.end() ? kNoId : it->second;
}

void TexturedPreview::clear() {
    for (auto& [n, actor] : actors_)
        renderer_->RemoveActor(actor);
    actors_.clear();
    nodes_.clear();
    meshes_.clear();
    textures_.clear();
    shown_.clear();
    builtFor_ = nullptr;
}

} // namespace hlod::widgets
