// Turns an hlod::Scene into VTK actors: per-instance actors for small scenes, per-material
// merged world-space geometry for large ones (see SceneActors.h for why).
#include "widgets/SceneActors.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnsignedIntArray.h>

#include "pipeline/io/Import.h"
#include "widgets/VtkSurfaceLook.h"

namespace hlod::widgets {

namespace {

float toSrgb(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// Below this alpha a material is drawn translucent.
constexpr float kOpaqueAlpha = 0.99f;

unsigned char toByte(float c) { return static_cast<unsigned char>(std::lround(c * 255.0f)); }

// Growing arrays for one polydata; reserve() first, then append meshes.
struct PolyBuilder {
    vtkNew<vtkFloatArray> points;
    vtkNew<vtkFloatArray> normals;
    vtkNew<vtkUnsignedCharArray> colors;
    vtkNew<vtkIdTypeArray> offsets;
    vtkNew<vtkIdTypeArray> connectivity;
    vtkNew<vtkUnsignedIntArray> instanceIds;
    vtkNew<vtkFloatArray> uvs;
    bool withColors = false;
    bool withUvs = false;
    int colorComponents = 3; // 4 carries the material's opacity per vertex
    bool withInstanceIds = false;
    vtkIdType vertexCount = 0;
    vtkIdType triangleCount = 0;

    void reserve(vtkIdType vertices, vtkIdType triangles) {
        points->SetNumberOfComponents(3);
        points->SetNumberOfTuples(vertices);
        normals->SetName("Normals");
        normals->SetNumberOfComponents(3);
        normals->SetNumberOfTuples(vertices);
        if (withColors) {
            colors->SetName("Colors");
            colors->SetNumberOfComponents(colorComponents);
            colors->SetNumberOfTuples(vertices);
        }
        offsets->SetNumberOfTuples(triangles + 1);
        connectivity->SetNumberOfTuples(triangles * 3);
        if (withInstanceIds) {
            instanceIds->SetName(SceneActors::kInstanceIdArray);
            instanceIds->SetNumberOfTuples(triangles);
        }
        if (withUvs) {
            uvs->SetName("TCoords");
            uvs->SetNumberOfComponents(2);
            uvs->SetNumberOfTuples(vertices);
        }
    }

    // Appends `mesh` transformed by `world` (identity for per-mesh data). `fallback` colours the
    // vertices of meshes without vertex colours when the builder stores colours; `tint`
    // (linear) multiplies vertex colours (textured parts: the base colour factor).
    void append(const Mesh& mesh, const glm::dmat4& world, const glm::vec4& fallback, Id instance,
                const glm::vec4& tint = glm::vec4(1.0f)) {
        const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
        float* p = points->GetPointer(vertexCount * 3);
        float* n = normals->GetPointer(vertexCount * 3);
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const glm::dvec3 wp =
                glm::dvec3(world * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0));
            // Importers guarantee normals; a short array still must not read out of bounds.
            const glm::dvec3 local =
                i < mesh.normals.size() ? glm::dvec3(mesh.normals[i]) : glm::dvec3(0, 0, 1);
            glm::dvec3 wn = normalMatrix * local;
            const double length = glm::length(wn);
            wn = length > 0.0 ? wn / length : glm::dvec3(0.0, 0.0, 1.0);
            for (int c = 0; c < 3; ++c) {
                p[3 * i + c] = static_cast<float>(wp[c]);
                n[3 * i + c] = static_cast<float>(wn[c]);
            }
        }
        if (withColors) {
            const int channels = colorComponents;
            unsigned char* rgb = colors->GetPointer(vertexCount * channels);
            for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
                const glm::vec4 c =
                    i < mesh.colors.size() ? linearToDisplay(tint * mesh.colors[i]) : fallback;
                for (int k = 0; k < channels; ++k)
                    rgb[channels * i + k] = toByte(c[k]);
            }
        }
        if (withUvs) {
            float* t = uvs->GetPointer(vertexCount * 2);
            for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
                const glm::vec2 uv = i < mesh.uvs.size() ? mesh.uvs[i] : glm::vec2(0.0f);
                t[2 * i] = uv.x;
                t[2 * i + 1] = uv.y;
            }
        }
        vtkIdType* off = offsets->GetPointer(0);
        vtkIdType* conn = connectivity->GetPointer(0);
        const std::size_t triangles = mesh.triangleCount();
        for (std::size_t t = 0; t < triangles; ++t) {
            const vtkIdType cell = triangleCount + static_cast<vtkIdType>(t);
            off[cell] = cell * 3;
            for (int k = 0; k < 3; ++k)
                conn[cell * 3 + k] = vertexCount + mesh.indices[3 * t + k];
            if (withInstanceIds) instanceIds->SetValue(cell, instance);
        }
        vertexCount += static_cast<vtkIdType>(mesh.positions.size());
        triangleCount += static_cast<vtkIdType>(triangles);
    }

    vtkSmartPointer<vtkPolyData> finish() {
        offsets->SetValue(triangleCount, triangleCount * 3);
        auto poly = vtkSmartPointer<vtkPolyData>::New();
        vtkNew<vtkPoints> pts;
        pts->SetData(points);
        poly->SetPoints(pts);
        vtkNew<vtkCellArray> cells;
        cells->SetData(offsets, connectivity);
        poly->SetPolys(cells);
        poly->GetPointData()->SetNormals(normals);
        if (withColors) poly->GetPointData()->SetScalars(colors);
        if (withUvs) poly->GetPointData()->SetTCoords(uvs);
        // Added, not made active: the mapper must not colour by instance id.
        if (withInstanceIds) poly->GetCellData()->AddArray(instanceIds);
        return poly;
    }
};

