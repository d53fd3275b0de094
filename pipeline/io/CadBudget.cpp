// Bounded CAD tessellation (issue 22): per-face and per-file triangle budgets enforced through
// BRepMesh's MinSize. Based on the OCCT 7.6 meshing guide (IMeshTools_Parameters: MinSize,
// BRepMesh_IncrementalMesh on a single face; a stored triangulation whose parameters carry the
// requested deflection is reused, not remeshed). See CadBudget.h for the budget's derivation.
#include "pipeline/io/CadBudget.h"
#include "pipeline/io/CadProgress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Adaptor3d_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Message_ProgressIndicator.hxx>
#include <Poly_Triangulation.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

namespace hlod::cad {

namespace {

// Knot spans of `knots` (distinct values) that overlap [lo, hi].
int spansWithin(const TColStd_Array1OfReal& knots, double lo, double hi) {
    int spans = 0;
    for (int i = knots.Lower(); i < knots.Upper(); ++i) {
        if (knots(i + 1) > lo && knots(i) < hi) ++spans;
    }
    return std::max(spans, 1);
}

double curveSpans(const Handle(Adaptor3d_Curve) & curve) {
    if (curve.IsNull() || curve->GetType() != GeomAbs_BSplineCurve) return 1.0;
    return std::max(1, curve->BSpline()->NbKnots() - 1);
}

double surfaceEstimate(const Adaptor3d_Surface& s, double u0, double u1, double v0, double v1,
                       double angular) {
    switch (s.GetType()) {
    case GeomAbs_BSplineSurface: {
        const Handle(Geom_BSplineSurface) b = s.BSpline();
        return 2.0 * spansWithin(b->UKnots(), u0, u1) * spansWithin(b->VKnots(), v0, v1);
    }
    case GeomAbs_OffsetSurface:
        return surfaceEstimate(*s.BasisSurface(), u0, u1, v0, v1, angular);
    case GeomAbs_SurfaceOfRevolution:
        // One ring of nodes per angular step along every span of the profile.
        return 2.0 * curveSpans(s.BasisCurve()) * std::ceil((u1 - u0) / angular);
    case GeomAbs_SurfaceOfExtrusion:
        return 2.0 * curveSpans(s.BasisCurve());
    default:
        return 0.0;
    }
}

// Area of the face's bounding box seen along its thinnest axis (file units squared).
double boxArea(const TopoDS_Face& face) {
    Bnd_Box box;
    BRepBndLib::Add(face, box, false);
    if (box.IsVoid() || box.IsOpen()) return 0.0;
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    double e[3] = {x1 - x0, y1 - y0, z1 - z0};
    std::sort(e, e + 3);
    const double area = e[1] * e[2];
    return std::isfinite(area) ? area : 0.0;
}

// Largest distance between the surface at a triangle's parametric centre and the triangle's
// centre, over (a sample of) the face's triangles: how far the mesh strays from the surface.
double meshDeviation(const TopoDS_Face& face) {
    TopLoc_Location loc;
    const Handle(Poly_Triangulation)& tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull() || !tri->HasUVNodes() || tri->NbTriangles() < 1) return 0.0;
    const gp_Trsf trsf = loc.Transformation();
    const BRepAdaptor_Surface surface(face, false);
    const int count = tri->NbTriangles();
    const int stride = std::max(1, count / 20000);
    double deviation = 0.0;
    for (int t = 1; t <= count; t += stride) {
        int a = 0, b = 0, c = 0;
        tri->Triangle(t).Get(a, b, c);
        const gp_XY uv = (tri->UVNode(a).XY() + tri->UVNode(b).XY() + tri->UVNode(c).XY()) / 3.0;
        const gp_XYZ mid =
            (tri->Node(a).Transformed(trsf).XYZ() + tri->Node(b).Transformed(trsf).XYZ() +
             tri->Node(c).Transformed(trsf).XYZ()) /
            3.0;
        deviation =
            std::max(deviation, surface.Value(uv.X(), uv.Y()).XYZ().Subtracted(mid).Modulus());
    }
    return deviation;
}

std::string surfaceName(const TopoDS_Face& face) {
    switch (BRepAdaptor_Surface(face, false).GetType()) {
    case GeomAbs_BSplineSurface:
        return "B-spline";
    case GeomAbs_OffsetSurface:
        return "offset";
    case GeomAbs_SurfaceOfRevolution:
        return "revolved";
    case GeomAbs_SurfaceOfExtrusion:
        return "extruded";
    default:
        return "other";
    }
}

std::string number(double v, const char* format = "%.3g") {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

// Meshes one face within `faceTriangles`; returns the triangles it got (0 on failure).
int meshFace(const TopoDS_Face& face, double area, double faceTriangles,
             const TessellationBudget& budget, FaceProgress* progress) {
    IMeshTools_Parameters params;
    params.Deflection = budget.linearDeflection;
    params.Angle = budget.angularDeflection;
    params.MinSize = std::sqrt(2.0 * area / faceTriangles);
    params.InParallel = false; // see tessellate(): faults are guarded on this thread only
    // Only for its cancel flag: this single face's own counter is not the shape's.
    Handle(Message_ProgressIndicator) indicator;
    if (progress != nullptr) indicator = progress->indicator(false);
    BRepMesh_IncrementalMesh mesher(
        face, params, indicator.IsNull() ? Message_ProgressRange() : indicator->Start());
    if (progress != nullptr) progress->throwIfCancelled();
    TopLoc_Location loc;
    const Handle(Poly_Triangulation)& tri = BRep_Tool::Triangulation(face, loc);
    return tri.IsNull() ? 0 : tri->NbTriangles();
}

} // namespace

TessellationBudget makeBudget(const std::filesystem::path& file, double diagonal,
                              double linearDeflection, double angularDeflection) {
    TessellationBudget b;
    b.file = file;
    b.linearDeflection = linearDeflection;
    b.angularDeflection = angularDeflection;
    b.elementSize = kElementsPerDeflection * linearDeflection;
    const double cells = diagonal / b.elementSize;
    b.fileTriangles = std::max(kMinFaceTriangles, 8.0 * cells * cells);
    return b;
}

double estimatedTriangles(const TopoDS_Face& face) {
    try {
        const BRepAdaptor_Surface surface(face, false);
        double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
        BRepTools::UVBounds(face, u0, u1, v0, v1);
        return surfaceEstimate(surface, u0, u1, v0, v1, 0.5);
    } catch (const Standard_Failure&) {
        return 0.0;
    }
}

void meshDenseFaces(const TopoDS_Shape& shape, TessellationBudget& budget, double unitScale,
                    FaceProgress* progress) {
    if (!(budget.elementSize > 0.0)) return;
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    const int first = budget.facesSeen;
    budget.facesSeen += faces.Extent();
    std::uint64_t meshed = 0;
    for (int i = 1; i <= faces.Extent(); ++i) {
        if (progress != nullptr) progress->throwIfCancelled();
        const TopoDS_Face& face = TopoDS::Face(faces(i));
        try {
            TopLoc_Location loc;
            if (!BRep_Tool::Triangulation(face, loc).IsNull()) continue;
            const double estimate = estimatedTriangles(face);
            const double area = boxArea(face);
            if (estimate <= kMinFaceTriangles || area <= 0.0) continue;
            const double own =
                std::max(kMinFaceTriangles, 2.0 * area / (budget.elementSize * budget.elementSize));
            if (estimate <= own) continue;
            const double remaining =
                std::max(kMinFaceTriangles, budget.fileTriangles - budget.usedTriangles);
            const double allowed = std::min(own, remaining);
            const int got = meshFace(face, area, allowed, budget, progress);
            budget.usedTriangles += got;
            if (progress != nullptr) progress->partDone(++meshed);
            const double deviation = meshDeviation(face);
            if (got > 0 && deviation > 2.0 * budget.linearDeflection) {
                budget.notes.push_back(
                    budget.file.filename().string() + ": face " + std::to_string(first + i) + " (" +
                    surfaceName(face) + " surface, about " + number(estimate, "%.0f") +
                    " triangles unbounded) coarsened by the tessellation budget to " +
                    std::to_string(got) + " triangles: deviates up to " +
                    number(deviation * unitScale) + " m for a deflection of " +
                    number(budget.linearDeflection * unitScale) + " m");
            }
        } catch (const Standard_Failure&) {
            // Left to the normal pass over the whole shape.
        }
    }
}

} // namespace hlod::cad
