#include "OffscreenRenderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include "pipeline/core/Error.h"
#include "widgets/VtkSurfaceLook.h"

namespace hlod::cli {

namespace {

using widgets::applyMaterialLook;
using widgets::makeVtkTexture;
using widgets::VtkMaterialLook;

float toSrgb(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

unsigned char toByte(float c) {
    return static_cast<unsigned char>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

// `factor` multiplies the vertex colours (Textured shading: the material's base colour factor,
// since VTK ignores the actor colour when a mesh has scalars); RGBA scalars when `withAlpha`.
vtkSmartPointer<vtkPolyData>
makePoly(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
         const std::vector<std::uint32_t>& indices, const std::vector<glm::vec4>* colorsLinear,
         const std::vector<glm::u8vec4>* colors8, const std::vector<glm::vec2>* uvs = nullptr,
         glm::vec4 factor = glm::vec4(1.0f), bool withAlpha = false) {
    const auto nv = static_cast<vtkIdType>(positions.size());
    const auto nt = static_cast<vtkIdType>(indices.size() / 3);
    vtkNew<vtkFloatArray> points;
    points->SetNumberOfComponents(3);
    points->SetNumberOfTuples(nv);
    std::copy_n(&positions[0].x, nv * 3, points->GetPointer(0));
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> pts;
    pts->SetData(points);
    poly->SetPoints(pts);
    vtkNew<vtkIdTypeArray> offsets;
    vtkNew<vtkIdTypeArray> connectivity;
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
        n->SetName("Normals");
        n->SetNumberOfComponents(3);
        n->SetNumberOfTuples(nv);
        std::copy_n(&normals[0].x, nv * 3, n->GetPointer(0));
        poly->GetPointData()->SetNormals(n);
    }
    if ((colorsLinear && colorsLinear->size() == positions.size()) ||
        (colors8 && colors8->size() == positions.size())) {
        const int comps = withAlpha ? 4 : 3;
        vtkNew<vtkUnsignedCharArray> c;
        c->SetName("Colors");
        c->SetNumberOfComponents(comps);
        c->SetNumberOfTuples(nv);
        unsigned char* p = c->GetPointer(0);
        for (vtkIdType i = 0; i < nv; ++i) {
            const glm::vec4 lin =
                factor * (colorsLinear
                              ? (*colorsLinear)[static_cast<std::size_t>(i)]
                              : glm::vec4((*colors8)[static_cast<std::size_t>(i)]) / 255.0f);
            for (int k = 0; k < 3; ++k)
                p[comps * i + k] = toByte(toSrgb(lin[k]));
            if (withAlpha) p[comps * i + 3] = toByte(lin.a);
        }
        poly->GetPointData()->SetScalars(c);
    }
    if (uvs && uvs->size() == positions.size()) {
        vtkNew<vtkFloatArray> t;
        t->SetName("TCoords");
        t->SetNumberOfComponents(2);
        t->SetNumberOfTuples(nv);
        std::copy_n(&(*uvs)[0].x, nv * 2, t->GetPointer(0));
        poly->GetPointData()->SetTCoords(t);
    }
    return poly;
}

// Mean linear RGB of 8-bit vertex colours (white when there are none).
glm::vec3 meanColor(const std::vector<glm::u8vec4>& colors) {
    if (colors.empty()) return glm::vec3(1.0f);
    glm::dvec3 sum(0.0);
    for (const glm::u8vec4& c : colors)
        sum += glm::dvec3(c.r, c.g, c.b) / 255.0;
    return glm::vec3(sum / static_cast<double>(colors.size()));
}

vtkSmartPointer<vtkMatrix4x4> toVtk(const glm::dmat4& m) {
    auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col)
            matrix->SetElement(row, col, m[col][row]); // glm is column-major
    return matrix;
}

} // namespace

struct OffscreenRenderer::Impl {
    int width = 0, height = 0;
    Shading shading = Shading::Geometry;
    vtkSmartPointer<vtkRenderWindow> window;
    std::vector<vtkSmartPointer<vtkRenderer>> layers;
    std::vector<std::vector<vtkSmartPointer<vtkActor>>> actors; // per layer
    std::vector<std::vector<int>> visible;                      // per layer
    // Geometry shared by every drawable of the same source mesh (key: Mesh address + colour
    // mode), so a mesh instanced N times is one polydata.
    std::map<std::pair<const void*, bool>, vtkSmartPointer<vtkPolyData>> meshes;
    std::map<const RgbaImage*, vtkSmartPointer<vtkTexture>> textures; // uploaded once each

    vtkTexture* textureFor(const RgbaImage& image) {
        auto& texture = textures[&image];
        if (texture) return texture;
        texture = makeVtkTexture(image);
        return texture;
    }

