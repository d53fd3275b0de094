// XCAF document -> hlod::Scene. Based on the OCCT 7.6 XDE user guide (XCAFDoc_ShapeTool,
// XCAFDoc_ColorTool) and XCAFPrs's colour precedence; see CadXcaf.h for the mapping.
#include "pipeline/io/CadXcaf.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>

#include <BRep_Builder.hxx>
#include <Quantity_ColorRGBA.hxx>
#include <TCollection_AsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDF_Tool.hxx>
#include <TDataStd_Name.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include "pipeline/core/Error.h"
#include "pipeline/io/CadTessellation.h"
#include "pipeline/io/InstancingGraph.h"

namespace hlod::cad {

namespace {

// Real assemblies are a handful of levels deep; a deeper chain means a corrupt document.
constexpr int kMaxAssemblyDepth = 256;

std::string entryOf(const TDF_Label& label) {
    TCollection_AsciiString entry;
    TDF_Tool::Entry(label, entry);
    return entry.ToCString();
}

// The label's TDataStd_Name in UTF-8 (TCollection_AsciiString converts to UTF-8 when no
// replacement character is given), or "" for none or for XCAF's generated "=>[0:1:1:n]".
std::string labelName(const TDF_Label& label) {
    Handle(TDataStd_Name) name;
    if (!label.FindAttribute(TDataStd_Name::GetID(), name)) return {};
    const std::string text = TCollection_AsciiString(name->Get()).ToCString();
    if (text.rfind("=>[", 0) == 0) return {};
    return text;
}

// "#rrggbb" of the sRGB colour a user would see in the CAD tool.
std::string hexName(const glm::vec4& linear) {
    const Quantity_Color colour(linear.r, linear.g, linear.b, Quantity_TOC_RGB);
    Standard_Real r = 0, g = 0, b = 0;
    colour.Values(r, g, b, Quantity_TOC_sRGB);
    const auto byte = [](double v) { return static_cast<unsigned>(v * 255.0 + 0.5); };
    char text[16];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(r), byte(g), byte(b));
    return text;
}

class XcafSceneBuilder {
public:
    XcafSceneBuilder(const Handle(TDocStd_Document) & doc, double unitScale,
                     const ImportOptions& options, const std::filesystem::path& file,
                     const Progress& progress)
        : shapes_(XCAFDoc_DocumentTool::ShapeTool(doc->Main())),
          colours_(XCAFDoc_DocumentTool::ColorTool(doc->Main())), unitScale_(unitScale),
          options_(options), file_(file), progress_(progress) {}

    Scene build();

private:
    std::uint64_t countPlacements(const TDF_Label& shape, int depth);
    void visit(const TDF_Label& shape, Id node, const std::optional<glm::vec4>& colour, int depth);
    void addComponents(const TDF_Label& assembly, Id node, const std::optional<glm::vec4>& colour,
                       int depth);
    void addPart(const TDF_Label& part, Id node, const std::optional<glm::vec4>& colour);
    const std::vector<Id>& partMeshes(const TDF_Label& part,
                                      const std::optional<glm::vec4>& colour);
    std::optional<glm::vec4> ownColour(const TDF_Label& label) const;
    FaceColourMap faceColours(const TDF_Label& part) const;
    Id materialFor(const std::optional<glm::vec4>& colour);
    bool visible(const TDF_Label& label) const { return colours_->IsVisible(label); }

    using PartKey = std::tuple<std::string, bool, std::array<float, 4>>;

