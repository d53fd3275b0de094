// Tests of the OpenCASCADE importer (pipeline/io/CadImporter.cpp, CadXcaf.cpp,
// CadTessellation.cpp) on the shared CAD data (AS1 STEP assembly, OCCT sample kitchen BREP,
// the robustness corpus) and on tiny models written here with OCCT itself, whose expected
// values follow from their construction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>

#include "pipeline/core/Error.h"
#include "pipeline/io/CadCrashGuard.h"
#include "pipeline/io/CadTessellation.h"
#include "pipeline/io/Import.h"
#include "pipeline/scene/Scene.h"
#include "tests/pipeline/TestUtil.h"

namespace hlod {
namespace {

namespace fs = std::filesystem;

const fs::path kAs1 = test::dataDir() / "scenes/as1-assembly/as1-oc-214.stp";
const fs::path kKitchen = test::dataDir() / "scenes/occt-kitchen";
const fs::path kEdgeCases = test::dataDir() / "robustness/real-world/cad-edge-cases";

const Mesh* findMesh(const Scene& scene, const std::string& name) {
    for (const Mesh& m : scene.meshes) {
        if (m.name == name) return &m;
    }
    return nullptr;
}

std::map<std::string, int> instancesPerMesh(const Scene& scene) {
    std::map<std::string, int> count;
    for (const MeshInstance& inst : scene.instances)
        ++count[scene.meshes[inst.mesh].name];
    return count;
}

// Divergence theorem: positive for a closed mesh whose triangles wind counter-clockwise seen
// from outside, which is what correct handling of TopAbs_REVERSED faces produces.
double signedVolume(const Mesh& mesh) {
    double volume = 0.0;
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const glm::dvec3 a = mesh.positions[mesh.indices[i]];
        const glm::dvec3 b = mesh.positions[mesh.indices[i + 1]];
        const glm::dvec3 c = mesh.positions[mesh.indices[i + 2]];
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return volume;
}

std::string readText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

ErrorCode importErrorCode(const fs::path& file, std::string* message = nullptr) {
    try {
        importCad(file, {});
    } catch (const Error& e) {
        if (message != nullptr) *message = e.what();
        return e.code();
    }
    ADD_FAILURE() << "no error for " << file;
    return ErrorCode::Io;
}

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// ---------------------------------------------------------------------------------------
// AS1 (STEP AP214 assembly in millimetres), loaded once for the whole suite.

class CadImporterAs1 : public ::testing::Test {
protected:
    static void SetUpTestSuite() { scene_ = new Scene(importCad(kAs1, {})); }
    static void TearDownTestSuite() {
        delete scene_;
        scene_ = nullptr;
    }
    static const Scene& scene() { return *scene_; }
    static Scene* scene_;
};
Scene* CadImporterAs1::scene_ = nullptr;

TEST_F(CadImporterAs1, EighteenInstancesShareFivePartMeshes) {
    // SOURCE.txt: 18 part instances of 5 parts. Per the assembly tree: the rod assembly holds
    // 2 nuts and the rod; each of the 2 l-bracket assemblies holds an l-bracket and 3
    // nut-bolt assemblies (a bolt and a nut each); the plate stands alone.
    EXPECT_EQ(scene().instances.size(), 18u);
    EXPECT_EQ(scene().meshes.size(), 5u);
    const std::map<std::string, int> expected{
        {"bolt", 6}, {"l-bracket", 2}, {"nut", 2 + 6}, {"plate", 1}, {"rod", 1}};
    EXPECT_EQ(instancesPerMesh(scene()), expected);
}

TEST_F(CadImporterAs1, NodesFollowTheAssemblyTreeAndItsNames) {
    // root > as1 > 4 components; l-bracket-assembly_n > nut-bolt-assembly_n > bolt_1/nut_3.
    // 1 root + 1 as1 + (1 + 3) rod assembly + 2 x (1 + 3 x 3 + 1) + 1 plate = 29 nodes; the
    // deepest path root/as1/l-bracket-assembly/nut-bolt-assembly/bolt has 5 levels.
    EXPECT_EQ(scene().nodes.size(), 29u);
    EXPECT_EQ(scene().stats().depth, 5u);
    ASSERT_EQ(scene().nodes[0].children.size(), 1u);
    const Node& as1 = scene().nodes[scene().nodes[0].children[0]];
    EXPECT_EQ(as1.name, "as1");
    std::vector<std::string> top;
    for (Id c : as1.children)
        top.push_back(scene().nodes[c].name);
    EXPECT_EQ(top, (std::vector<std::string>{"rod-assembly_1", "l-bracket-assembly_1", "plate_1",
                                             "l-bracket-assembly_2"}));
    std::set<std::string> names;
    for (const Node& n : scene().nodes)
        names.insert(n.name);
    for (const char* name :
         {"nut_1", "nut_2", "rod_1", "nut-bolt-assembly_3", "bolt_1", "nut_3", "l-bracket_1"}) {
        EXPECT_TRUE(names.count(name)) << name;
    }
}

TEST_F(CadImporterAs1, BoundsAreInMetres) {
    // The file declares SI_UNIT(.MILLI.,.METRE.); OCCT's own bounding box of the model is
    // (-10, 0, -4)..(190, 150, 80) mm: the 200 x 150 mm plate plus brackets 80 mm high. In
    // metres that is a 0.2 m plate. Tolerance 0.5 mm: the tessellation deviates from the
    // true surface by at most 0.001 x the 0.26 m diagonal (0.26 mm).
    const Aabb bounds = scene().worldBounds();
    expectNear(bounds.min, {-0.010, 0.0, -0.004}, 0.0005);
    expectNear(bounds.max, {0.190, 0.150, 0.080}, 0.0005);
}

TEST_F(CadImporterAs1, SharedPartInstancesHaveTheirOwnTransforms) {
    // The 8 nuts are one mesh placed by 8 different component locations.
    std::set<std::vector<double>> origins;
    for (const MeshInstance& inst : scene().instances) {
        if (scene().meshes[inst.mesh].name != "nut") continue;
        const glm::dmat4& w = scene().nodes[inst.node].world;
        origins.insert(
            {std::round(w[3][0] * 1e6), std::round(w[3][1] * 1e6), std::round(w[3][2] * 1e6)});
    }
    EXPECT_EQ(origins.size(), 8u);
}

TEST_F(CadImporterAs1, PartColoursBecomeLinearMaterials) {
    // COLOUR_RGB in the file (sRGB): nut (1,0,0), rod (1,0.5,0), bolt (0,0,1), l-bracket
    // (0,1,0), plate (0.8,1,0). Linear values: sRGB 0.5 -> 0.2140, sRGB 0.8 -> 0.6038.
    const std::map<std::string, glm::vec3> expected{{"nut", {1, 0, 0}},
                                                    {"rod", {1, 0.2140f, 0}},
                                                    {"bolt", {0, 0, 1}},
                                                    {"l-bracket", {0, 1, 0}},
                                                    {"plate", {0.6038f, 1, 0}}};
    for (const auto& [name, rgb] : expected) {
        const Mesh* mesh = findMesh(scene(), name);
        ASSERT_NE(mesh, nullptr) << name;
        const glm::vec4 c = scene().materials[mesh->material].baseColor;
        EXPECT_NEAR(c.r, rgb.r, 1e-3) << name;
        EXPECT_NEAR(c.g, rgb.g, 1e-3) << name;
        EXPECT_NEAR(c.b, rgb.b, 1e-3) << name;
        EXPECT_FLOAT_EQ(c.a, 1.0f) << name;
    }
    EXPECT_EQ(scene().materials[findMesh(scene(), "plate")->material].name, "#ccff00");
    // 5 colours + the default material every scene has.
    EXPECT_EQ(scene().materials.size(), 6u);
}

TEST_F(CadImporterAs1, PartsAreClosedAndFaceOutwards) {
    // Every AS1 part is a closed solid: a positive signed volume means reversed faces got
    // their winding flipped. Vertex normals must agree with the winding too.
    for (const Mesh& mesh : scene().meshes) {
        EXPECT_GT(signedVolume(mesh), 0.0) << mesh.name;
        std::size_t agreeing = 0;
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const glm::vec3 a = mesh.positions[mesh.indices[i]];
            const glm::vec3 n = glm::cross(mesh.positions[mesh.indices[i + 1]] - a,
                                           mesh.positions[mesh.indices[i + 2]] - a);
            const glm::vec3 vn = mesh.normals[mesh.indices[i]] + mesh.normals[mesh.indices[i + 1]] +
                                 mesh.normals[mesh.indices[i + 2]];
            if (glm::dot(n, vn) > 0.0f) ++agreeing;
        }
        EXPECT_EQ(agreeing, mesh.triangleCount()) << mesh.name;
    }
}

TEST_F(CadImporterAs1, RecordsTheSourceFile) {
    ASSERT_EQ(scene().sourceFiles.size(), 1u);
    EXPECT_EQ(scene().sourceFiles[0], kAs1);
}

// ---------------------------------------------------------------------------------------
// The OCCT sample kitchen (BREP, modelled in centimetres).

ImportOptions kitchenOptions() {
    ImportOptions options;
    options.cadBrepUnitMetres = 0.01; // SOURCE.txt: a 400 x 400 x 300 cm room
    return options;
}

TEST(CadImporterKitchen, ChairIsFourSolidsInMetres) {
    const Scene scene = importCad(kKitchen / "MODERN_Chair_1.brep", kitchenOptions());
    // The file is a compound of 4 solids (OCCT counts them with TopExp_Explorer): one node and
    // mesh each, named after the file.
    ASSERT_EQ(scene.instances.size(), 4u);
    EXPECT_EQ(scene.meshes.size(), 4u);
    std::vector<std::string> names;
    for (Id c : scene.nodes[0].children)
        names.push_back(scene.nodes[c].name);
    EXPECT_EQ(names, (std::vector<std::string>{"MODERN_Chair_1_1", "MODERN_Chair_1_2",
                                               "MODERN_Chair_1_3", "MODERN_Chair_1_4"}));
    // OCCT's bounding box is (182.5, 119.69, -0.21)..(227.5, 158.81, 85.97) cm: a chair 45 cm
    // wide and 86 cm high. Tolerance 3 mm: BRepBndLib's box of curved faces is up to the
    // poles' hull (the -0.21 cm) while the mesh lies on the surface.
    const Aabb bounds = scene.worldBounds();
    expectNear(bounds.min, {1.825, 1.1969, 0.0}, 0.003);
    expectNear(bounds.max, {2.275, 1.5881, 0.8597}, 0.003);
    // About 2.4K triangles with the default deflection (0.001 x the 1 m diagonal = 1 mm);
    // a plausible range, not an exact value, since it depends on BRepMesh's internals.
    EXPECT_GT(scene.stats().triangles, 1500u);
    EXPECT_LT(scene.stats().triangles, 4000u);
}

TEST(CadImporterKitchen, RoomIsFiveFreeFacesOfTwoTriangles) {
    // Room.brep is 5 bare planar rectangles (floor and 4 walls, no solid): each becomes its own
    // node and mesh, and a rectangle tessellates into exactly 2 triangles.
    const Scene scene = importCad(kKitchen / "Room.brep", kitchenOptions());
    EXPECT_EQ(scene.instances.size(), 5u);
    for (const Mesh& mesh : scene.meshes)
        EXPECT_EQ(mesh.triangleCount(), 2u) << mesh.name;
    const Aabb bounds = scene.worldBounds();
    expectNear(bounds.min, {0.0, 0.0, 0.0}, 1e-6);
    expectNear(bounds.max, {4.0, 4.0, 3.0}, 1e-6); // the 400 x 400 x 300 cm room
}

TEST(CadImporterKitchen, ClosedSetHasSeventeenSolids) {
    // SOURCE.txt: the closed set (8 files) holds 17 solids and Room.brep's 5 faces, ~20K
    // triangles at 0.001 x diagonal. We measure 16.6K; the range allows for BRepMesh details.
    std::size_t items = 0, triangles = 0;
    for (const char* stem :
         {"Room", "MODERN_Table_1", "MODERN_Chair_1", "MODERN_Cooker_1", "MODERN_Exhaust_1",
          "MODERN_MVCooker_1", "MODERN_Refrigerator_1", "MODERN_Sink_1"}) {
        const Scene scene = importCad(kKitchen / (std::string(stem) + ".brep"), kitchenOptions());
        items += scene.instances.size();
        triangles += scene.stats().triangles;
    }
    EXPECT_EQ(items, 17u + 5u);
    EXPECT_GT(triangles, 12'000u);
    EXPECT_LT(triangles, 30'000u);
}

TEST(CadImporterKitchen, FinerDeflectionGivesMoreTriangles) {
    ImportOptions coarse = kitchenOptions();
    coarse.cadRelativeDeflection = 0.01;
    ImportOptions fine = kitchenOptions();
    fine.cadRelativeDeflection = 0.0002;
    const fs::path chair = kKitchen / "MODERN_Chair_1.brep";
    const std::size_t coarseCount = importCad(chair, coarse).stats().triangles;
    const std::size_t defaultCount = importCad(chair, kitchenOptions()).stats().triangles;
    const std::size_t fineCount = importCad(chair, fine).stats().triangles;
    EXPECT_LT(coarseCount, defaultCount);
    EXPECT_LT(defaultCount, fineCount);
}

TEST(CadImporterKitchen, BrepUnitScalesPositions) {
    // The same table read as millimetres is 10 times smaller than read as centimetres.
    ImportOptions mm;
    mm.cadBrepUnitMetres = 0.001;
    const fs::path table = kKitchen / "MODERN_Table_1.brep";
    const Aabb cm = importCad(table, kitchenOptions()).worldBounds();
    const Aabb asMm = importCad(table, mm).worldBounds();
    EXPECT_NEAR(cm.extent().x, 1.0, 1e-3); // a 100 cm table
    EXPECT_NEAR(asMm.extent().x, 0.1, 1e-4);
}

// ---------------------------------------------------------------------------------------
// Models built here with OCCT: exact expectations.

gp_Trsf translation(double x, double y, double z) {
    gp_Trsf t;
    t.SetTranslation(gp_Vec(x, y, z));
    return t;
}

TEST(CadImporter, TransformConversionIsColumnMajorWithTranslationInMetres) {
    // 90 degrees about +Z then a (10, 20, 30) mm shift: x -> y, y -> -x.
    gp_Trsf rotation;
    rotation.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), M_PI / 2);
    const gp_Trsf trsf = translation(10, 20, 30) * rotation;
    const glm::dmat4 m = cad::toGlm(trsf, 0.001);
    expectNear(glm::dvec3(m * glm::dvec4(1, 0, 0, 0)), {0, 1, 0}, 1e-12);
    expectNear(glm::dvec3(m * glm::dvec4(0, 1, 0, 0)), {-1, 0, 0}, 1e-12);
    expectNear(glm::dvec3(m * glm::dvec4(0, 0, 0, 1)), {0.010, 0.020, 0.030}, 1e-12);
    // OCCT maps the point (1, 0, 0) mm to (10, 21, 30) mm.
    const gp_Pnt p = gp_Pnt(1, 0, 0).Transformed(trsf);
    expectNear(glm::dvec3(m * glm::dvec4(0.001, 0, 0, 1)),
               {p.X() * 0.001, p.Y() * 0.001, p.Z() * 0.001}, 1e-12);
}

TEST(CadImporter, BrepRepeatedSolidBecomesOneMeshTwice) {
    // A compound holding the same 10 x 20 x 30 box twice, the second moved by 100 along x:
    // one mesh of 12 triangles (2 per planar face), two instances, 6000 mm^3 each.
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(10, 20, 30).Shape();
    TopoDS_Compound compound;
    BRep_Builder builder;
    builder.MakeCompound(compound);
    builder.Add(compound, box);
    builder.Add(compound, box.Moved(TopLoc_Location(translation(100, 0, 0))));
    const test::TempDir dir;
    const fs::path file = dir / "boxes.brep";
    ASSERT_TRUE(BRepTools::Write(compound, file.string().c_str()));

    const Scene scene = importCad(file, {}); // default: millimetres
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(scene.meshes[0].triangleCount(), 12u);
    // Positions are floats: relative error ~1e-7, so 6e-6 m^3 to within 1e-12.
    EXPECT_NEAR(signedVolume(scene.meshes[0]), 10 * 20 * 30 * 1e-9, 1e-12);
    EXPECT_EQ(scene.nodes[scene.instances[0].node].name, "boxes_1");
    EXPECT_EQ(scene.nodes[scene.instances[1].node].name, "boxes_2");
    EXPECT_NEAR(scene.nodes[scene.instances[1].node].world[3][0], 0.1, 1e-12);
    const Aabb bounds = scene.worldBounds();
    expectNear(bounds.min, {0, 0, 0}, 1e-7);
    expectNear(bounds.max, {0.110, 0.020, 0.030}, 1e-7);
}

// An XCAF document with one named box part (red) placed twice by an assembly; the second
// placement has its own colour (blue) and the part's top face its own (green).
fs::path writeColouredAssembly(const fs::path& file) {
    Handle(TDocStd_Document) doc;
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
    const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    const Handle(XCAFDoc_ColorTool) colours = XCAFDoc_DocumentTool::ColorTool(doc->Main());
    BRepPrimAPI_MakeBox maker(10, 20, 30);
    const TDF_Label part = shapes->AddShape(maker.Shape(), false);
    TDataStd_Name::Set(part, "box");
    colours->SetColor(part, Quantity_Color(1, 0, 0, Quantity_TOC_RGB), XCAFDoc_ColorSurf);
    const TDF_Label top = shapes->AddSubShape(part, maker.TopFace());
    colours->SetColor(top, Quantity_Color(0, 1, 0, Quantity_TOC_RGB), XCAFDoc_ColorSurf);
    const TDF_Label assembly = shapes->NewShape();
    TDataStd_Name::Set(assembly, "pair");
    const TDF_Label left = shapes->AddComponent(assembly, part, TopLoc_Location());
    TDataStd_Name::Set(left, "left");
    const TDF_Label right =
        shapes->AddComponent(assembly, part, TopLoc_Location(translation(50, 0, 0)));
    TDataStd_Name::Set(right, "right");
    colours->SetColor(right, Quantity_Color(0, 0, 1, Quantity_TOC_RGB), XCAFDoc_ColorSurf);
    shapes->UpdateAssemblies();
    STEPCAFControl_Writer writer;
    if (!writer.Transfer(doc, STEPControl_AsIs) ||
        writer.Write(file.string().c_str()) != IFSelect_RetDone) {
        ADD_FAILURE() << "cannot write " << file;
    }
    XCAFApp_Application::GetApplication()->Close(doc);
    return file;
}

TEST(CadImporter, StepFaceAndInstanceColoursSplitMeshes) {
    const test::TempDir dir;
    const Scene scene = importCad(writeColouredAssembly(dir / "pair.step"), {});
    // "left" shows the part colour (red) except the top face (green); "right" has its own
    // colour (blue), but the top face's own colour is more specific and stays green. Each
    // colour is its own mesh: 5 faces = 10 triangles, 1 face = 2 triangles.
    ASSERT_EQ(scene.instances.size(), 4u);
    std::map<std::string, std::vector<std::pair<std::string, std::size_t>>> byNode;
    for (const MeshInstance& inst : scene.instances) {
        const Mesh& mesh = scene.meshes[inst.mesh];
        byNode[scene.nodes[inst.node].name].emplace_back(scene.materials[mesh.material].name,
                                                         mesh.triangleCount());
    }
    for (auto& [node, meshes] : byNode)
        std::sort(meshes.begin(), meshes.end());
    using Entry = std::vector<std::pair<std::string, std::size_t>>;
    EXPECT_EQ(byNode["left"], (Entry{{"#00ff00", 2}, {"#ff0000", 10}}));
    EXPECT_EQ(byNode["right"], (Entry{{"#0000ff", 10}, {"#00ff00", 2}}));
    // The green top face of the red part and of the blue instance are separate meshes
    // (a mesh is shared only when the instance colour matches), named after the part.
    EXPECT_EQ(scene.meshes.size(), 4u);
    for (const Mesh& mesh : scene.meshes)
        EXPECT_EQ(mesh.name.rfind("box_", 0), 0u);
    // Written in millimetres by OCCT's default unit: the right box ends at 60 mm.
    expectNear(scene.worldBounds().max, {0.060, 0.020, 0.030}, 1e-7);
}

// ---------------------------------------------------------------------------------------
// Broken and degenerate input: a typed error naming the file, never a crash.

TEST(CadImporter, TruncatedStepIsMalformedAndNamesTheFile) {
    const std::string text = readText(kAs1);
    const test::TempDir dir;
    const fs::path file = test::writeFile(dir / "half.stp", text.substr(0, text.size() / 2));
    std::string message;
    EXPECT_EQ(importErrorCode(file, &message), ErrorCode::Malformed);
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
}

TEST(CadImporter, StepWithoutProductsIsMalformed) {
    // A syntactically valid AP214 file whose DATA section is empty: nothing to transfer.
    const test::TempDir dir;
    const fs::path file = test::writeFile(dir / "empty.step", R"(ISO-10303-21;
HEADER;
FILE_DESCRIPTION(('empty'),'2;1');
FILE_NAME('empty.step','2024-01-01T00:00:00',(''),(''),'','','');
FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));
ENDSEC;
DATA;
ENDSEC;
END-ISO-10303-21;
)");
    std::string message;
    EXPECT_EQ(importErrorCode(file, &message), ErrorCode::Malformed);
    EXPECT_NE(message.find("no transferable roots"), std::string::npos) << message;
}

