// The import budget (pipeline/io/ImportLimits.h, issue 22): small generated files that expand
// into a great deal of work or memory are refused early, with a message naming the file, what
// was counted and the limit; textures past their budget are left undecoded with a reason.
#include <gtest/gtest.h>

#include <stb_image_write.h>

#include "pipeline/io/ImageDecode.h"
#include "pipeline/io/Import.h"
#include "tests/pipeline/TestUtil.h"
#include "tests/pipeline/io/ExpandingFiles.h"
#include "tests/pipeline/io/NestedAssemblyStep.h"

namespace hlod {
namespace {

namespace fs = std::filesystem;
using test::problemOf;

ErrorCode codeOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.code();
    }
    return ErrorCode::InvalidArgument; // "no error" never is this code in these tests
}

TEST(ImportLimits, ColladaInstanceNodeDagIsRefusedBeforeAssimpExpandsIt) {
    test::TempDir dir;
    // 40 levels, 4 KB: 2^40 triangles, 2^42 nodes. Unbounded, 18 levels already took assimp
    // 20 s and 1.6 GB; the scan counts it in one pass over the tags.
    const fs::path file = test::writeInstancingDae(dir / "bomb.dae", 40);
    const std::string problem = problemOf([&] { importScene({file}); });
    EXPECT_NE(problem.find("bomb.dae: its <instance_node> references expand to 4398046511102 "
                           "nodes, over the import limit of 2000000 (--max-instances raises it)"),
              std::string::npos)
        << problem;
    EXPECT_EQ(codeOf([&] { importScene({file}); }), ErrorCode::TooLarge);
    // Its memory is checked by CliImportLimits (a process of its own: RUSAGE_CHILDREN here would
    // include the other tests' readers when the suite runs in one process, as sanitized).
}

TEST(ImportLimits, ColladaWithinTheLimitLoadsEveryExpandedInstance) {
    test::TempDir dir;
    // 4 levels: 16 placed triangles, one shared mesh.
    const Scene s = importScene({test::writeInstancingDae(dir / "small.dae", 4)});
    EXPECT_EQ(s.instances.size(), 16u);
    EXPECT_EQ(s.meshes.size(), 1u);
    // The same file with a lower limit: refused, and the flag that raises it named.
    ImportOptions low;
    low.limits.maxInstances = 10;
    EXPECT_NE(problemOf([&] { importScene({dir / "small.dae"}, low); }).find("--max-instances"),
              std::string::npos);
}

TEST(ImportLimits, ColladaInstanceNodeCycleIsMalformedNotACrash) {
    test::TempDir dir;
    // n0 places n3, which places n2, n1, n0 again: found when the walk comes back to n3.
    const fs::path file = test::writeInstancingDae(dir / "cycle.dae", 3, true);
    EXPECT_EQ(problemOf([&] { importScene({file}); }),
              file.string() + ": node 'n3' places itself (an instancing cycle)");
}

TEST(ImportLimits, StepSubAssemblyReusedAtEveryLevelIsRefusedBeforeTransfer) {
    test::TempDir dir;
    // 10 levels placing the level below twice: 1024 boxes. Under a limit of 100 the NAUO scan
    // refuses it before OpenCASCADE builds the located shapes (24 levels ran past the 600 s
    // reader timeout unbounded).
    const fs::path file = dir / "assembly.step";
    test::writeNestedAssemblyStep(file, 10);
    ImportOptions low;
    low.limits.maxInstances = 100;
    EXPECT_EQ(problemOf([&] { importScene({file}, low); }),
              file.string() + ": its assemblies place 1024 parts once every reused sub-assembly "
                              "is expanded, over the import limit of 100 (--max-instances "
                              "raises it)");
    // Within the default limit every placement is there, the box meshed once.
    const Scene s = importScene({file});
    EXPECT_EQ(s.instances.size(), 1024u);
    EXPECT_EQ(s.meshes.size(), 1u);
}

