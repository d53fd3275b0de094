// The plan folder of a distributed bake (BakePlan.h): shards run from it alone, the final
// check finds the plan of its own build and names the shards that have not finished, damaged
// plan files are refused with the file named, and `--shard auto/N` reads the schedulers'
// index variables.
#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "TestUtil.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/graph/BakePlan.h"
#include "pipeline/io/SampleScene.h"
#include "pipeline/proxy/BakeCosts.h"
#include "pipeline/proxy/ProxyCache.h"

using namespace hlod;

namespace {

struct Sample {
    Scene scene = makeSampleScene();
    ClusterTree tree = buildClusterTree(scene, ClusterParams{});
    ParamValues bake = [] {
        ParamValues v = defaultValues(NodeKind::Bake);
        v["proxy"] = std::string("sloppy"); // fast; the plan is the same for every method
        v["proxy_textures"] = std::string("off");
        return v;
    }();
};

void flipLastByte(const std::filesystem::path& file) {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(-1, std::ios::end);
    const char c = static_cast<char>(f.get());
    f.seekp(-1, std::ios::end);
    f.put(static_cast<char>(c ^ 0x5a));
}

} // namespace

TEST(BakePlan, ShardsRunFromThePlanAloneAndTheCheckNamesTheMissingOnes) {
    Sample s;
    test::TempDir cache;
    const PlanSummary plan = writeBakePlan(cache.path(), s.scene, s.tree, s.bake, 3);
    EXPECT_EQ(plan.shards.shards, 3);
    EXPECT_TRUE(std::filesystem::exists(cache / "plan/plan.json"));
    EXPECT_TRUE(std::filesystem::exists(cache / "plan/tree.bin"));
    for (int i = 0; i < 3; ++i)
        EXPECT_TRUE(
            std::filesystem::exists(cache / ("plan/shard-" + std::to_string(i) + ".scene")));

    BakeParams params = bakeParamsFrom(s.bake);
    PlanCheck check = checkBakePlan(cache.path(), s.scene, s.tree, params);
    EXPECT_TRUE(check.found);
    EXPECT_TRUE(check.matches);
    EXPECT_EQ(check.missing, (std::vector<int>{0, 1, 2}));

    const ShardResult r = runBakeShard(cache.path(), 1, 3, 1);
    EXPECT_EQ(r.marker, cache / "plan/shard-1.done");
    EXPECT_EQ(r.subtrees, plan.shards.roots[1].size());
    EXPECT_EQ(r.baked + r.reused, r.innerNodes);
    check = checkBakePlan(cache.path(), s.scene, s.tree, params);
    EXPECT_EQ(check.missing, (std::vector<int>{0, 2}));
    EXPECT_EQ(describeMissingShards(check),
              "shards 0 and 2 of 3 have not finished (no shard-0.done, shard-2.done)");

    // Run again (a shard killed after its bake, before its marker): everything is reused.
    const ShardResult again = runBakeShard(cache.path(), 1, 3, 1);
    EXPECT_EQ(again.baked, 0u);
    EXPECT_EQ(again.reused, again.innerNodes);

    runBakeShard(cache.path(), 0, 3, 1);
    runBakeShard(cache.path(), 2, 3, 1);
    EXPECT_TRUE(checkBakePlan(cache.path(), s.scene, s.tree, params).missing.empty());

    // Another plan in the same folder drops the old markers.
    writeBakePlan(cache.path(), s.scene, s.tree, s.bake, 2);
    check = checkBakePlan(cache.path(), s.scene, s.tree, params);
    EXPECT_EQ(check.shards, 2);
    EXPECT_EQ(check.missing, (std::vector<int>{0, 1}));
}

TEST(BakePlan, TheCheckOnlyMatchesTheSameSceneTreeAndParameters) {
    Sample s;
    test::TempDir cache;
    writeBakePlan(cache.path(), s.scene, s.tree, s.bake, 2);
    BakeParams params = bakeParamsFrom(s.bake);
    EXPECT_TRUE(checkBakePlan(cache.path(), s.scene, s.tree, params).matches);
    params.threads = 7; // not part of what is baked
    params.cacheDir = "/elsewhere";
    EXPECT_TRUE(checkBakePlan(cache.path(), s.scene, s.tree, params).matches);
    BakeParams other = params;
    other.screen.screenSize = 200.0;
    EXPECT_FALSE(checkBakePlan(cache.path(), s.scene, s.tree, other).matches);
    Scene moved = s.scene;
    moved.meshes[0].positions[0].x += 0.25f;
    EXPECT_FALSE(checkBakePlan(cache.path(), moved, s.tree, params).matches);
    test::TempDir empty;
    EXPECT_FALSE(checkBakePlan(empty.path(), s.scene, s.tree, params).found);
}