TEST(CadImporter, GarbageInEveryCadExtensionIsMalformed) {
    const test::TempDir dir;
    for (const char* name : {"junk.step", "junk.igs", "junk.brep"}) {
        const fs::path file = test::writeFile(dir / name, "this is not a CAD file\n");
        std::string message;
        EXPECT_EQ(importErrorCode(file, &message), ErrorCode::Malformed) << name;
        EXPECT_NE(message.find(name), std::string::npos) << message;
    }
}

TEST(CadImporter, TruncatedBrepIsMalformed) {
    const std::string text = readText(kKitchen / "MODERN_Chair_1.brep");
    const test::TempDir dir;
    const fs::path file = test::writeFile(dir / "chair.brep", text.substr(0, text.size() / 3));
    EXPECT_EQ(importErrorCode(file), ErrorCode::Malformed);
}

TEST(CadImporter, StepWithDanglingReferenceLosesThePartNotTheProcess) {
    // Without the VECTOR entity #77, the LINE #75 of a nut edge keeps a null handle and OCCT
    // 7.6 dereferences it (SIGSEGV in StepToGeom::MakeVectorWithMagnitude). With the crash
    // guard the fault lands in OCCT's own error handler around the solid, which drops that
    // solid: the 8 nut instances are gone, the other 10 part instances load.
    std::string text = readText(kAs1);
    const std::size_t at = text.find("#77 = VECTOR('',#78,1.);");
    ASSERT_NE(at, std::string::npos);
    text.erase(at, text.find('\n', at) + 1 - at); // the file has CRLF line ends
    const test::TempDir dir;
    const Scene scene = importCad(test::writeFile(dir / "dangling.stp", text), {});
    EXPECT_EQ(scene.instances.size(), 18u - 8u);
    EXPECT_EQ(findMesh(scene, "nut"), nullptr);
    // OCCT's state survived the fault: the next STEP and IGES reads work.
    EXPECT_EQ(importCad(kAs1, {}).instances.size(), 18u);
    EXPECT_EQ(importCad(kEdgeCases / "surf114.igs", {}).instances.size(), 4u);
}