TEST(ImportLimits, GltfIdenticalPrimitivesAreOneMeshPlacedAgainNotCopies) {
    test::TempDir dir;
    // 1000 triangles read by 500 identical primitives: one mesh of 1000 triangles placed 500
    // times (copied, it was 500,000 stored triangles from a 36 KB buffer).
    const Scene s = importScene({test::writeSharedAccessorGltf(dir / "shared.gltf", 1000, 500)});
    const SceneStats st = s.stats();
    EXPECT_EQ(st.meshes, 1u);
    EXPECT_EQ(st.uniqueTriangles, 1000u);
    EXPECT_EQ(st.instances, 500u);
    EXPECT_EQ(st.triangles, 500'000u);
}

TEST(ImportLimits, GltfDistinctPrimitivesSharingAccessorsAreBoundedBeforeCopying) {
    test::TempDir dir;
    // The same, each primitive with a material of its own: 500 meshes of the same 1000
    // triangles, 500,000 stored triangles.
    const fs::path file = test::writeSharedAccessorGltf(dir / "shared.gltf", 1000, 500, 1, true);
    ImportOptions low;
    low.limits.maxUniqueTriangles = 100'000;
    // Refused at the 101st primitive, before reading it: 101 x 1000 > 100,000.
    EXPECT_EQ(problemOf([&] { importScene({file}, low); }),
              file.string() + ": its mesh primitives declare 101000 triangles or more, over the "
                              "import limit of 100000 (--max-unique-triangles raises it)");
    EXPECT_EQ(importScene({file}).stats().uniqueTriangles, 500'000u);
}

TEST(ImportLimits, InstancesAndPlacedTrianglesOfAFileAreBounded) {
    test::TempDir dir;
    // 3 primitives of 10 triangles placed by 40 nodes: 120 instances, 1,200 placed triangles.
    const fs::path file = test::writeSharedAccessorGltf(dir / "placed.gltf", 10, 3, 40, true);
    ImportOptions fewInstances;
    fewInstances.limits.maxInstances = 100;
    EXPECT_EQ(problemOf([&] { importScene({file}, fewInstances); }),
              file.string() + ": the scene places 120 mesh instances, over the import limit of "
                              "100 (--max-instances raises it)");
    ImportOptions fewTriangles;
    fewTriangles.limits.maxTriangles = 1000;
    EXPECT_EQ(problemOf([&] { importScene({file}, fewTriangles); }),
              file.string() + ": its placed meshes make 1200 triangles, over the import limit "
                              "of 1000 (--max-triangles raises it)");
    // Several files loaded together share the limits: two copies, 240 instances.
    fs::copy_file(file, dir / "placed2.gltf");
    ImportOptions pair;
    pair.limits.maxInstances = 200;
    EXPECT_NE(problemOf([&] {
                  importScene({file, dir / "placed2.gltf"}, pair);
              }).find("placed2.gltf: the scene places 240 mesh instances"),
              std::string::npos);
}

TEST(ImportLimits, PngDeclaringHugeSizeIsNotDecodedAndTheImportGoesOn) {
    test::TempDir dir;
    // 60000 x 60000 RGBA (14.4 GB) declared in 65 bytes.
    const fs::path file =
        test::writeTexturedGltf(dir / "bomb.gltf", {test::pngHeader(60000, 60000)});
    const Scene s = importScene({file});
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].image, nullptr);
    EXPECT_NE(s.textures[0].error.find("bomb.gltf: image 0: image too large (60000 x 60000 "
                                       "texels, over the import limit of 67108864 texels per "
                                       "image); not decoded"),
              std::string::npos)
        << s.textures[0].error;
    EXPECT_EQ(s.stats().triangles, 1u);
}

TEST(ImportLimits, TexturesPastTheFilesTexelBudgetAreLeftUndecoded) {
    test::TempDir dir;
    // Three distinct 64 x 64 images under a budget of two: the third is not decoded.
    std::vector<std::vector<std::uint8_t>> images;
    for (int i = 0; i < 3; ++i) {
        std::vector<std::uint8_t> texels(64 * 64 * 4, 255);
        texels[static_cast<std::size_t>(i) * 4] = 0; // distinct bytes: no shared decode
        std::vector<std::uint8_t> png;
        stbi_write_png_to_func(
            [](void* out, void* data, int size) {
                auto* bytes = static_cast<std::uint8_t*>(data);
                static_cast<std::vector<std::uint8_t>*>(out)->insert(
                    static_cast<std::vector<std::uint8_t>*>(out)->end(), bytes, bytes + size);
            },
            &png, 64, 64, 4, texels.data(), 64 * 4);
        images.push_back(std::move(png));
    }
    const fs::path file = test::writeTexturedGltf(dir / "three.gltf", images);
    ImportOptions two;
    two.limits.maxTexels = 2 * 64 * 64;
    const Scene s = importScene({file}, two);
    ASSERT_EQ(s.textures.size(), 3u);
    EXPECT_NE(s.textures[0].image, nullptr);
    EXPECT_NE(s.textures[1].image, nullptr);
    EXPECT_EQ(s.textures[2].image, nullptr);
    EXPECT_NE(s.textures[2].error.find("three.gltf: image 2: image of 64 x 64 texels not "
                                       "decoded: the scene's textures would pass the import "
                                       "limit of 8192 texels (--max-texels raises it)"),
              std::string::npos)
        << s.textures[2].error;
    // Under the default budget all three decode.
    for (const Texture& t : importScene({file}).textures)
        EXPECT_NE(t.image, nullptr) << t.error;
}

TEST(ImportLimits, TexelBudgetChargesEachImageAgainstBothLimits) {
    TexelBudget b;
    b.imageLimit = 100;
    b.fileLimit = 150;
    std::string why;
    EXPECT_TRUE(b.charge(10, 10, why));  // 100: at the image limit
    EXPECT_FALSE(b.charge(11, 10, why)); // 110 > 100 per image
    EXPECT_NE(why.find("image too large (11 x 10 texels"), std::string::npos);
    EXPECT_TRUE(b.charge(5, 10, why)); // 150 in all
    EXPECT_FALSE(b.charge(1, 1, why)); // 151 > 150
    EXPECT_EQ(b.used, 150u);
}

} // namespace
} // namespace hlod