vtkSmartPointer<vtkMatrix4x4> toVtk(const glm::dmat4& m) {
    auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col)
            matrix->SetElement(row, col, m[col][row]); // glm is column-major
    return matrix;
}

// The decoded texture `instance` is drawn with, null when untextured (no texture, unreadable,
// or the mesh has no uvs).
std::shared_ptr<const RgbaImage> textureOf(const Scene& scene, Id instance) {
    const Mesh& mesh = scene.meshes[scene.instances[instance].mesh];
    if (mesh.uvs.size() != mesh.positions.size() || mesh.material >= scene.materials.size())
        return nullptr;
    const Id t = scene.materials[mesh.material].texture;
    if (t >= scene.textures.size()) return nullptr;
    const auto& image = scene.textures[t].image;
    return image && !image->empty() ? image : nullptr;
}

// Textured parts show base colour factor x texture; untextured ones the effective colour.
glm::vec4 partColor(const Material& material, bool textured) {
    return linearToDisplay(textured ? material.baseColor : material.effectiveColor());
}

void applyLook(vtkActor& actor, const ScenePart& part) {
    vtkProperty* property = actor.GetProperty();
    property->SetColor(part.color.r, part.color.g, part.color.b);
    // Fully transparent materials would vanish; keep them faintly visible. Opacity only where
    // the material blends (an OPAQUE material's alpha is ignored, as engines ignore it).
    const bool blends = part.look.alphaMode == AlphaMode::Blend;
    property->SetOpacity(
        blends && part.color.a < kOpaqueAlpha ? std::max(0.05, double(part.color.a)) : 1.0);
    property->SetInterpolationToPhong();
    property->SetAmbient(0.1);
    property->SetDiffuse(0.8);
    property->SetSpecular(0.12);
    property->SetSpecularPower(24.0);
}

} // namespace

glm::vec4 linearToDisplay(const glm::vec4& linear) {
    return {toSrgb(linear.r), toSrgb(linear.g), toSrgb(linear.b), std::clamp(linear.a, 0.0f, 1.0f)};
}

int suggestedUpAxis(const Scene& scene) {
    if (scene.sourceFiles.empty()) return 1;
    const bool allCad =
        std::all_of(scene.sourceFiles.begin(), scene.sourceFiles.end(),
                    [](const auto& f) { return formatForPath(f) == SceneFormat::Cad; });
    return allCad ? 2 : 1;
}

std::shared_ptr<SceneActors> SceneActors::build(const Scene& scene,
                                                const SceneActorsOptions& options) {
    auto result = std::shared_ptr<SceneActors>(new SceneActors());
    result->instanceCount_ = scene.instances.size();
    if (scene.instances.size() > options.mergeAbove)
        result->buildMerged(scene, std::max<std::size_t>(options.maxMergedParts, 1));
    else
        result->buildPerInstance(scene);

    Aabb box;
    result->fitPoints_.reserve(scene.instances.size() * 8);
    for (Id i = 0; i < scene.instances.size(); ++i) {
        const Aabb b = scene.instanceBounds(i);
        result->triangleCount_ += scene.meshes[scene.instances[i].mesh].triangleCount();
        if (b.empty()) continue;
        box.expand(b);
        for (int c = 0; c < 8; ++c)
            result->fitPoints_.emplace_back((c & 1) ? b.max.x : b.min.x,
                                            (c & 2) ? b.max.y : b.min.y,
                                            (c & 4) ? b.max.z : b.min.z);
    }
    if (!box.empty())
        result->bounds_ = {box.min.x, box.max.x, box.min.y, box.max.y, box.min.z, box.max.z};
    return result;
}

