// Materials as authored reach the scene from every importer (issue 28): AC3D surface sides
// (SURF flag 0x20) and `emis` drawn through the object's texture, as TORCS draws it; assimp's
// emissive colour and texture (OBJ Ke / map_Ke) and two-sided property (COLLADA's
// double_sided); glTF's alpha modes, cut-offs, doubleSided, emissive factor, texture and
// strength (MaterialsScene.h); and the scene's binary form keeps them.
#include <gtest/gtest.h>

#include "MaterialsScene.h"
#include "SgiTestFiles.h"
#include "TestUtil.h"
#include "pipeline/io/Ac3dTextures.h"
#include "pipeline/io/Import.h"
#include "pipeline/scene/SceneBinary.h"

using namespace hlod;
using hlod::test::TempDir;

namespace {

// Two objects under a world: "front" has a one-sided polygon with material 0 and a two-sided
// polygon (SURF 0x30: shaded, two-sided) with material 1; "strip" has a two-sided triangle
// strip (0x24, TORCS's .acc type 4) with material 0 and a two-sided line (0x22) with material 1.
// Material 1 emits (0.4 like TORCS' materials), and "front" names a texture.
std::string twoObjects(const std::string& frontTexture) {
    return "AC3Db\n"
           "MATERIAL \"plain\" rgb 1 1 1  amb 0.2 0.2 0.2  emis 0 0 0  spec 0 0 0  shi 0  trans 0\n"
           "MATERIAL \"lit\" rgb 0.4 0.4 0.4  amb 0.8 0.8 0.8  emis 0.4 0.4 0.4  spec 0.5 0.5 0.5"
           "  shi 50  trans 0\n"
           "OBJECT world\nkids 2\n"
           "OBJECT poly\nname \"front\"\n" +
           frontTexture +
           "numvert 4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\nnumsurf 2\n"
           "SURF 0x10\nmat 0\nrefs 3\n0 0 0\n1 1 0\n2 1 1\n"
           "SURF 0x30\nmat 1\nrefs 3\n0 0 0\n2 1 1\n3 0 1\nkids 0\n"
           "OBJECT poly\nname \"strip\"\n"
           "numvert 4\n0 0 1\n1 0 1\n0 1 1\n1 1 1\nnumsurf 2\n"
           "SURF 0x24\nmat 0\nrefs 4\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n"
           "SURF 0x22\nmat 1\nrefs 2\n0 0 0\n1 0 0\nkids 0\n";
}

// A 2x2 verbatim RGB SGI file of one grey.
std::string sgiGrey(std::uint8_t v) {
    std::vector<std::uint8_t> b = hlod::test::sgiHeader(0, 2, 2, 3);
    b.insert(b.end(), 12, v);
    return {b.begin(), b.end()};
}

const Material& materialOfMesh(const Scene& s, const std::string& node, std::size_t nth = 0) {
    for (const MeshInstance& inst : s.instances) {
        if (s.nodes[inst.node].name != node) continue;
        if (nth-- == 0) return s.materials[s.meshes[inst.mesh].material];
    }
    ADD_FAILURE() << "no mesh under " << node;
    return s.materials[0];
}

} // namespace

TEST(Ac3dSurfaces, FlagsAndMaterialOfEverySurfaceAreRead) {
    const auto file = parseAc3dFile(twoObjects(""));
    ASSERT_TRUE(file);
    EXPECT_EQ(file->materials, 2u);
    const Ac3dObject& front = file->objects.front().kids[0];
    ASSERT_EQ(front.surfaces.size(), 2u);
    EXPECT_EQ(front.vertices, 4u);
    EXPECT_EQ(front.surfaces[0].flags, 0x10u);
    EXPECT_EQ(front.surfaces[1].flags, 0x30u);
    EXPECT_EQ(front.surfaces[1].material, 1u);
    EXPECT_EQ(front.surfaces[1].refs, 3u);
}

