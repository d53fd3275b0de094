// `hlod` end to end: exit codes, the one-line error contract, and `info` on the shared scenes
// with the counts their SOURCE.txt files give.
#include <gtest/gtest.h>

#include <set>

#include <nlohmann/json.hpp>

#include "RunCli.h"

using hlod::test::runCli;

namespace {
std::string scene(const std::string& rel) {
    return std::string(HLOD_TEST_DATA_DIR) + "/scenes/" + rel;
}
} // namespace

TEST(Cli, VersionAndHelp) {
    const auto v = runCli({"--version"});
    EXPECT_EQ(v.exitCode, 0);
    EXPECT_EQ(v.out.rfind("hlod ", 0), 0u);
    EXPECT_EQ(runCli({}).exitCode, 2); // usage on stderr
    EXPECT_EQ(runCli({"frobnicate"}).exitCode, 2);
}

TEST(Cli, UnknownOptionAndBadNumberAreUsageErrors) {
    const auto r = runCli({"info", "--bogus"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("unknown option --bogus"), std::string::npos) << r.err;
    EXPECT_EQ(runCli({"info", "--deflection", "abc"}).exitCode, 2);
}

TEST(Cli, MissingFileGivesOneLineNamingIt) {
    const auto r = runCli({"info", "/no/such/scene.glb"});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err, "hlod info: error: /no/such/scene.glb: no such file\n");
    EXPECT_TRUE(r.out.empty());
}

TEST(Cli, InfoWithoutSceneDescribesTheSample) {
    const auto r = runCli({"info", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["inputs"][0], "sample:plant");
    EXPECT_EQ(j["counts"]["instances"], 97); // see SampleScene test for the breakdown
}

TEST(Cli, InfoJsonOnTheEngineMatchesSourceCounts) {
    const auto r = runCli({"info", scene("engine-2cylinder/2CylinderEngine.glb"), "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["counts"]["triangles"], 121496);       // SOURCE.txt: instanced triangles
    EXPECT_EQ(j["counts"]["unique_triangles"], 75730); // SOURCE.txt: unique triangles
    EXPECT_EQ(j["file_bytes"], 1838084);               // ls -l of the GLB
    EXPECT_EQ(j["bounds"]["unit"], "m");
}

TEST(Cli, InfoJsonListsTheTorcsMaterialsAsAuthored) {
    const auto r = runCli({"info", scene("torcs-spring/spring.acc"), "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    // assimp makes one material per object and material (4418 meshes), plus our default.
    ASSERT_EQ(j["materials"].size(), 4419u);
    std::size_t mask = 0, emitsThroughTexture = 0, doubleSided = 0;
    for (const auto& m : j["materials"]) {
        mask += m["alpha_mode"] == "MASK" ? 1 : 0;
        doubleSided += m["double_sided"].get<bool>() ? 1 : 0;
        // spring.acc's one MATERIAL line: rgb 0.4 0.4 0.4 ... emis 0.4 0.4 0.4.
        if (m["emissive_factor"][0].get<double>() > 0.39 && m.contains("emissive_texture") &&
            m["emissive_texture"] == m["base_color_texture"])
            ++emitsThroughTexture;
    }
    EXPECT_EQ(emitsThroughTexture, 4418u);
    EXPECT_EQ(doubleSided, 0u); // every SURF line of spring.acc is 0x14 (a shaded strip)
    // The objects whose texture has transparent texels (trees, fences): cut-outs at 0.5.
    EXPECT_EQ(mask, 102u);
}

TEST(Cli, InfoJsonListsTheStepAssemblyPartsByName) {
    const auto r = runCli({"info", scene("as1-assembly/as1-oc-214.stp"), "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    // SOURCE.txt: 18 part instances of 5 parts.
    EXPECT_EQ(j["counts"]["instances"], 18);
    EXPECT_EQ(j["counts"]["meshes"], 5);
    std::set<std::string> names;
    for (const auto& inst : j["instances"])
        names.insert(inst["mesh_name"].get<std::string>());
    EXPECT_EQ(names.size(), 5u);
    for (const auto& inst : j["instances"])
        EXPECT_FALSE(inst["name"].get<std::string>().empty());
}

TEST(Cli, InfoOnSeveralBrepFilesMakesOneScene) {
    const std::string k = scene("occt-kitchen/");
    const auto r = runCli(
        {"info", k + "Room.brep", k + "MODERN_Table_1.brep", k + "MODERN_Chair_1.brep", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["inputs"].size(), 3u);
    EXPECT_GE(j["counts"]["instances"].get<int>(), 3);
}