TEST(CadImporter, BrepWithUnknownCurveCodeIsMalformedNotAHang) {
    // An edge's curve representation code 1 (3D curve) turned into the unknown code 7: OCCT
    // 7.6's BRepTools_ShapeSet then reads past the end of the data forever unless the stream
    // throws on a failed read.
    std::string text = readText(kKitchen / "MODERN_Chair_1.brep");
    const std::size_t at = text.find("\n1  145 0 4.71238898038469");
    ASSERT_NE(at, std::string::npos);
    text[at + 1] = '7';
    const test::TempDir dir;
    const fs::path file = test::writeFile(dir / "chair.brep", text);
    EXPECT_EQ(importErrorCode(file), ErrorCode::Malformed);
}

TEST(CadImporter, CrashGuardTurnsAFaultIntoAnExceptionAndRestoresHandlers) {
    // A fault outside any OCCT error handler reaches the guard's own catch point.
    struct sigaction before {};
    sigaction(SIGSEGV, nullptr, &before);
    struct sigaction interruptBefore {};
    sigaction(SIGINT, nullptr, &interruptBefore);
    EXPECT_THROW(cad::runGuarded([] { std::raise(SIGSEGV); }), cad::OcctCrash);
    // A second fault works too: the signal was unblocked after the first.
    EXPECT_THROW(cad::runGuarded([] { std::raise(SIGSEGV); }), cad::OcctCrash);
    // Ordinary exceptions pass through unchanged.
    EXPECT_THROW(cad::runGuarded([] { throw std::out_of_range("x"); }), std::out_of_range);
    struct sigaction after {};
    sigaction(SIGSEGV, nullptr, &after);
    EXPECT_EQ(after.sa_flags & SA_SIGINFO, before.sa_flags & SA_SIGINFO);
    EXPECT_EQ(reinterpret_cast<void*>(after.sa_handler),
              reinterpret_cast<void*>(before.sa_handler));
    // OSD::SetSignal also grabs Ctrl-C; the guard must have put it back.
    struct sigaction interruptAfter {};
    sigaction(SIGINT, nullptr, &interruptAfter);
    EXPECT_EQ(reinterpret_cast<void*>(interruptAfter.sa_handler),
              reinterpret_cast<void*>(interruptBefore.sa_handler));
}