void SceneActors::buildPerInstance(const Scene& scene) {
    std::vector<vtkSmartPointer<vtkPolyData>> meshData(scene.meshes.size());
    for (Id i = 0; i < scene.instances.size(); ++i) {
        const MeshInstance& instance = scene.instances[i];
        const Mesh& mesh = scene.meshes[instance.mesh];
        if (mesh.triangleCount() == 0) continue;
        const std::shared_ptr<const RgbaImage> texture = textureOf(scene, i);
        if (!meshData[instance.mesh]) {
            PolyBuilder builder;
            builder.withColors = !mesh.colors.empty();
            builder.withUvs = texture != nullptr;
            builder.reserve(static_cast<vtkIdType>(mesh.vertexCount()),
                            static_cast<vtkIdType>(mesh.triangleCount()));
            const Id m = mesh.material < scene.materials.size() ? mesh.material : 0;
            builder.append(mesh, glm::dmat4(1.0), glm::vec4(1.0f), instance.mesh,
                           texture ? scene.materials[m].baseColor : glm::vec4(1.0f));
            meshData[instance.mesh] = builder.finish();
        }
        ScenePart part;
        part.polyData = meshData[instance.mesh];
        part.transform = scene.instanceTransform(i);
        part.material = mesh.material < scene.materials.size() ? mesh.material : 0;
        part.instance = i;
        const Material& material = scene.materials[part.material];
        part.color = partColor(material, texture != nullptr);
        part.vertexColors = !mesh.colors.empty();
        part.texture = texture;
        part.look = materialLookOf(scene, part.material, texture != nullptr);
        parts_.push_back(std::move(part));
    }
}

namespace {

// Instances that end up in one merged polydata, counted before anything is allocated.
struct MergeGroup {
    std::vector<Id> instances;
    vtkIdType vertices = 0;
    vtkIdType triangles = 0;
    bool anyColors = false;

    void add(const Scene& scene, Id instance) {
        const Mesh& mesh = scene.meshes[scene.instances[instance].mesh];
        instances.push_back(instance);
        vertices += static_cast<vtkIdType>(mesh.vertexCount());
        triangles += static_cast<vtkIdType>(mesh.triangleCount());
        anyColors = anyColors || !mesh.colors.empty();
    }
};

Id materialOf(const Scene& scene, Id instance) {
    const Id material = scene.meshes[scene.instances[instance].mesh].material;
    return material < scene.materials.size() ? material : 0;
}

// Display colour of every material, computed once.
std::vector<glm::vec4> displayColors(const Scene& scene) {
    std::vector<glm::vec4> colors;
    colors.reserve(scene.materials.size());
    for (const Material& material : scene.materials)
        colors.push_back(linearToDisplay(material.effectiveColor()));
    return colors;
}

} // namespace

void SceneActors::buildMerged(const Scene& scene, std::size_t maxParts) {
    const std::vector<glm::vec4> colors = displayColors(scene);
    std::vector<MergeGroup> byMaterial(scene.materials.size());
    std::vector<std::shared_ptr<const RgbaImage>> textures(scene.instances.size());
    for (Id i = 0; i < scene.instances.size(); ++i) {
        byMaterial[materialOf(scene, i)].add(scene, i);
        textures[i] = textureOf(scene, i);
    }
    const auto used = static_cast<std::size_t>(std::count_if(
        byMaterial.begin(), byMaterial.end(), [](const MergeGroup& g) { return g.triangles > 0; }));

    if (used <= maxParts) {
        layout_ = Layout::PerMaterial;
        for (Id material = 0; material < byMaterial.size(); ++material) {
            const MergeGroup& group = byMaterial[material];
            if (group.triangles == 0) continue;
            // Textured only when every instance can be (all have uvs).
            const bool textured = std::all_of(group.instances.begin(), group.instances.end(),
                                              [&](Id i) { return textures[i] != nullptr; });
            const Material& m = scene.materials[material];
            ScenePart part;
            part.material = material;
            part.color = partColor(m, textured);
            part.vertexColors = group.anyColors;
            PolyBuilder builder;
            builder.withColors = group.anyColors;
            builder.withUvs = textured;
            builder.withInstanceIds = true;
            builder.reserve(group.vertices, group.triangles);
            for (Id i : group.instances)
                builder.append(scene.meshes[scene.instances[i].mesh], scene.instanceTransform(i),
                               part.color, i, textured ? m.baseColor : glm::vec4(1.0f));
            part.polyData = builder.finish();
            if (textured) part.texture = textures[group.instances.front()];
            part.look = materialLookOf(scene, material, textured);
            parts_.push_back(std::move(part));
        }
        return;
    }
    buildByOpacity(scene, colors, textures);
}

