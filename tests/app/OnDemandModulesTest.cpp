// The heavy libraries (OpenVDB, OpenCASCADE, assimp, VTK) load only in the steps that use them
// (pipeline/core/OnDemand.h, app/CMakeLists.txt): `hlod` links none of them, starts small,
// still reads STEP and assimp formats, remeshes and renders; a missing or broken module is
// named with what it is for and where it was looked for, and nothing is half written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <sys/resource.h>

#include "RunCli.h"
#include "tests/pipeline/TestUtil.h"

using hlod::test::runCli;
using hlod::test::runProcess;

namespace {

std::string scene(const std::string& rel) {
    return std::string(HLOD_TEST_DATA_DIR) + "/scenes/" + rel;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

TEST(OnDemandModules, HlodLinksNoHeavyLibraryAndStartsSmall) {
    const auto ldd = runProcess({"ldd", HLOD_CLI});
    ASSERT_EQ(ldd.exitCode, 0) << ldd.err;
    for (const char* lib : {"libopenvdb", "libTK", "libassimp", "libvtk", "libGL"})
        EXPECT_FALSE(contains(ldd.out, lib)) << lib << " is linked:\n" << ldd.out;
    // A glTF scene needs no module: the whole run stays far below the 85 MB that loading the
    // heavy libraries alone took.
    const auto r = runCli({"info", scene("engine-2cylinder/2CylinderEngine.glb")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    rusage usage{};
    ::getrusage(RUSAGE_CHILDREN, &usage);
    EXPECT_LT(usage.ru_maxrss, 60L * 1024L) << usage.ru_maxrss << " KiB";
}

TEST(OnDemandModules, StepAssimpAndRemeshLoadTheirModules) {
    const auto step = runCli({"info", scene("as1-assembly/as1-oc-214.stp")}, 120);
    ASSERT_EQ(step.exitCode, 0) << step.err;
    EXPECT_TRUE(contains(step.out, "triangles")) << step.out;
    const auto ac = runCli({"info", scene("cg57-cruiser/CG-57.ac")}, 120);
    ASSERT_EQ(ac.exitCode, 0) << ac.err;
    EXPECT_TRUE(contains(ac.out, "triangles")) << ac.out;
    hlod::test::TempDir dir;
    const auto out = dir / "pkg";
    const auto remesh = runCli({"build", scene("as1-assembly/as1-oc-214.stp"), "-o", out.string(),
                                "--no-cache", "--no-dlod", "--proxy", "remesh"},
                               300);
    ASSERT_EQ(remesh.exitCode, 0) << remesh.err;
    EXPECT_TRUE(std::filesystem::is_regular_file(out / "tileset.json"));
}

TEST(OnDemandModules, AMissingModuleIsNamedWithWhereItWasLookedFor) {
    hlod::test::TempDir empty;
    const std::string env = "HLOD_MODULE_DIR=" + empty.path().string();
    const auto r =
        runProcess({"env", env, HLOD_CLI, "info", scene("as1-assembly/as1-oc-214.stp")}, 60);
    EXPECT_EQ(r.exitCode, 1) << r.out;
    EXPECT_TRUE(contains(r.err, "libhlod-cad.so")) << r.err;
    EXPECT_TRUE(contains(r.err, "STEP/IGES/BREP import")) << r.err;
    EXPECT_TRUE(contains(r.err, "not installed")) << r.err;
    EXPECT_TRUE(contains(r.err, empty.path().string())) << r.err;

    // The remesh method's module missing: the build fails naming it and writes no package.
    hlod::test::TempDir dir;
    const auto out = dir / "pkg";
    const auto b =
        runProcess({"env", env, HLOD_CLI, "build", scene("engine-2cylinder/2CylinderEngine.glb"),
                    "-o", out.string(), "--no-cache", "--no-dlod", "--proxy", "remesh"},
                   120);
    EXPECT_EQ(b.exitCode, 1) << b.out;
    EXPECT_TRUE(contains(b.err, "libhlod-vdb.so")) << b.err;
    EXPECT_TRUE(contains(b.err, "remesh (OpenVDB)")) << b.err;
    EXPECT_FALSE(std::filesystem::exists(out / "tileset.json"));
}

TEST(OnDemandModules, ABrokenModuleIsNamed) {
    hlod::test::TempDir dir;
    const auto module = dir / "libhlod-assimp.so";
    std::ofstream(module) << "not a shared library\n";
    const auto r = runProcess({"env", "HLOD_MODULE_DIR=" + dir.path().string(), HLOD_CLI, "info",
                               scene("cg57-cruiser/CG-57.ac")},
                              60);
    EXPECT_EQ(r.exitCode, 1) << r.out;
    EXPECT_TRUE(contains(r.err, module.string())) << r.err;
    EXPECT_TRUE(contains(r.err, "cannot load the assimp import module")) << r.err;
}