TEST(CadImporter, CurvesOnlyGiveNoGeometry) {
    // SOURCE.txt: wire.brep is a wire, curve_geom_plate.igs holds curves and no face.
    EXPECT_EQ(importErrorCode(kEdgeCases / "wire.brep"), ErrorCode::NoGeometry);
    EXPECT_EQ(importErrorCode(kEdgeCases / "curve_geom_plate.igs"), ErrorCode::NoGeometry);
}

TEST(CadImporter, IgesFreeFacesKeepTheirColours) {
    // SOT23.igs (SOURCE.txt: 73 free faces, no solid) becomes 73 nodes and meshes, all in the
    // file's grey (sRGB 0.8); an SOT-23 package is 2.9 mm long.
    const Scene scene = importCad(kEdgeCases / "SOT23.igs", {});
    EXPECT_EQ(scene.instances.size(), 73u);
    EXPECT_EQ(scene.meshes.size(), 73u);
    EXPECT_EQ(scene.materials[scene.meshes[0].material].name, "#cccccc");
    EXPECT_NEAR(scene.worldBounds().extent().x, 0.00292, 0.00005);
}

TEST(CadImporter, RejectsNonPositiveDeflection) {
    ImportOptions options;
    options.cadRelativeDeflection = 0.0;
    try {
        importCad(kAs1, options);
        ADD_FAILURE() << "zero deflection accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
    }
}

} // namespace
} // namespace hlod
