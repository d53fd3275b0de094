// The distributed bake without a scheduler (issue 21): `hlod plan`, a loop of `hlod build
// --shard I/N` processes (what any farm can run), and the final `hlod build` write the package
// a single machine writes, byte for byte; a final build started too early names the missing
// shards; a shard killed half-way is rerun and reuses what it finished; damaged cache files
// are baked again, never trusted. The real Slurm cluster is in SlurmClusterTest.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "FolderCompare.h"
#include "RunCli.h"

using hlod::test::runCli;
using hlod::test::ScratchDir;
namespace fs = std::filesystem;

namespace {

// Every build here uses the embedded sample scene (no SCENE argument): 97 instances, 26
// inner nodes, a second to bake.
void expectOk(const hlod::test::CliResult& r, const std::string& what) {
    ASSERT_FALSE(r.timedOut) << what;
    ASSERT_EQ(r.exitCode, 0) << what << "\n" << r.err;
}

std::vector<fs::path> proxyFiles(const fs::path& cache) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(cache)) {
        if (e.path().extension() == ".hlodproxy") files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace

TEST(CliDistributedBake, ShardsByHandThenTheFinalBuildWriteTheSingleMachinesPackage) {
    ScratchDir tmp;
    expectOk(runCli({"build", "-o", tmp / "plain", "--no-cache"}), "plain build");
    const auto plan = runCli({"plan", "--shards", "4", "--cache", tmp / "cache", "--json"});
    expectOk(plan, "plan");
    const auto j = nlohmann::json::parse(plan.out);
    EXPECT_EQ(j["shards"], 4);
    EXPECT_EQ(j["shard_list"].size(), 4u);
    // Shards 0, 1, 3 by index, shard 2 through the Slurm array variable (auto/N).
    for (const char* i : {"0", "1", "3"})
        expectOk(runCli({"build", "--shard", std::string(i) + "/4", "--cache", tmp / "cache"}),
                 std::string("shard ") + i);
    ::setenv("SLURM_ARRAY_TASK_ID", "2", 1);
    const auto two = runCli({"build", "--shard", "auto/4", "--cache", tmp / "cache", "--json"});
    ::unsetenv("SLURM_ARRAY_TASK_ID");
    expectOk(two, "shard auto/4");
    EXPECT_EQ(nlohmann::json::parse(two.out)["shard"], 2);
    EXPECT_TRUE(fs::exists(tmp.path() / "cache/plan/shard-2.done"));

    const auto final = runCli({"build", "-o", tmp / "final", "--cache", tmp / "cache"});
    expectOk(final, "final build");
    EXPECT_NE(final.out.find("all 4 shards finished"), std::string::npos) << final.out;
    EXPECT_EQ(hlod::test::folderDifference(tmp.path() / "plain", tmp.path() / "final"), "");
}

TEST(CliDistributedBake, TheLeanFinalStepReadsThePlanAndTheShardsTilesNotTheScene) {
    // Issue 30: the shards write their subtrees' finished tiles; the final build bakes the nodes
    // above the cut and links the tiles, without importing or clustering: the same package.
    ScratchDir tmp;
    const std::string cache = tmp / "cache";
    for (const char* compression : {"meshopt", "none"}) {
        SCOPED_TRACE(compression);
        fs::remove_all(tmp.path() / "cache");
        expectOk(runCli({"build", "-o", tmp / "plain", "--no-cache", "--no-dlod", "--compression",
                         compression}),
                 "plain build");
        const auto plan = runCli(
            {"plan", "--shards", "3", "--cache", cache, "--compression", compression, "--json"});
        expectOk(plan, "plan");
        EXPECT_TRUE(nlohmann::json::parse(plan.out)["lean_final"].get<bool>()) << plan.out;
        for (const char* i : {"0", "1", "2"})
            expectOk(runCli({"build", "--shard", std::string(i) + "/3", "--cache", cache}),
                     std::string("shard ") + i);
        EXPECT_TRUE(fs::exists(tmp.path() / "cache/plan/shard-1.tiles"));
        const auto final = runCli({"build", "-o", tmp / "final", "--cache", cache, "--no-dlod",
                                   "--compression", compression});
        expectOk(final, "final build");
        EXPECT_NE(final.out.find("not imported"), std::string::npos) << final.out;
        EXPECT_NE(final.out.find("all 3 shards finished; lean final step"), std::string::npos)
            << final.out;
        EXPECT_EQ(hlod::test::folderDifference(tmp.path() / "plain", tmp.path() / "final"), "");
    }
    // Other parameters than the plan's: not this plan (the classic check warns and bakes all).
    const auto other = runCli({"build", "-o", tmp / "other", "--cache", cache, "--no-dlod",
                               "--compression", "none", "--screen-size", "200"});
    expectOk(other, "build with another screen size");
    EXPECT_EQ(other.out.find("lean final step"), std::string::npos) << other.out;
    EXPECT_NE(other.err.find("holds a plan for another scene or other parameters"),
              std::string::npos)
        << other.err;
    // A damaged shard part is named; running that shard again mends it.
    const fs::path part = tmp.path() / "cache/plan/shard-2.tiles";
    {
        std::fstream f(part, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(static_cast<std::streamoff>(fs::file_size(part) / 2));
        f.put('\x01');
    }
    const auto broken = runCli(
        {"build", "-o", tmp / "broken", "--cache", cache, "--no-dlod", "--compression", "none"});
    EXPECT_EQ(broken.exitCode, 1);
    EXPECT_NE(broken.err.find("shard-2.tiles: is damaged"), std::string::npos) << broken.err;
    EXPECT_FALSE(fs::exists(tmp.path() / "broken"));
    expectOk(runCli({"build", "--shard", "2/3", "--cache", cache}), "shard 2 again");
    const auto mended = runCli(
        {"build", "-o", tmp / "mended", "--cache", cache, "--no-dlod", "--compression", "none"});
    expectOk(mended, "final build after the shard ran again");
    EXPECT_EQ(hlod::test::folderDifference(tmp.path() / "plain", tmp.path() / "mended"), "");
    // A damaged tile is named, with the shard to run again; the package is not written.
    std::vector<fs::path> tiles;
    for (const auto& e : fs::directory_iterator(tmp.path() / "cache/tiles"))
        tiles.push_back(e.path());
    ASSERT_FALSE(tiles.empty());
    std::sort(tiles.begin(), tiles.end());
    {
        std::fstream f(tiles.front(), std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(static_cast<std::streamoff>(fs::file_size(tiles.front()) / 2));
        f.put('\x7f');
    }
    const auto damaged = runCli(
        {"build", "-o", tmp / "damaged", "--cache", cache, "--no-dlod", "--compression", "none"});
    EXPECT_EQ(damaged.exitCode, 1);
    EXPECT_NE(damaged.err.find(tiles.front().filename().string() +
                               ": is damaged (its bytes do not match its name): run hlod build "
                               "--shard "),
              std::string::npos)
        << damaged.err;
    EXPECT_FALSE(fs::exists(tmp.path() / "damaged"));
}

TEST(CliDistributedBake, AFinalBuildStartedTooEarlyNamesTheMissingShards) {
    ScratchDir tmp;
    const std::string cache = tmp / "cache";
    expectOk(runCli({"plan", "--shards", "4", "--cache", cache}), "plan");
    expectOk(runCli({"build", "--shard", "0/4", "--cache", cache}), "shard 0");
    expectOk(runCli({"build", "--shard", "2/4", "--cache", cache}), "shard 2");
    const auto r = runCli({"build", "-o", tmp / "pkg", "--cache", cache});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err.substr(r.err.rfind("hlod build: error:")),
              "hlod build: error: " + cache +
                  "/plan: shards 1 and 3 of 4 have not finished (no shard-1.done, "
                  "shard-3.done): run hlod build --shard I/4 --cache " +
                  cache + " for them, or wait for their jobs\n");
    EXPECT_FALSE(fs::exists(tmp.path() / "pkg"));
}

TEST(CliDistributedBake, AKilledShardIsRerunAndDamagedCacheFilesAreBakedAgain) {
    ScratchDir tmp;
    const std::string cache = tmp / "cache";
    expectOk(runCli({"build", "-o", tmp / "plain", "--no-cache"}), "plain build");
    expectOk(runCli({"plan", "--shards", "2", "--cache", cache}), "plan");
    expectOk(runCli({"build", "--shard", "1/2", "--cache", cache}), "shard 1");
    // Killed half-way: some of its proxies made it to the cache, its marker did not.
    const std::vector<fs::path> files = proxyFiles(cache);
    ASSERT_GE(files.size(), 2u);
    for (std::size_t i = 0; i < files.size(); i += 2)
        fs::remove(files[i]);
    fs::remove(tmp.path() / "cache/plan/shard-1.done");
    const auto rerun = runCli({"build", "--shard", "1/2", "--cache", cache, "--json"});
    expectOk(rerun, "shard 1 again");
    const auto j = nlohmann::json::parse(rerun.out);
    EXPECT_GT(j["reused"].get<int>(), 0) << rerun.out;
    EXPECT_GT(j["baked"].get<int>(), 0) << rerun.out;
    expectOk(runCli({"build", "--shard", "0/2", "--cache", cache}), "shard 0");

    // A damaged file (a bit flipped on the shared disk) is not trusted: baked again.
    const fs::path victim = proxyFiles(cache).front();
    {
        std::fstream f(victim, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(static_cast<std::streamoff>(fs::file_size(victim) / 2));
        f.put('\x7f');
    }
    const auto final = runCli({"build", "-o", tmp / "final", "--cache", cache});
    expectOk(final, "final build");
    EXPECT_NE(final.err.find("hlod build: warning: 1 damaged proxy file in the cache was not "
                             "trusted and was baked again"),
              std::string::npos)
        << final.err;
    EXPECT_EQ(hlod::test::folderDifference(tmp.path() / "plain", tmp.path() / "final"), "");
}

TEST(CliDistributedBake, ShardAndPlanUsageErrorsSayWhatIsWrong) {
    ScratchDir tmp;
    const std::string cache = tmp / "cache";
    auto expectUsage = [](const hlod::test::CliResult& r, const std::string& message) {
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    };
    expectUsage(runCli({"plan", "--shards", "4"}), "missing --cache DIR");
    expectUsage(runCli({"plan", "--cache", cache}), "missing --shards N");
    expectUsage(runCli({"plan", "--shards", "0", "--cache", cache}), "--shards must be within");
    expectUsage(runCli({"plan", "--shards", "2", "--cache", cache, "--no-cache"}),
                "a plan needs the proxy cache");
    expectOk(runCli({"plan", "--shards", "2", "--cache", cache}), "plan");
    expectUsage(runCli({"build", "scene.glb", "--shard", "0/2", "--cache", cache}),
                "a shard takes its scene from the plan");
    expectUsage(runCli({"build", "--shard", "0/2", "--cache", cache, "--screen-size", "200"}),
                "--screen-size cannot be given with --shard");
    expectUsage(runCli({"build", "--shard", "2/2", "--cache", cache}), "got '2/2'");
    expectUsage(runCli({"build", "--shard", "0/2"}), "--shard needs --cache DIR");
    expectUsage(runCli({"build", "--shard", "0/3", "--cache", cache}), "has 2 shards, not 3");
    ::unsetenv("SLURM_ARRAY_TASK_ID");
    ::unsetenv("JOB_COMPLETION_INDEX");
    ::unsetenv("AWS_BATCH_JOB_ARRAY_INDEX");
    expectUsage(runCli({"build", "--shard", "auto/2", "--cache", cache}),
                "none of SLURM_ARRAY_TASK_ID, JOB_COMPLETION_INDEX, AWS_BATCH_JOB_ARRAY_INDEX");
    const auto noPlan = runCli({"build", "--shard", "0/2", "--cache", tmp / "empty"});
    EXPECT_EQ(noPlan.exitCode, 1);
    EXPECT_NE(noPlan.err.find("plan.json: no such file (run hlod plan"), std::string::npos)
        << noPlan.err;
}

TEST(CliDistributedBake, HelpDescribesPlanAndShard) {
    const auto plan = runCli({"help", "plan"});
    EXPECT_EQ(plan.exitCode, 0);
    EXPECT_NE(plan.out.find("--shards N"), std::string::npos) << plan.out;
    EXPECT_NE(plan.out.find("--cache DIR"), std::string::npos) << plan.out;
    const auto build = runCli({"build", "--help"});
    EXPECT_NE(build.out.find("--shard I/N"), std::string::npos) << build.out;
    EXPECT_NE(build.out.find("SLURM_ARRAY_TASK_ID"), std::string::npos) << build.out;
}