TEST(Ac3dSurfaces, TwoSidedMaterialsFollowAssimpsMaterialOrder) {
    const auto file = parseAc3dFile(twoObjects(""));
    ASSERT_TRUE(file);
    // assimp: per object (world has no vertices), per used material in index order:
    // front/0 one-sided, front/1 two-sided, strip/0 two-sided strip, strip/1 a line (its
    // material exists, its mesh is dropped later; a line's flag does not count).
    const auto sides = ac3dTwoSidedMaterials(*file, 4);
    ASSERT_TRUE(sides);
    EXPECT_EQ(*sides, (std::vector<bool>{false, true, true, false}));
    EXPECT_FALSE(ac3dTwoSidedMaterials(*file, 5)); // does not pair up: nothing is claimed
}

TEST(MaterialImport, AcTwoSidedSurfacesMakeDoubleSidedMaterials) {
    TempDir dir;
    const Scene s = importScene({hlod::test::writeFile(dir / "t.ac", twoObjects(""))});
    EXPECT_FALSE(materialOfMesh(s, "front", 0).doubleSided);
    EXPECT_TRUE(materialOfMesh(s, "front", 1).doubleSided);
    EXPECT_TRUE(materialOfMesh(s, "strip", 0).doubleSided);
}

TEST(MaterialImport, AcEmisIsEmittedThroughTheObjectsTexture) {
    TempDir dir;
    hlod::test::writeFile(dir / "grey.rgb", sgiGrey(128));
    const Scene s = importScene(
        {hlod::test::writeFile(dir / "t.acc", twoObjects("texture \"grey.rgb\" base\n"))});
    const Material& lit = materialOfMesh(s, "front", 1);
    EXPECT_EQ(lit.emissive, glm::vec3(0.4f));
    EXPECT_EQ(lit.baseColor, glm::vec4(0.4f, 0.4f, 0.4f, 1.0f));
    ASSERT_NE(lit.texture, kNoId);
    EXPECT_EQ(lit.emissiveTexture, lit.texture); // OpenGL modulate: (lit + emis) x texture
    EXPECT_EQ(lit.emissiveTextureFile, lit.baseColorTexture);
    EXPECT_EQ(lit.emissiveMean, glm::vec3(lit.textureMean));
    // Material 0 says emis 0: nothing emitted, no emissive texture.
    const Material& plain = materialOfMesh(s, "front", 0);
    EXPECT_FALSE(plain.emits());
    EXPECT_EQ(plain.emissiveTexture, kNoId);
}

