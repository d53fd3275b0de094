// Bounded CAD tessellation: a triangle budget per face and per file, derived from the linear
// deflection and the size of each face, so a single dense surface (a terrain as one B-spline
// face with a 250 x 250 control net) cannot take minutes and gigabytes in BRepMesh.
//
// Why BRepMesh blows up: its NURBS range splitter seeds a node on every knot line, then
// refines by deflection and classifies each new node against the face's boundary polygon, so
// the cost grows with the control net (and faster than linearly), not with the deflection.
// The lever is IMeshTools_Parameters::MinSize (no element edge shorter than it): we mesh a
// face that would exceed its budget on its own, with MinSize = the edge length of a uniform
// grid of the budgeted size over the face.
//
// The budget (file units):
//  - element size s = kElementsPerDeflection x linear deflection: the finest mesh a budgeted
//    face can get; features smaller than a few deflections are below what the chosen
//    deflection shows anyway;
//  - per face: 2 x (face area / s^2) triangles (a grid of s-sized squares over the face's
//    bounding box), at least kMinFaceTriangles;
//  - per file: 8 x (model diagonal / s)^2, shared by the budgeted faces in meshing order.
// Only faces whose estimated count (from the surface's own definition: knot spans of
// B-splines, their basis curves for swept surfaces) exceeds their budget are treated; every
// other face is meshed exactly as before.
//
// A budgeted face counts as coarsened when its mesh then deviates from the surface by more
// than twice the deflection (measured at the triangles' parametric centres); each coarsened
// face gives one note naming the file and the face, which `hlod info` prints.
// Failure: never throws; OCCT failures on a face leave that face to the normal mesher.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

namespace hlod::cad {

class FaceProgress;

constexpr double kElementsPerDeflection = 5.0;
constexpr double kMinFaceTriangles = 2000.0;

struct TessellationBudget {
    double linearDeflection = 0.0; // file units
    double angularDeflection = 0.5;
    double elementSize = 0.0;       // s, file units
    double fileTriangles = 0.0;     // what budgeted faces may use together
    double usedTriangles = 0.0;     // used by budgeted faces so far
    int facesSeen = 0;              // faces visited, for naming a face by its index
    std::vector<std::string> notes; // one per coarsened face
    std::filesystem::path file;
};

// The budget for a model of bounding-box diagonal `diagonal` meshed at `linearDeflection`
// (both in file units).
TessellationBudget makeBudget(const std::filesystem::path& file, double diagonal,
                              double linearDeflection, double angularDeflection);

// Triangles BRepMesh would make on `face` at best (one node per knot-span crossing), from the
// surface definition alone; 0 for surfaces whose cost only the deflection decides.
double estimatedTriangles(const TopoDS_Face& face);

// Meshes, one by one and with a MinSize, the faces of `shape` that are untriangulated and
// exceed their budget; the caller's BRepMesh pass over the whole shape then keeps those
// triangulations (they carry the requested deflection) and meshes the rest normally.
// `unitScale` (metres per file unit) only serves the notes.
// With `progress`, each budgeted face counts as meshed when done, and a raised cancel flag
// stops the meshing (Error(Cancelled)).
void meshDenseFaces(const TopoDS_Shape& shape, TessellationBudget& budget, double unitScale,
                    FaceProgress* progress = nullptr);

} // namespace hlod::cad