// Too many materials for one actor each (TORCS has one per object): one polydata per look,
// with each material's colour (and opacity) stored per vertex. A look is the texture, alpha
// mode and cut-off, sidedness and emission; untextured materials are opaque or translucent by
// their colour's alpha.
void SceneActors::buildByOpacity(const Scene& scene, const std::vector<glm::vec4>& colors,
                                 const std::vector<std::shared_ptr<const RgbaImage>>& textures) {
    layout_ = Layout::ByOpacity;
    using Key = std::tuple<const RgbaImage*, int, float, bool, float, float, float, bool>;
    std::map<Key, MergeGroup> groups;
    std::map<Key, VtkMaterialLook> looks;
    for (Id i = 0; i < scene.instances.size(); ++i) {
        const Id material = materialOf(scene, i);
        VtkMaterialLook look = materialLookOf(scene, material, textures[i] != nullptr);
        if (!textures[i]) {
            look.alphaMode =
                colors[material].a < kOpaqueAlpha ? AlphaMode::Blend : AlphaMode::Opaque;
            look.alphaCutoff = 0.5f;
        }
        const Key key{textures[i].get(), static_cast<int>(look.alphaMode),
                      look.alphaCutoff,  look.doubleSided,
                      look.emissive.r,   look.emissive.g,
                      look.emissive.b,   look.emissiveTimesTexture};
        groups[key].add(scene, i);
        looks[key] = look;
    }
    for (auto& [key, group] : groups) {
        if (group.triangles == 0) continue;
        const bool isTextured = std::get<0>(key) != nullptr;
        const VtkMaterialLook& look = looks[key];
        PolyBuilder builder;
        builder.withColors = true;
        builder.colorComponents = look.alphaMode == AlphaMode::Blend ? 4 : 3;
        builder.withUvs = isTextured;
        builder.withInstanceIds = true;
        builder.reserve(group.vertices, group.triangles);
        for (Id i : group.instances) {
            const Material& m = scene.materials[materialOf(scene, i)];
            builder.append(scene.meshes[scene.instances[i].mesh], scene.instanceTransform(i),
                           isTextured ? partColor(m, true) : colors[materialOf(scene, i)], i,
                           isTextured ? m.baseColor : glm::vec4(1.0f));
        }
        ScenePart part;
        part.polyData = builder.finish();
        part.material = kNoId;
        part.color = glm::vec4(1.0f);
        part.vertexColors = true;
        if (isTextured) part.texture = textures[group.instances.front()];
        part.look = look;
        parts_.push_back(std::move(part));
    }
}

const std::vector<vtkSmartPointer<vtkActor>>& SceneActors::actors() {
    if (!actors_.empty() || parts_.empty()) return actors_;
    actors_.reserve(parts_.size());
    for (const ScenePart& part : parts_) {
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputData(part.polyData);
        mapper->SetScalarVisibility(part.vertexColors);
        mapper->SetColorModeToDirectScalars();
        auto actor = vtkSmartPointer<vtkActor>::New();
        actor->SetMapper(mapper);
        if (part.transform != glm::dmat4(1.0)) actor->SetUserMatrix(toVtk(part.transform));
        applyLook(*actor, part);
        if (part.texture) {
            auto& texture = textures_[part.texture.get()];
            if (!texture) texture = makeVtkTexture(*part.texture);
            actor->SetTexture(texture);
        }
        applyMaterialLook(*actor, part.look);
        actors_.push_back(actor);
    }
    return actors_;
}

Id SceneActors::instanceOf(std::size_t part, vtkIdType cell) const {
    if (part >= parts_.size() || cell < 0) return kNoId;
    const ScenePart& p = parts_[part];
    if (cell >= p.polyData->GetNumberOfCells()) return kNoId;
    if (p.instance != kNoId) return p.instance;
    auto* ids =
        vtkUnsignedIntArray::SafeDownCast(p.polyData->GetCellData()->GetArray(kInstanceIdArray));
    return ids ? ids->GetValue(cell) : kNoId;
}

} // namespace hlod::widgets