TEST(MaterialImport, ObjEmissiveColourAndTextureAreKept) {
    TempDir dir;
    hlod::test::writeFile(dir / "glow.rgb", sgiGrey(255));
    hlod::test::writeFile(dir / "m.mtl", "newmtl lamp\nKd 0.2 0.2 0.2\nKe 1 0.5 0.25\n"
                                         "map_Ke glow.rgb\n");
    const Scene s = importScene({hlod::test::writeFile(
        dir / "m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                       "usemtl lamp\nf 1/1 2/2 3/3\n")});
    const Material& m = s.materials[s.meshes.at(0).material];
    EXPECT_EQ(m.emissive, glm::vec3(1.0f, 0.5f, 0.25f));
    ASSERT_NE(m.emissiveTexture, kNoId);
    EXPECT_EQ(m.emissiveTextureFile.filename(), "glow.rgb");
    EXPECT_EQ(m.emissiveMean, glm::vec3(1.0f)); // all white texels
    EXPECT_FALSE(m.doubleSided);
}

TEST(MaterialImport, ColladaDoubleSidedIsKept) {
    TempDir dir;
    const std::string dae = R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
 <asset><unit meter="1"/><up_axis>Y_UP</up_axis></asset>
 <library_effects><effect id="fx"><profile_COMMON><technique sid="common"><lambert>
  <diffuse><color>0.5 0.5 0.5 1</color></diffuse></lambert></technique>
  <extra><technique profile="GOOGLEEARTH"><double_sided>1</double_sided></technique></extra>
 </profile_COMMON></effect></library_effects>
 <library_materials><material id="mat" name="leaf"><instance_effect url="#fx"/></material>
 </library_materials>
 <library_geometries><geometry id="g"><mesh>
  <source id="p"><float_array id="pa" count="9">0 0 0 1 0 0 0 1 0</float_array>
   <technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/>
   <param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common>
  </source>
  <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
  <triangles material="m" count="1"><input semantic="VERTEX" source="#v" offset="0"/>
   <p>0 1 2</p></triangles>
 </mesh></geometry></library_geometries>
 <library_visual_scenes><visual_scene id="s"><node id="n" name="card">
  <instance_geometry url="#g"><bind_material><technique_common>
   <instance_material symbol="m" target="#mat"/></technique_common></bind_material>
  </instance_geometry></node></visual_scene></library_visual_scenes>
 <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)";
    const Scene s = importScene({hlod::test::writeFile(dir / "card.dae", dae)});
    EXPECT_TRUE(s.materials[s.meshes.at(0).material].doubleSided);
}

TEST(MaterialImport, GltfMaterialsAreKeptAsAuthored) {
    TempDir dir;
    const Scene s = importScene({hlod::test::writeMaterialsScene(dir.path())});
    auto named = [&](const std::string& name) -> const Material& {
        for (const Material& m : s.materials)
            if (m.name == name) return m;
        ADD_FAILURE() << "no material " << name;
        return s.materials[0];
    };
    EXPECT_EQ(named("Opaque").alphaMode, AlphaMode::Opaque);
    EXPECT_EQ(named("Blend").alphaMode, AlphaMode::Blend);
    EXPECT_EQ(named("MaskLow").alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(named("MaskLow").alphaCutoff, 0.25f);
    EXPECT_FLOAT_EQ(named("MaskDefault").alphaCutoff, 0.5f);
    EXPECT_FLOAT_EQ(named("MaskHigh").alphaCutoff, 0.75f);
    EXPECT_EQ(named("BlendFactor").baseColor.a, 0.5f);
    EXPECT_TRUE(named("DoubleSided").doubleSided);
    EXPECT_FALSE(named("Opaque").doubleSided);
    const Material& glow = named("Emissive");
    EXPECT_EQ(glow.emissive, glm::vec3(1.0f, 0.5f, 0.25f));
    ASSERT_NE(glow.emissiveTexture, kNoId);
    EXPECT_NE(glow.emissiveTexture, glow.texture);
    EXPECT_EQ(glow.emissiveTextureFile.filename(), "glow.png");
    // glow.png: top half white, bottom half (1, 1, 64/255): the blue mean is linear 0.5 x 1
    // + 0.5 x srgbToLinear(64/255) = 0.5 + 0.5 x 0.0513.
    EXPECT_NEAR(glow.emissiveMean.b, 0.5 + 0.5 * 0.0513, 1e-3);
    // Strength 3 scales the factor.
    EXPECT_EQ(named("EmissiveStrong").emissive, glm::vec3(3.0f));
    EXPECT_EQ(named("EmissiveStrong").emissiveTexture, kNoId);
}

TEST(MaterialImport, SceneBinaryKeepsSidesAndEmission) {
    TempDir dir;
    const Scene s = importScene({hlod::test::writeMaterialsScene(dir.path())});
    const Scene back = readSceneBinary(writeSceneBinary(s), "scene.bin");
    ASSERT_EQ(back.materials.size(), s.materials.size());
    for (std::size_t i = 0; i < s.materials.size(); ++i) {
        EXPECT_TRUE(sameLook(back.materials[i], s.materials[i])) << s.materials[i].name;
        EXPECT_EQ(back.materials[i].name, s.materials[i].name);
    }
}
