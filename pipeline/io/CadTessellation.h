// OpenCASCADE B-rep -> hlod::Mesh: tessellation (BRepMesh_IncrementalMesh) and extraction of
// the per-face Poly_Triangulation into triangle meshes, split by face colour.
//
// Based on the OCCT 7.6 meshing guide (BRepMesh_IncrementalMesh + BRep_Tool::Triangulation,
// "Mesh" user guide) and the way XCAFPrs/RWMesh_FaceIterator walk faces: nodes are in the
// face's location frame, triangles of a TopAbs_REVERSED face are wound backwards.
//
// Units: shapes are in the file's unit; every function taking `unitScale` multiplies lengths
// by it (metres per file unit) so the results are in metres.
// Failure: OCCT's Standard_Failure never escapes these functions; a face that cannot be
// tessellated contributes no triangles (the caller reports NoGeometry when nothing did).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include <NCollection_DataMap.hxx>
#include <Quantity_ColorRGBA.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Trsf.hxx>

#include <glm/glm.hpp>

#include "pipeline/io/CadBudget.h"
#include "pipeline/io/CadProgress.h"
#include "pipeline/io/Import.h"
#include "pipeline/scene/Scene.h"

namespace hlod::cad {

// Colour per face, matched with TopoDS_Shape::IsSame (same TShape and location, any
// orientation). The caller expands colours of shells/solids to their faces.
using FaceColourMap = NCollection_DataMap<TopoDS_Shape, glm::vec4, TopTools_ShapeMapHasher>;

// Linear RGBA (Quantity_Color stores linear RGB since OCCT 7.5, as our Material wants).
glm::vec4 toLinearRgba(const Quantity_ColorRGBA& colour);

// The bounding-box diagonal of `shape` from its geometry (not from any triangulation), or 0
// when the box is empty, open (infinite geometry) or not finite.
double modelDiagonal(const TopoDS_Shape& shape);

// Drops any triangulation stored in the shape (BREP files carry one) so that the deflection
// the caller asks for, not the file's, decides the tessellation.
void clearTriangulation(const TopoDS_Shape& shape);

// Tessellates every face of `shape` that has no triangulation yet, with an absolute linear
// deflection (file units) and an angular deflection (radians). With a `budget`, faces that
// would exceed it are meshed first within it (CadBudget.h; `unitScale` is metres per file
// unit, for its notes). With `progress`, the shape's faces are reported as they are meshed and
// a raised cancel flag stops the meshing with Error(Cancelled) (CadProgress.h). Returns false
// when OCCT threw.
bool tessellate(const TopoDS_Shape& shape, double linearDeflection, double angularDeflection,
                TessellationBudget* budget = nullptr, double unitScale = 1.0,
                FaceProgress* progress = nullptr);

// A triangle mesh for one colour of a shape; `colour` is empty when neither the faces nor
// the caller gave one (the default material applies).
struct ColouredMesh {
    std::optional<glm::vec4> colour;
    Mesh mesh;
};

// Triangles of all faces of `shape` (already tessellated) in the shape's frame, one mesh per
// distinct colour: a face takes its colour from `faceColours` (may be null), else
// `baseColour`. Normals come from the surface where it
// defines one (exact shading of curved faces) and from the adjacent triangles elsewhere.
std::vector<ColouredMesh> extractMeshes(const TopoDS_Shape& shape, double unitScale,
                                        const std::optional<glm::vec4>& baseColour,
                                        const FaceColourMap* faceColours);

// Throws TooLarge naming `file` when `triangles` tessellated so far exceed the file's
// options.limits.maxUniqueTriangles.
void checkTessellatedTriangles(std::uint64_t triangles, const ImportOptions& options,
                               const std::filesystem::path& file);

// Column-major glm matrix of an OCCT transformation (scale factor included), with the
// translation converted to metres.
glm::dmat4 toGlm(const gp_Trsf& trsf, double unitScale);

} // namespace hlod::cad
