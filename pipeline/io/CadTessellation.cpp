// OpenCASCADE tessellation and triangle extraction. Based on the OCCT 7.6 meshing guide
// (BRepMesh_IncrementalMesh, BRep_Tool::Triangulation) and RWMesh_FaceIterator's handling of
// face location and orientation; see CadTessellation.h for the contract.
#include "pipeline/io/CadTessellation.h"

#include <cmath>
#include <utility>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Message_ProgressIndicator.hxx>
#include <Poly_Triangulation.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

namespace hlod::cad {

namespace {

// One face's share of a mesh: where its vertices start, so normals can be filled per face.
struct FaceRange {
    std::size_t firstVertex = 0;
    std::size_t firstIndex = 0;
};

// Area-weighted normals from the face's own triangles: the fallback where the surface has no
// normal (cone apex, sphere pole, degenerate patches) or the triangulation carries no UVs.
void triangleNormals(Mesh& mesh, const FaceRange& range) {
    for (std::size_t i = range.firstIndex; i + 2 < mesh.indices.size(); i += 3) {
        const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
        const glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a],
                                       mesh.positions[c] - mesh.positions[a]);
        mesh.normals[a] += n;
        mesh.normals[b] += n;
        mesh.normals[c] += n;
    }
    for (std::size_t v = range.firstVertex; v < mesh.normals.size(); ++v) {
        const float len = glm::length(mesh.normals[v]);
        mesh.normals[v] = len > 0.0f ? mesh.normals[v] / len : glm::vec3(0.0f, 0.0f, 1.0f);
    }
}

// Exact normals where the triangulation stores them or the surface defines one at the
// node's UV. BRepAdaptor_Surface applies the face location itself, stored normals need it.
void surfaceNormals(const TopoDS_Face& face, const Handle(Poly_Triangulation) & tri,
                    const gp_Trsf& trsf, bool reversed, Mesh& mesh, const FaceRange& range) {
    const float sign = reversed ? -1.0f : 1.0f;
    const auto store = [&](int node, const gp_Dir& d) {
        mesh.normals[range.firstVertex + static_cast<std::size_t>(node - 1)] =
            sign * glm::vec3(float(d.X()), float(d.Y()), float(d.Z()));
    };
    if (tri->HasNormals()) {
        for (int i = 1; i <= tri->NbNodes(); ++i)
            store(i, tri->Normal(i).Transformed(trsf));
        return;
    }
    if (!tri->HasUVNodes()) return;
    const BRepAdaptor_Surface surface(face, false);
    BRepLProp_SLProps props(surface, 1, Precision::Confusion());
    for (int i = 1; i <= tri->NbNodes(); ++i) {
        const gp_Pnt2d uv = tri->UVNode(i);
        props.SetParameters(uv.X(), uv.Y());
        if (props.IsNormalDefined()) store(i, props.Normal());
    }
}

// Appends one face's triangulation to `mesh` (positions in metres, winding by orientation).
void appendFace(const TopoDS_Face& face, double unitScale, Mesh& mesh) {
    TopLoc_Location loc;
    const Handle(Poly_Triangulation)& tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull() || tri->NbNodes() < 3 || tri->NbTriangles() < 1) return;
    const gp_Trsf trsf = loc.Transformation();
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    const FaceRange range{mesh.positions.size(), mesh.indices.size()};
    const int nodeCount = tri->NbNodes();
    for (int i = 1; i <= nodeCount; ++i) {
        const gp_Pnt p = tri->Node(i).Transformed(trsf);
        mesh.positions.emplace_back(float(p.X() * unitScale), float(p.Y() * unitScale),
                                    float(p.Z() * unitScale));
    }
    for (int t = 1; t <= tri->NbTriangles(); ++t) {
        int a = 0, b = 0, c = 0;
        tri->Triangle(t).Get(a, b, c);
        if (reversed) std::swap(b, c);
        // Out-of-range or collapsed triangles come only from corrupt stored triangulations.
        if (a < 1 || b < 1 || c < 1 || a > nodeCount || b > nodeCount || c > nodeCount) continue;
        if (a == b || b == c || a == c) continue;
        for (int n : {a, b, c}) {
            mesh.indices.push_back(static_cast<std::uint32_t>(range.firstVertex + (n - 1)));
        }
    }
    mesh.normals.resize(mesh.positions.size(), glm::vec3(0.0f));
    triangleNormals(mesh, range);
    try {
        surfaceNormals(face, tri, trsf, reversed, mesh, range);
    } catch (const Standard_Failure&) {
        // The surface refused an evaluation: the triangle normals already stored stay.
    }
}

} // namespace

