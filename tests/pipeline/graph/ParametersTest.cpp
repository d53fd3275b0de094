// The parameter declarations (pipeline/graph/Parameters.h): defaults agree with the pipeline's
// structs, text and JSON are validated with messages naming the parameter, conversions round
// trip.
#include <gtest/gtest.h>

#include <set>

#include <nlohmann/json.hpp>

#include "TestUtil.h"
#include "pipeline/core/Error.h"
#include "pipeline/graph/Parameters.h"

namespace hlod {
namespace {

using test::problemOf;

TEST(Parameters, EveryBuildFlagIsDeclaredOnceWithAValidDefault) {
    // The flags `hlod build` has always taken (README "Command-line tool").
    const std::set<std::string> flags{
        "--volume", "--k", "--max-children", "--proxy", "--screen-size", "--pixel-error", "--fov",
        "--viewport-height", "--threads", "--cache", "--no-cache", "--no-dlod", "--deflection",
        "--brep-unit", "--geo", "-o", "--compression", "--proxy-textures", "--proxy-ratio",
        "--level-growth",
        // The import budget (ImportLimits.h, issue 22).
        "--max-triangles", "--max-unique-triangles", "--max-instances", "--max-texels"};
    std::set<std::string> keys, declared;
    for (const ParamDecl& d : parameterDeclarations()) {
        EXPECT_TRUE(keys.insert(d.key).second) << d.key << " declared twice";
        EXPECT_NO_THROW(validateValue(d, d.defaultValue)) << d.key;
        EXPECT_FALSE(d.label.empty()) << d.key;
        EXPECT_FALSE(d.tooltip.empty()) << d.key;
        if (!d.cliFlag.empty()) declared.insert(d.cliFlag);
    }
    EXPECT_EQ(declared, flags);
}

TEST(Parameters, DefaultsAreThoseOfThePipelineStructs) {
    const ClusterParams cluster = clusterParamsFrom(defaultValues(NodeKind::Cluster));
    const BakeParams bake = bakeParamsFrom(defaultValues(NodeKind::Bake));
    const ClusterParams cp;
    EXPECT_EQ(cluster.volume, cp.volume);
    EXPECT_EQ(cluster.k, cp.k);
    EXPECT_EQ(cluster.maxChildren, cp.maxChildren);
    // Level growth: the library keeps the thesis' merges, the tool coarsens (LevelGrowth.h).
    EXPECT_EQ(cluster.levelGrowth, kDefaultLevelGrowth);
    EXPECT_EQ(bake.screen.screenSize, 300.0); // the thesis' S: 300 px
    EXPECT_EQ(bake.screen.pixelError, 1.0);
    EXPECT_EQ(bake.method, ProxyMethod::Decimate);
    const ImportOptions io = importOptionsFrom(defaultValues(NodeKind::Import));
    EXPECT_EQ(io.cadRelativeDeflection, ImportOptions{}.cadRelativeDeflection);
    EXPECT_EQ(io.cadBrepUnitMetres, ImportOptions{}.cadBrepUnitMetres);
    EXPECT_EQ(io.limits.maxTriangles, ImportLimits{}.maxTriangles);
    EXPECT_EQ(io.limits.maxUniqueTriangles, ImportLimits{}.maxUniqueTriangles);
    EXPECT_EQ(io.limits.maxInstances, ImportLimits{}.maxInstances);
    EXPECT_EQ(io.limits.maxTexels, ImportLimits{}.maxTexels);
}

TEST(Parameters, TextIsParsedAndCheckedAgainstTheDeclaration) {
    const ParamDecl& k = parameterDeclaration("k");
    EXPECT_EQ(std::get<double>(parseParamText(k, "2", "--k")), 2.0);
    EXPECT_EQ(problemOf([&] { parseParamText(k, "20", "--k"); }),
              "--k must be within [0, 16], got 20");
    EXPECT_EQ(problemOf([&] { parseParamText(k, "abc", "--k"); }),
              "--k expects a number, got 'abc'");
    const ParamDecl& m = parameterDeclaration("max_children");
    EXPECT_EQ(problemOf([&] { parseParamText(m, "2.5", "--max-children"); }),
              "--max-children expects an integer, got '2.5'");
    EXPECT_EQ(
        problemOf([&] { parseParamText(parameterDeclaration("volume"), "cube", "--volume"); }),
        "--volume must be one of sphere, aabb, octree, original, got 'cube'");
}

TEST(Parameters, JsonRoundTripsAndNamesTheFileAndKeyOnError) {
    ParamValues v = defaultValues(NodeKind::Cluster);
    v["k"] = 2.0;
    v["volume"] = std::string("aabb");
    const nlohmann::json j = paramsToJson(NodeKind::Cluster, v);
    EXPECT_EQ(j["k"], 2.0);
    EXPECT_EQ(j["max_children"], 8);
    EXPECT_EQ(paramsFromJson(NodeKind::Cluster, j), v);
    // An integer in the file is fine for a double parameter.
    EXPECT_EQ(std::get<double>(paramsFromJson(NodeKind::Cluster, {{"k", 1}}).at("k")), 1.0);

    try {
        paramsFromJson(NodeKind::Cluster, {{"k", "two"}}, "p.hlodproj");
        FAIL() << "expected Malformed";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ErrorCode::Malformed);
        EXPECT_EQ(std::string(e.what()), "p.hlodproj: k expects a number");
    }
    EXPECT_EQ(problemOf([] {
                  paramsFromJson(NodeKind::Cluster, {{"screen_size", 10}});
              }),
              "unknown cluster parameter 'screen_size'");
}

TEST(Parameters, StructConversionsRoundTrip) {
    BakeParams b;
    b.method = ProxyMethod::Remesh;
    b.screen.screenSize = 150.0;
    b.threads = 3;
    b.cacheDir = "/tmp/cache";
    const BakeParams back = bakeParamsFrom(paramsFrom(b));
    EXPECT_EQ(back.method, ProxyMethod::Remesh);
    EXPECT_EQ(back.screen.screenSize, 150.0);
    EXPECT_EQ(back.threads, 3);
    EXPECT_EQ(back.cacheDir, std::filesystem::path("/tmp/cache"));
    ClusterParams c;
    c.volume = VolumeType::Octree;
    c.maxChildren = 4;
    EXPECT_EQ(paramsFrom(clusterParamsFrom(paramsFrom(c))), paramsFrom(c));
    // No cache: an empty folder means "cache off" once converted.
    ParamValues off = defaultValues(NodeKind::Bake);
    off["cache"] = false;
    EXPECT_TRUE(bakeParamsFrom(off).cacheDir.empty());
}

} // namespace
} // namespace hlod