TEST(BakePlan, DamagedOrMissingPlanFilesAreRefusedNamingTheFile) {
    Sample s;
    test::TempDir cache;
    EXPECT_EQ(test::problemOf([&] { runBakeShard(cache.path(), 0, 2, 1); }),
              (cache / "plan/plan.json").string() +
                  ": no such file (run hlod plan SCENE --shards N --cache DIR first)");
    writeBakePlan(cache.path(), s.scene, s.tree, s.bake, 2);
    EXPECT_NE(
        test::problemOf([&] { runBakeShard(cache.path(), 0, 3, 1); }).find("has 2 shards, not 3"),
        std::string::npos);
    flipLastByte(cache / "plan/shard-1.scene");
    EXPECT_EQ(test::problemOf([&] { runBakeShard(cache.path(), 1, 2, 1); }),
              (cache / "plan/shard-1.scene").string() +
                  ": is damaged (checksum mismatch; run hlod plan again)");
    flipLastByte(cache / "plan/tree.bin");
    EXPECT_NE(
        test::problemOf([&] { runBakeShard(cache.path(), 0, 2, 1); }).find("tree.bin: is damaged"),
        std::string::npos);
    test::writeFile(cache / "plan/plan.json", "{\"format\": 1, \"shards\": ");
    EXPECT_EQ(test::problemOf([&] { runBakeShard(cache.path(), 0, 2, 1); }),
              (cache / "plan/plan.json").string() + ": is not valid JSON (damaged?)");
}

TEST(BakePlan, APlanOfTheOldFormatIsRefusedWithRunPlanAgain) {
    Sample s;
    test::TempDir cache;
    writeBakePlan(cache.path(), s.scene, s.tree, s.bake, 2);
    std::ifstream in(cache / "plan/plan.json");
    nlohmann::json j = nlohmann::json::parse(in);
    in.close();
    j["format"] = 1; // written by an hlod before measured costs (no keys.bin) and tiles
    test::writeFile(cache / "plan/plan.json", j.dump());
    EXPECT_EQ(test::problemOf([&] { runBakeShard(cache.path(), 0, 2, 1); }),
              (cache / "plan/plan.json").string() +
                  ": has plan format 1, this hlod reads 3 (run hlod plan again)");
}

TEST(BakePlan, ShardsRecordWhatTheyBakedAndTheNextPlanIsCostedInSeconds) {
    Sample s;
    test::TempDir cache;
    const PlanSummary first = writeBakePlan(cache.path(), s.scene, s.tree, s.bake, 2);
    EXPECT_EQ(first.shards.measuredNodes, 0u); // nothing measured yet: estimated triangles
    EXPECT_EQ(first.shards.secondsPerTriangle, 0.0);
    const ShardResult r0 = runBakeShard(cache.path(), 0, 2, 1);
    const ShardResult r1 = runBakeShard(cache.path(), 1, 2, 1);
    // One record per node a shard baked (the reused ones cost nothing there).
    const MeasuredCosts costs = readBakeCosts(cache.path());
    EXPECT_GT(costs.size(), 0u);
    EXPECT_LE(costs.size(), r0.baked + r1.baked);
    EXPECT_TRUE(std::filesystem::exists(cache / ("costs/" + first.id + "-0.costs")));

    const PlanSummary next = writeBakePlan(cache.path(), s.scene, s.tree, s.bake, 2);
    EXPECT_GE(next.shards.measuredNodes, costs.size()); // copies share a key
    EXPECT_GT(next.shards.secondsPerTriangle, 0.0);
    // Costs are now CPU seconds: the whole tree costs about what the shards measured plus
    // the estimate of the few nodes above the cut, far below its triangle count.
    EXPECT_LT(next.shards.totalCost, first.shards.totalCost / 100.0);
}

TEST(BakePlan, ShardIndexComesFromSlurmKubernetesOrAwsBatch) {
    std::map<std::string, std::string> env;
    auto get = [&](const char* name) -> const char* {
        const auto it = env.find(name);
        return it == env.end() ? nullptr : it->second.c_str();
    };
    EXPECT_NE(test::problemOf([&] { shardIndexFromEnvironment(get); }).find("SLURM_ARRAY_TASK_ID"),
              std::string::npos);
    env["AWS_BATCH_JOB_ARRAY_INDEX"] = "5";
    EXPECT_EQ(shardIndexFromEnvironment(get), 5);
    env["JOB_COMPLETION_INDEX"] = "3";
    EXPECT_EQ(shardIndexFromEnvironment(get), 3);
    env["SLURM_ARRAY_TASK_ID"] = "2";
    EXPECT_EQ(shardIndexFromEnvironment(get), 2);
    env["SLURM_ARRAY_TASK_ID"] = "two";
    EXPECT_EQ(test::problemOf([&] { shardIndexFromEnvironment(get); }),
              "SLURM_ARRAY_TASK_ID=two is not a shard index");
}