glm::vec4 toLinearRgba(const Quantity_ColorRGBA& colour) {
    Standard_Real r = 0, g = 0, b = 0;
    colour.GetRGB().Values(r, g, b, Quantity_TOC_RGB);
    return {float(r), float(g), float(b), colour.Alpha()};
}

double modelDiagonal(const TopoDS_Shape& shape) {
    try {
        Bnd_Box box;
        BRepBndLib::Add(shape, box, false);
        if (box.IsVoid() || box.IsOpen()) return 0.0;
        const double diagonal = std::sqrt(box.SquareExtent());
        return std::isfinite(diagonal) ? diagonal : 0.0;
    } catch (const Standard_Failure&) {
        return 0.0;
    }
}

void clearTriangulation(const TopoDS_Shape& shape) {
    try {
        BRepTools::Clean(shape);
    } catch (const Standard_Failure&) {
        // Nothing removed: BRepMesh then keeps whatever triangulation the file had.
    }
}

bool tessellate(const TopoDS_Shape& shape, double linearDeflection, double angularDeflection,
                TessellationBudget* budget, double unitScale, FaceProgress* progress) {
    if (progress != nullptr) progress->beginPart(faceCount(shape));
    bool done = false;
    try {
        if (budget != nullptr) meshDenseFaces(shape, *budget, unitScale, progress);
        IMeshTools_Parameters params;
        params.Deflection = linearDeflection;
        params.Angle = angularDeflection;
        // On the calling thread, not BRepMesh's parallel mode: a fault inside OCCT can only be
        // turned into an error on the thread that runs the guarded call (CadCrashGuard.h).
        params.InParallel = false;
        Handle(Message_ProgressIndicator) indicator;
        if (progress != nullptr) indicator = progress->indicator(true);
        BRepMesh_IncrementalMesh mesher(
            shape, params, indicator.IsNull() ? Message_ProgressRange() : indicator->Start());
        done = mesher.IsDone();
    } catch (const Standard_Failure&) {
        done = false;
    }
    if (progress != nullptr) {
        progress->throwIfCancelled(); // OCCT stopped early: the mesh is incomplete
        progress->endPart();
    }
    return done;
}

std::vector<ColouredMesh> extractMeshes(const TopoDS_Shape& shape, double unitScale,
                                        const std::optional<glm::vec4>& baseColour,
                                        const FaceColourMap* faceColours) {
    std::vector<ColouredMesh> groups;
    const auto groupFor = [&groups](const std::optional<glm::vec4>& colour) -> Mesh& {
        for (ColouredMesh& g : groups) {
            if (g.colour == colour) return g.mesh;
        }
        groups.push_back(ColouredMesh{colour, Mesh{}});
        return groups.back().mesh;
    };
    for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
        const TopoDS_Face& face = TopoDS::Face(ex.Current());
        std::optional<glm::vec4> colour = baseColour;
        if (faceColours != nullptr) {
            if (const glm::vec4* c = faceColours->Seek(face)) colour = *c;
        }
        Mesh& mesh = groupFor(colour);
        const std::size_t vertices = mesh.positions.size(), indices = mesh.indices.size();
        try {
            appendFace(face, unitScale, mesh);
        } catch (const Standard_Failure&) {
            // A face OCCT cannot evaluate adds nothing (its partial data is rolled back);
            // its neighbours still do.
            mesh.positions.resize(vertices);
            mesh.normals.resize(vertices);
            mesh.indices.resize(indices);
        }
    }
    std::erase_if(groups, [](const ColouredMesh& g) { return g.mesh.indices.empty(); });
    return groups;
}

void checkTessellatedTriangles(std::uint64_t triangles, const ImportOptions& options,
                               const std::filesystem::path& file) {
    if (triangles > options.limits.maxUniqueTriangles) {
        throwOverLimit(file,
                       "tessellation reaches " + std::to_string(triangles) +
                           " triangles (a coarser --deflection makes fewer)",
                       options.limits.maxUniqueTriangles, "--max-unique-triangles");
    }
}

glm::dmat4 toGlm(const gp_Trsf& trsf, double unitScale) {
    glm::dmat4 m(1.0);
    for (int col = 0; col < 3; ++col) {
        for (int row = 0; row < 3; ++row)
            m[col][row] = trsf.Value(row + 1, col + 1);
    }
    for (int row = 0; row < 3; ++row)
        m[3][row] = trsf.Value(row + 1, 4) * unitScale;
    return m;
}

} // namespace hlod::cad