    Handle(XCAFDoc_ShapeTool) shapes_;
    Handle(XCAFDoc_ColorTool) colours_;
    double unitScale_;
    const ImportOptions& options_;
    std::filesystem::path file_;
    const Progress& progress_;
    std::optional<FaceProgress> faces_;
    // The assembly walk before building: placements under each label (saturating), and the
    // distinct parts it reaches with their face counts (for the progress total).
    std::map<std::string, std::uint64_t> placements_;
    std::map<std::string, std::uint64_t> partFaces_;
    Scene scene_;
    double linearDeflection_ = 0.0;
    TessellationBudget budget_;
    std::set<std::string> tessellated_;
    std::map<PartKey, std::vector<Id>> partMeshes_;
    std::map<std::array<float, 4>, Id> materials_;
    std::size_t triangles_ = 0;
};

Scene XcafSceneBuilder::build() {
    TDF_LabelSequence free;
    shapes_->GetFreeShapes(free);
    if (free.IsEmpty()) throw Error(ErrorCode::Malformed, file_, "the file holds no shape");
    // First, before anything walks the located shapes (the bounding box below visits every
    // placement of every face): how many placements the assembly graph expands to.
    std::uint64_t placements = 0;
    for (const TDF_Label& label : free) {
        if (visible(label)) placements = saturatingAdd(placements, countPlacements(label, 0));
    }
    if (placements > options_.limits.maxInstances) {
        throwOverLimit(file_,
                       "the assembly places " + std::to_string(placements) +
                           " parts once its reused sub-assemblies are expanded",
                       options_.limits.maxInstances, "--max-instances");
    }

    // The deflection is relative to the whole model, so gather every free shape first.
    TopoDS_Compound all;
    BRep_Builder builder;
    builder.MakeCompound(all);
    for (const TDF_Label& label : free)
        builder.Add(all, shapes_->GetShape(label));
    if (!TopExp_Explorer(all, TopAbs_FACE).More()) {
        throw Error(ErrorCode::NoGeometry, file_, "the model has no faces (curves or points only)");
    }
    const double diagonal = modelDiagonal(all);
    if (diagonal <= 0.0) {
        throw Error(ErrorCode::NoGeometry, file_, "the model's faces have no finite extent");
    }
    linearDeflection_ = options_.cadRelativeDeflection * diagonal;
    budget_ = makeBudget(file_, diagonal, linearDeflection_, options_.cadAngularDeflection);
    std::uint64_t totalFaces = 0;
    for (const auto& [entry, faces] : partFaces_)
        totalFaces += faces;
    faces_.emplace(progress_, file_, totalFaces);
    const std::string stem = file_.stem().string();
    for (int i = 1; i <= free.Length(); ++i) {
        const TDF_Label& label = free.Value(i);
        if (!visible(label)) continue;
        std::string name = labelName(label);
        if (name.empty()) name = free.Length() == 1 ? stem : stem + "_" + std::to_string(i);
        const Id node = scene_.addNode(name, 0);
        visit(label, node, std::nullopt, 0);
    }
    if (scene_.instances.empty()) {
        throw Error(ErrorCode::NoGeometry, file_, "no face could be tessellated");
    }
    scene_.updateWorldTransforms();
    scene_.importNotes = std::move(budget_.notes);
    return std::move(scene_);
}

// Placements (part instances) under `shape` with every sub-assembly expanded, computed once per
// label: a file of 30 levels each placing the level below twice is 2^30 placements, counted
// here in 30 steps instead of built. Visibility is judged as visit() does.
std::uint64_t XcafSceneBuilder::countPlacements(const TDF_Label& shape, int depth) {
    if (depth > kMaxAssemblyDepth) {
        throw Error(ErrorCode::Malformed, file_, "assembly nested deeper than 256 levels");
    }
    const std::string entry = entryOf(shape);
    if (auto it = placements_.find(entry); it != placements_.end()) return it->second;
    std::uint64_t count = 0;
    if (shapes_->IsAssembly(shape)) {
        TDF_LabelSequence components;
        XCAFDoc_ShapeTool::GetComponents(shape, components, false);
        for (const TDF_Label& component : components) {
            TDF_Label referred;
            if (!XCAFDoc_ShapeTool::GetReferredShape(component, referred)) continue;
            if (!visible(component) || !visible(referred)) continue;
            count = saturatingAdd(count, countPlacements(referred, depth + 1));
        }
    } else if (shapes_->IsSimpleShape(shape)) {
        count = 1;
        partFaces_.emplace(entry, faceCount(shapes_->GetShape(shape)));
    }
    placements_.emplace(entry, count);
    return count;
}

// `inherited` is what the parent passes down (its instance colour, or its own colour).
void XcafSceneBuilder::visit(const TDF_Label& shape, Id node,
                             const std::optional<glm::vec4>& inherited, int depth) {
    if (depth > kMaxAssemblyDepth) {
        throw Error(ErrorCode::Malformed, file_, "assembly nested deeper than 256 levels");
    }
    if (shapes_->IsAssembly(shape)) {
        const std::optional<glm::vec4> own = ownColour(shape);
        addComponents(shape, node, own ? own : inherited, depth);
    } else if (shapes_->IsSimpleShape(shape)) {
        addPart(shape, node, inherited);
    }
}

void XcafSceneBuilder::addComponents(const TDF_Label& assembly, Id node,
                                     const std::optional<glm::vec4>& colour, int depth) {
    TDF_LabelSequence components;
    XCAFDoc_ShapeTool::GetComponents(assembly, components, false);
    for (const TDF_Label& component : components) {
        TDF_Label referred;
        if (!XCAFDoc_ShapeTool::GetReferredShape(component, referred)) continue;
        if (!visible(component) || !visible(referred)) continue;
        std::string name = labelName(component);
        if (name.empty()) name = labelName(referred);
        if (name.empty()) name = entryOf(referred);
        const glm::dmat4 local =
            toGlm(XCAFDoc_ShapeTool::GetLocation(component).Transformation(), unitScale_);
        const Id child = scene_.addNode(name, node, local);
        // Instance colour > referred shape colour > what the assembly passes down.
        std::optional<glm::vec4> placed = ownColour(component);
        if (!placed) placed = ownColour(referred);
        if (!placed) placed = colour;
        visit(referred, child, placed, depth + 1);
    }
}

void XcafSceneBuilder::addPart(const TDF_Label& part, Id node,
                               const std::optional<glm::vec4>& inherited) {
    // A free part (no component above it) still has its own colour to apply.
    std::optional<glm::vec4> colour = inherited;
    if (!colour) colour = ownColour(part);
    for (Id mesh : partMeshes(part, colour))
        scene_.addInstance(mesh, node);
}

const std::vector<Id>& XcafSceneBuilder::partMeshes(const TDF_Label& part,
                                                    const std::optional<glm::vec4>& colour) {
    const std::string entry = entryOf(part);
    const PartKey key{entry, colour.has_value(),
                      colour ? std::array<float, 4>{colour->r, colour->g, colour->b, colour->a}
                             : std::array<float, 4>{}};
    if (auto it = partMeshes_.find(key); it != partMeshes_.end()) return it->second;
    const TopoDS_Shape shape = shapes_->GetShape(part);
    if (tessellated_.insert(entry).second) {
        tessellate(shape, linearDeflection_, options_.cadAngularDeflection, &budget_, unitScale_,
                   &*faces_);
    }
    const FaceColourMap faces = faceColours(part);
    std::vector<ColouredMesh> groups = extractMeshes(shape, unitScale_, colour, &faces);
    std::string name = labelName(part);
    if (name.empty()) name = file_.stem().string();
    std::vector<Id>& ids = partMeshes_[key];
    for (std::size_t g = 0; g < groups.size(); ++g) {
        Mesh& mesh = groups[g].mesh;
        triangles_ += mesh.triangleCount();
        checkTessellatedTriangles(triangles_, options_, file_);
        mesh.name = groups.size() == 1 ? name : name + "_" + std::to_string(g + 1);
        mesh.material = materialFor(groups[g].colour);
        ids.push_back(scene_.addMesh(std::move(mesh)));
    }
    return ids;
}

std::optional<glm::vec4> XcafSceneBuilder::ownColour(const TDF_Label& label) const {
    Quantity_ColorRGBA colour;
    // Surface colour is what shading uses; a generic colour is the next best thing.
    if (colours_->GetColor(label, XCAFDoc_ColorSurf, colour) ||
        colours_->GetColor(label, XCAFDoc_ColorGen, colour)) {
        return toLinearRgba(colour);
    }
    return std::nullopt;
}

// Colours of the part's sub-shape labels, expanded to faces: shells and solids first, then
// faces, so a face's own colour wins over its shell's.
FaceColourMap XcafSceneBuilder::faceColours(const TDF_Label& part) const {
    FaceColourMap faces;
    TDF_LabelSequence subs;
    XCAFDoc_ShapeTool::GetSubShapes(part, subs);
    for (int pass = 0; pass < 2; ++pass) {
        for (const TDF_Label& sub : subs) {
            const std::optional<glm::vec4> colour = ownColour(sub);
            const TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(sub);
            if (!colour || shape.IsNull()) continue;
            if ((shape.ShapeType() == TopAbs_FACE) != (pass == 1)) continue;
            for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
                if (faces.IsBound(ex.Current())) faces.UnBind(ex.Current());
                faces.Bind(ex.Current(), *colour);
            }
        }
    }
    return faces;
}

Id XcafSceneBuilder::materialFor(const std::optional<glm::vec4>& colour) {
    if (!colour) return 0; // the scene's default material
    const std::array<float, 4> key{colour->r, colour->g, colour->b, colour->a};
    if (auto it = materials_.find(key); it != materials_.end()) return it->second;
    const Id id = scene_.addMaterial(Material{hexName(*colour), *colour, {}});
    materials_.emplace(key, id);
    return id;
}

} // namespace

Scene sceneFromXcaf(const Handle(TDocStd_Document) & doc, double unitScale,
                    const ImportOptions& options, const std::filesystem::path& file,
                    const Progress& progress) {
    return XcafSceneBuilder(doc, unitScale, options, file, progress).build();
}

} // namespace hlod::cad