    // The look on the actor for this renderer's shading (see Shading): sides always; alpha,
    // texture and emission in Textured; emission (flat) in Colour.
    void applyLook(vtkActor& actor, const SurfaceLook& look, bool hasUvs) {
        VtkMaterialLook vtk;
        vtk.doubleSided = look.doubleSided;
        if (shading == Shading::Textured) {
            const bool textured = look.texture && hasUvs;
            if (textured) actor.SetTexture(textureFor(*look.texture));
            vtk.alphaMode = look.alphaMode;
            vtk.alphaCutoff = look.alphaCutoff;
            vtk.emissiveTimesTexture = textured && look.emissiveIsTexture;
            vtk.emissive =
                look.emissive * (vtk.emissiveTimesTexture ? glm::vec3(1.0f) : look.emissiveMean);
            if (look.alphaMode == AlphaMode::Blend)
                actor.GetProperty()->SetOpacity(std::clamp(double(look.factor.a), 0.05, 1.0));
        } else if (shading == Shading::Colour) {
            vtk.emissive = look.emissive * look.emissiveMean;
        }
        applyMaterialLook(actor, vtk);
    }

    vtkSmartPointer<vtkActor> makeActor(vtkPolyData* poly, const glm::vec4& color,
                                        bool vertexColors) {
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputData(poly);
        mapper->SetScalarVisibility(vertexColors);
        mapper->SetColorModeToDirectScalars();
        mapper->StaticOn(); // the data never changes: skip the pipeline update per render
        auto actor = vtkSmartPointer<vtkActor>::New();
        actor->SetMapper(mapper);
        vtkProperty* p = actor->GetProperty();
        if (shading == Shading::Geometry) {
            p->SetColor(0.78, 0.78, 0.76);
        } else if (vertexColors) {
            p->SetColor(1.0, 1.0, 1.0);
        } else {
            p->SetColor(toSrgb(color.r), toSrgb(color.g), toSrgb(color.b));
        }
        p->SetAmbient(0.15);
        p->SetDiffuse(0.85);
        p->SetSpecular(0.0);
        actor->VisibilityOff();
        return actor;
    }

    void setCamera(int layer, const Camera& c) {
        vtkCamera* cam = layers[static_cast<std::size_t>(layer)]->GetActiveCamera();
        cam->SetPosition(c.eye.x, c.eye.y, c.eye.z);
        cam->SetFocalPoint(c.target.x, c.target.y, c.target.z);
        cam->SetViewUp(c.up.x, c.up.y, c.up.z);
        cam->SetViewAngle(glm::degrees(c.fovY));
        cam->SetClippingRange(c.nearPlane, c.farPlane);
    }

    void activate(int layer) {
        for (std::size_t i = 0; i < layers.size(); ++i)
            layers[i]->SetDraw(static_cast<int>(i) == layer ? 1 : 0);
    }
};

OffscreenRenderer::OffscreenRenderer(int width, int height, Shading shading)
    : impl_(std::make_unique<Impl>()) {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display)
        throw Error(ErrorCode::InvalidArgument,
                    "bench renders with VTK, which needs an X display here (Debian's VTK has "
                    "no EGL/OSMesa): DISPLAY is unset; run it under xvfb-run -a");
    vtkOutputWindow::GetInstance()->SetDisplayModeToNever(); // no VTK chatter on stderr
    impl_->width = width;
    impl_->height = height;
    impl_->shading = shading;
    impl_->window = vtkSmartPointer<vtkRenderWindow>::New();
    impl_->window->SetOffScreenRendering(1);
    impl_->window->SetMultiSamples(0);
    impl_->window->SetSize(width, height);
}

OffscreenRenderer::~OffscreenRenderer() { close(); }

void OffscreenRenderer::close() {
    if (impl_ && impl_->window) {
        impl_->window->Finalize();
        impl_->window = nullptr;
    }
}

int OffscreenRenderer::addLayer() {
    auto r = vtkSmartPointer<vtkRenderer>::New();
    r->SetBackground(0.93, 0.94, 0.96);
    r->SetDraw(0);
    // Default headlight (light follows the camera): the same lighting for every layer.
    impl_->window->AddRenderer(r);
    impl_->layers.push_back(r);
    impl_->actors.emplace_back();
    impl_->visible.emplace_back();
    return static_cast<int>(impl_->layers.size()) - 1;
}

int OffscreenRenderer::addMesh(int layer, const Mesh& mesh, const glm::dmat4& world,
                               const glm::vec4& color, const SurfaceLook& look) {
    const bool colour = impl_->shading != Shading::Geometry;
    const bool textured = impl_->shading == Shading::Textured;
    const bool vertexColors = colour && mesh.colors.size() == mesh.positions.size();
    const bool hasUvs = textured && look.texture && mesh.uvs.size() == mesh.positions.size();
    auto& poly = impl_->meshes[{&mesh, vertexColors}];
    if (!poly) {
        // Textured: the factor goes into the vertex colours (one material per Mesh, so the
        // shared polydata is right for every instance).
        poly =
            makePoly(mesh.positions, mesh.normals, mesh.indices,
                     vertexColors ? &mesh.colors : nullptr, nullptr, textured ? &mesh.uvs : nullptr,
                     textured ? look.factor : glm::vec4(1.0f), textured);
    }
    // Colour: vertex colours replace the actor colour (VTK ignores it with scalars).
    auto actor = impl_->makeActor(poly, textured ? look.factor : color, vertexColors);
    impl_->applyLook(*actor, look, hasUvs);
    if (world != glm::dmat4(1.0)) actor->SetUserMatrix(toVtk(world));
    impl_->layers[static_cast<std::size_t>(layer)]->AddActor(actor);
    auto& list = impl_->actors[static_cast<std::size_t>(layer)];
    list.push_back(actor);
    return static_cast<int>(list.size()) - 1;
}

