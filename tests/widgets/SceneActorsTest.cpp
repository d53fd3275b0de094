// Tests of widgets/SceneActors: both layouts, world transforms, instance mapping, colours.
#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include "TestScenes.h"
#include "widgets/SceneActors.h"

namespace hlod::widgets {
namespace {

TEST(SceneActors, SmallSceneGetsOneActorPerInstanceSharingMeshData) {
    const Scene scene = test::makeTinyScene();
    auto actors = SceneActors::build(scene);
    ASSERT_EQ(actors->layout(), SceneActors::Layout::PerInstance);
    ASSERT_EQ(actors->parts().size(), 3u);
    // Instances 0 and 1 both draw mesh "tri": one polydata, two placements.
    EXPECT_EQ(actors->parts()[0].polyData.Get(), actors->parts()[1].polyData.Get());
    EXPECT_EQ(actors->parts()[0].instance, 0u);
    EXPECT_EQ(actors->parts()[2].instance, 2u);
    EXPECT_EQ(actors->parts()[1].transform[3], glm::dvec4(0, 5, 0, 1)); // node "right"
    EXPECT_EQ(actors->actors().size(), 3u);
    // The actor carries the instance's world matrix: translation (10,0,0) for "left".
    vtkMatrix4x4* m = actors->actors()[0]->GetUserMatrix();
    ASSERT_NE(m, nullptr);
    EXPECT_DOUBLE_EQ(m->GetElement(0, 3), 10.0);
    // Instance 2 sits at the root (identity): no user matrix at all.
    EXPECT_EQ(actors->actors()[2]->GetUserMatrix(), nullptr);
    EXPECT_EQ(actors->triangleCount(), 4u); // 1 + 1 + 2
}

TEST(SceneActors, BoundsCoverEveryInstanceInWorldSpace) {
    // tri at x 10..11, y 0..1; tri scaled 2 at y 5..7, x 0..2; quad 0..1: union x 0..11, y 0..7.
    auto actors = SceneActors::build(test::makeTinyScene());
    const auto& b = actors->bounds();
    EXPECT_DOUBLE_EQ(b[0], 0.0);
    EXPECT_DOUBLE_EQ(b[1], 11.0);
    EXPECT_DOUBLE_EQ(b[2], 0.0);
    EXPECT_DOUBLE_EQ(b[3], 7.0);
    EXPECT_DOUBLE_EQ(b[4], 0.0);
    EXPECT_DOUBLE_EQ(b[5], 0.0);
}

TEST(SceneActors, LargeSceneIsMergedPerMaterialInWorldSpace) {
    SceneActorsOptions options;
    options.mergeAbove = 0; // force the merged layout on the tiny scene
    auto actors = SceneActors::build(test::makeTinyScene(), options);
    ASSERT_EQ(actors->layout(), SceneActors::Layout::PerMaterial);
    // Material 0 holds both triangles (instances 0, 1), material 1 the quad (instance 2).
    ASSERT_EQ(actors->parts().size(), 2u);
    const ScenePart& grey = actors->parts()[0];
    const ScenePart& red = actors->parts()[1];
    EXPECT_EQ(grey.material, 0u);
    EXPECT_EQ(red.material, 1u);
    EXPECT_EQ(grey.polyData->GetNumberOfPoints(), 6);
    EXPECT_EQ(grey.polyData->GetNumberOfCells(), 2);
    EXPECT_EQ(red.polyData->GetNumberOfCells(), 2);
    // Vertex 1 of instance 0 is (1,0,0) + (10,0,0); vertex 5 is (0,1,0) * 2 + (0,5,0).
    double p[3];
    grey.polyData->GetPoint(1, p);
    EXPECT_DOUBLE_EQ(p[0], 11.0);
    grey.polyData->GetPoint(5, p);
    EXPECT_DOUBLE_EQ(p[1], 7.0);
    // Cells map back to the instances they came from.
    EXPECT_EQ(actors->instanceOf(0, 0), 0u);
    EXPECT_EQ(actors->instanceOf(0, 1), 1u);
    EXPECT_EQ(actors->instanceOf(1, 1), 2u);
    EXPECT_EQ(actors->instanceOf(1, 2), kNoId); // no third cell
    EXPECT_EQ(actors->instanceOf(5, 0), kNoId); // no sixth part
    // The instance id array must not become the colouring scalars.
    EXPECT_EQ(grey.polyData->GetCellData()->GetScalars(), nullptr);
    EXPECT_NE(grey.polyData->GetCellData()->GetArray(SceneActors::kInstanceIdArray), nullptr);
}

TEST(SceneActors, ManyMaterialsMergeByOpacityWithColoursPerVertex) {
    // 70 cubes with 70 materials (more than maxMergedParts = 64): one opaque part holding the
    // 69 opaque cubes, one translucent part holding the cube whose material has alpha 0.5.
    Scene scene = test::makeCubeGrid(70);
    for (Id i = 0; i < 70; ++i) {
        Material m;
        m.baseColor = {i / 70.0f, 0.5f, 1.0f - i / 70.0f, i == 7 ? 0.5f : 1.0f};
        const Id material = scene.addMaterial(m);
        Mesh cube = scene.meshes[0];
        cube.material = material;
        scene.instances[i].mesh = scene.addMesh(cube);
    }
    auto actors = SceneActors::build(scene, {.mergeAbove = 0});
    EXPECT_EQ(actors->layout(), SceneActors::Layout::ByOpacity);
    ASSERT_EQ(actors->parts().size(), 2u);
    const ScenePart& opaque = actors->parts()[0];
    const ScenePart& translucent = actors->parts()[1];
    EXPECT_EQ(opaque.material, kNoId);
    EXPECT_TRUE(opaque.vertexColors);
    EXPECT_EQ(opaque.polyData->GetNumberOfCells(), 69 * 12);
    EXPECT_EQ(translucent.polyData->GetNumberOfCells(), 12);
    EXPECT_EQ(actors->instanceOf(1, 0), 7u);
    // The translucent part keeps alpha per vertex: 0.5 -> byte 128.
    auto* rgba =
        vtkUnsignedCharArray::SafeDownCast(translucent.polyData->GetPointData()->GetScalars());
    ASSERT_NE(rgba, nullptr);
    EXPECT_EQ(rgba->GetNumberOfComponents(), 4);
    EXPECT_EQ(rgba->GetValue(3), 128);
    // Cube 0's material: linear (0, 0.5, 1) -> sRGB bytes (0, 188, 255).
    auto* rgb = vtkUnsignedCharArray::SafeDownCast(opaque.polyData->GetPointData()->GetScalars());
    ASSERT_NE(rgb, nullptr);
    EXPECT_EQ(rgb->GetValue(0), 0);
    EXPECT_EQ(rgb->GetValue(1), 188);
    EXPECT_EQ(rgb->GetValue(2), 255);
}

TEST(SceneActors, MaterialColourIncludesTheTextureMean) {
    // A textured material shows base colour x texture mean: (1,1,1) x (0.5,0.5,0.5) -> 0.5
    // linear -> 0.7354 sRGB.
    Scene scene = test::makeTinyScene();
    scene.materials[1].textureMean = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    scene.materials[1].baseColor = glm::vec4(1.0f);
    auto actors = SceneActors::build(scene);
    EXPECT_NEAR(actors->parts()[2].color.g, 0.735357f, 1e-5f);
}

TEST(SceneActors, MergedNormalsUseTheInverseTransposeOfTheInstanceMatrix) {
    // A non-uniform scale (2,1,1) maps normal (1,1,0)/sqrt2 to (0.5,1,0) normalised:
    // (0.4472, 0.8944, 0); a plain matrix multiply would give (0.894, 0.447, 0).
    Scene scene;
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const glm::vec3 n = glm::normalize(glm::vec3(1, 1, 0));
    mesh.normals.assign(3, n);
    mesh.indices = {0, 1, 2};
    const Id m = scene.addMesh(mesh);
    const Id node = scene.addNode("scaled", 0, glm::dmat4(glm::dmat3(2, 0, 0, 0, 1, 0, 0, 0, 1)));
    scene.addInstance(m, node);
    scene.updateWorldTransforms();
    auto actors = SceneActors::build(scene, {.mergeAbove = 0});
    double normal[3];
    actors->parts()[0].polyData->GetPointData()->GetNormals()->GetTuple(0, normal);
    EXPECT_NEAR(normal[0], 0.4472136, 1e-6);
    EXPECT_NEAR(normal[1], 0.8944272, 1e-6);
    EXPECT_NEAR(normal[2], 0.0, 1e-6);
}

TEST(SceneActors, MaterialColourIsConvertedToSrgbForDisplay) {
    auto actors = SceneActors::build(test::makeTinyScene());
    // Red (1,0,0) stays (1,0,0); default grey is whatever Scene() sets, converted.
    EXPECT_FLOAT_EQ(actors->parts()[2].color.r, 1.0f);
    EXPECT_FLOAT_EQ(actors->parts()[2].color.g, 0.0f);
    // sRGB encoding of linear 0.5 is 0.7354 (IEC 61966-2-1).
    EXPECT_NEAR(linearToDisplay(glm::vec4(0.5f)).r, 0.735357f, 1e-5f);
    EXPECT_NEAR(linearToDisplay(glm::vec4(0.002f)).g, 0.02584f, 1e-5f); // linear segment
    EXPECT_FLOAT_EQ(linearToDisplay(glm::vec4(0.5f)).a, 0.5f);          // alpha untouched
}

TEST(SceneActors, VertexColoursBecomeDirectScalars) {
    Scene scene = test::makeTinyScene();
    // Linear 1.0 / 0.0 / 0.2140 encode to sRGB bytes 255 / 0 / 127.
    scene.meshes[0].colors.assign(3, glm::vec4(1.0f, 0.0f, 0.2140f, 1.0f));
    auto actors = SceneActors::build(scene);
    const ScenePart& part = actors->parts()[0];
    EXPECT_TRUE(part.vertexColors);
    auto* scalars = vtkUnsignedCharArray::SafeDownCast(part.polyData->GetPointData()->GetScalars());
    ASSERT_NE(scalars, nullptr);
    EXPECT_EQ(scalars->GetNumberOfComponents(), 3);
    EXPECT_EQ(scalars->GetValue(0), 255);
    EXPECT_EQ(scalars->GetValue(1), 0);
    EXPECT_EQ(scalars->GetValue(2), 127);
    EXPECT_FALSE(actors->parts()[2].vertexColors); // the quad has none
}

TEST(SceneActors, UpAxisFollowsTheSourceFormat) {
    Scene scene;
    EXPECT_EQ(suggestedUpAxis(scene), 1); // sample scene: no files
    scene.sourceFiles = {"/data/part.step", "/data/Room.brep"};
    EXPECT_EQ(suggestedUpAxis(scene), 2);
    scene.sourceFiles = {"/data/room.glb"};
    EXPECT_EQ(suggestedUpAxis(scene), 1);
}

} // namespace
} // namespace hlod::widgets
