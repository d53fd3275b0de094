// Tests of the bounded CAD tessellation (pipeline/io/CadBudget.cpp): a dense B-spline face is
// meshed within its budget and noted, ordinary faces are meshed exactly as before.
#include <gtest/gtest.h>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPControl_Writer.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "pipeline/io/CadBudget.h"
#include "pipeline/io/CadTessellation.h"
#include "pipeline/io/Import.h"
#include "tests/pipeline/TestUtil.h"
#include "tests/pipeline/io/DenseBsplineBrep.h"

namespace hlod {
namespace {

namespace fs = std::filesystem;

TopoDS_Shape readShape(const fs::path& file) {
    TopoDS_Shape shape;
    BRep_Builder builder;
    BRepTools::Read(shape, file.string().c_str(), builder);
    return shape;
}

int triangleCount(const TopoDS_Shape& shape) {
    int count = 0;
    for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
        TopLoc_Location loc;
        const auto tri = BRep_Tool::Triangulation(TopoDS::Face(ex.Current()), loc);
        if (!tri.IsNull()) count += tri->NbTriangles();
    }
    return count;
}

TEST(CadBudget, BudgetFollowsTheDeflection) {
    // Element size 5 deflections; the file may hold 8 squares of the diagonal at that size.
    const cad::TessellationBudget b = cad::makeBudget("x.brep", 1000.0, 2.0, 0.5);
    EXPECT_DOUBLE_EQ(b.elementSize, 10.0);
    EXPECT_DOUBLE_EQ(b.fileTriangles, 8.0 * 100.0 * 100.0);
}

TEST(CadBudget, EstimateCountsTheKnotSpansOfABsplineFace) {
    test::TempDir dir;
    test::writeDenseBsplineBrep(dir / "net.brep", 64);
    // 64 poles of degree 3: 62 distinct knots, 61 spans each way, two triangles per cell.
    const TopoDS_Shape shape = readShape(dir / "net.brep");
    EXPECT_DOUBLE_EQ(cad::estimatedTriangles(TopoDS::Face(shape)), 2.0 * 61 * 61);
}

TEST(CadBudget, DenseBsplineTerrainIsMeshedWithinItsBudgetAndNoted) {
    test::TempDir dir;
    const fs::path file = dir / "terrain.brep";
    test::writeDenseBsplineBrep(file, 256, 10000.0);
    const Scene scene = importCad(file, {});
    ASSERT_EQ(scene.meshes.size(), 1u);
    // Diagonal ~14,159 (10,000 x 10,000 x ~700), deflection 0.001 of it: 14.16; elements of
    // at least 5 x 14.16 = 70.8 over 10^8 of area: 2 x 10^8 / 70.8^2 ~ 39,900 triangles.
    // Delaunay triangles with edges >= MinSize are not all half-squares, hence the margin;
    // unbounded, BRepMesh makes > 130,000 here (a node per knot line, 253 x 253 spans).
    const std::size_t triangles = scene.meshes[0].triangleCount();
    EXPECT_LT(triangles, 48'000u);
    EXPECT_GT(triangles, 10'000u); // still a terrain, not a couple of triangles
    ASSERT_EQ(scene.importNotes.size(), 1u);
    const std::string& note = scene.importNotes[0];
    EXPECT_NE(note.find("terrain.brep: face 1 (B-spline surface"), std::string::npos) << note;
    EXPECT_NE(note.find("coarsened by the tessellation budget"), std::string::npos) << note;
}

TEST(CadBudget, DenseBsplineFaceInAStepFileIsBudgetedToo) {
    // The XCAF path (STEP/IGES) meshes part by part through the same budget.
    test::TempDir dir;
    test::writeDenseBsplineBrep(dir / "terrain.brep", 256, 10000.0);
    STEPControl_Writer writer;
    ASSERT_EQ(writer.Transfer(readShape(dir / "terrain.brep"), STEPControl_AsIs), IFSelect_RetDone);
    ASSERT_EQ(writer.Write((dir / "terrain.step").string().c_str()), IFSelect_RetDone);
    const Scene scene = importCad(dir / "terrain.step", {});
    EXPECT_LT(scene.stats().triangles, 48'000u); // the same budget as the BREP above
    EXPECT_GT(scene.stats().triangles, 10'000u);
    ASSERT_EQ(scene.importNotes.size(), 1u);
    EXPECT_NE(scene.importNotes[0].find("terrain.step: face 1 (B-spline surface"),
              std::string::npos)
        << scene.importNotes[0];
}

TEST(CadBudget, FacesWithinTheirBudgetAreMeshedExactlyAsWithout) {
    test::TempDir dir;
    const fs::path file = dir / "small.brep";
    // 32 x 32 poles: 29 x 29 spans, ~1,700 estimated triangles, under the 2,000 floor.
    test::writeDenseBsplineBrep(file, 32, 1000.0);
    const TopoDS_Shape plain = readShape(file);
    const TopoDS_Shape budgeted = readShape(file);
    const double diagonal = cad::modelDiagonal(plain);
    ASSERT_TRUE(cad::tessellate(plain, 0.001 * diagonal, 0.5));
    cad::TessellationBudget budget = cad::makeBudget(file, diagonal, 0.001 * diagonal, 0.5);
    ASSERT_TRUE(cad::tessellate(budgeted, 0.001 * diagonal, 0.5, &budget));
    EXPECT_GT(triangleCount(plain), 0);
    EXPECT_EQ(triangleCount(budgeted), triangleCount(plain));
    EXPECT_TRUE(budget.notes.empty());
}

TEST(CadBudget, KitchenSolidsGetNoNotes) {
    // Planes, cylinders and a few small B-splines: nothing near a budget.
    const Scene scene = importScene({test::dataDir() / "scenes/occt-kitchen"}, [] {
        ImportOptions o;
        o.cadBrepUnitMetres = 0.01;
        return o;
    }());
    EXPECT_GT(scene.stats().triangles, 0u);
    EXPECT_TRUE(scene.importNotes.empty());
}

} // namespace
} // namespace hlod