int OffscreenRenderer::addProxy(int layer, const ProxyMesh& proxy, const glm::dmat4& frame) {
    const bool colour = impl_->shading != Shading::Geometry;
    const bool atlas = impl_->shading == Shading::Textured && proxy.hasAtlas();
    // With an atlas the texture carries the whole base colour (ProxyMesh.h).
    auto poly = makePoly(proxy.positions, proxy.normals, proxy.indices, nullptr,
                         colour && !atlas ? &proxy.colors : nullptr, atlas ? &proxy.uvs : nullptr);
    auto actor = impl_->makeActor(poly, glm::vec4(1.0f), colour && !atlas && !proxy.colors.empty());
    SurfaceLook look;
    look.doubleSided = proxy.doubleSided;
    look.emissive = proxy.emissive;
    if (atlas) {
        look.texture = proxy.atlas->image.get();
        look.alphaMode = proxy.atlas->mask ? AlphaMode::Mask : AlphaMode::Opaque;
        look.emissiveIsTexture = true; // the factor is relative to the atlas (ProxyLook.h)
    } else if (proxy.hasAtlas()) {
        // Colour shading of an atlas proxy: the emission rides on the vertex colours' mean.
        look.emissiveMean = meanColor(proxy.colors);
    }
    impl_->applyLook(*actor, look, atlas);
    actor->SetUserMatrix(toVtk(frame));
    impl_->layers[static_cast<std::size_t>(layer)]->AddActor(actor);
    auto& list = impl_->actors[static_cast<std::size_t>(layer)];
    list.push_back(actor);
    return static_cast<int>(list.size()) - 1;
}

SurfaceLook lookOf(const Scene& scene, Id material) {
    SurfaceLook look;
    if (material >= scene.materials.size()) material = 0;
    const Material& m = scene.materials[material];
    look.factor = m.baseColor;
    look.texture = scene.textureImage(material);
    look.alphaMode = m.alphaMode;
    look.alphaCutoff = m.alphaCutoff;
    look.doubleSided = m.doubleSided;
    look.emissive = m.emissive;
    look.emissiveMean = m.emissiveMean;
    look.emissiveIsTexture = m.emissiveTexture != kNoId && m.emissiveTexture == m.texture;
    return look;
}

void OffscreenRenderer::setVisible(int layer, const std::vector<int>& drawables) {
    auto& actors = impl_->actors[static_cast<std::size_t>(layer)];
    auto& visible = impl_->visible[static_cast<std::size_t>(layer)];
    for (int d : visible)
        actors[static_cast<std::size_t>(d)]->VisibilityOff();
    for (int d : drawables)
        actors[static_cast<std::size_t>(d)]->VisibilityOn();
    visible = drawables;
}

void OffscreenRenderer::warmUp(int layer, const Camera& camera) {
    auto& actors = impl_->actors[static_cast<std::size_t>(layer)];
    std::vector<int> all(actors.size());
    for (std::size_t i = 0; i < all.size(); ++i)
        all[i] = static_cast<int>(i);
    setVisible(layer, all);
    render(layer, camera);
    setVisible(layer, {});
}

double OffscreenRenderer::render(int layer, const Camera& camera) {
    impl_->activate(layer);
    impl_->setCamera(layer, camera);
    const auto t0 = std::chrono::steady_clock::now();
    impl_->window->Render();
    impl_->window->WaitForCompletion(); // glFinish
    const auto t1 = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::milli>(t1 - t0).count();
}

RgbImage OffscreenRenderer::readPixels() {
    const int w = impl_->width, h = impl_->height;
    vtkNew<vtkUnsignedCharArray> data;
    impl_->window->GetPixelData(0, 0, w - 1, h - 1, 0, data, 0);
    RgbImage img(w, h);
    const unsigned char* src = data->GetPointer(0);
    const int comps = data->GetNumberOfComponents();
    for (int y = 0; y < h; ++y) {
        const unsigned char* row = src + static_cast<std::size_t>(h - 1 - y) * w * comps;
        for (int x = 0; x < w; ++x)
            img.set(x, y, Rgb(row[x * comps], row[x * comps + 1], row[x * comps + 2]));
    }
    return img;
}

} // namespace hlod::cli
