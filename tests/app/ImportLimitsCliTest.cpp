// `hlod info` under the import budget (issue 22): a 4 KB COLLADA file whose nodes expand to
// 2^42 is refused in one line that names the file and the limit, within a small memory bound;
// the flags raise or lower the limits; the limits are printed.
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "RunCli.h"
#include "tests/pipeline/TestUtil.h"
#include "tests/pipeline/io/ExpandingFiles.h"

using hlod::test::runCli;

TEST(CliImportLimits, InstancingBombIsOneClearLineAndStaysSmall) {
    hlod::test::TempDir dir;
    const auto file = hlod::test::writeInstancingDae(dir / "bomb.dae", 40);
    const auto r = runCli({"info", file.string()}, 60);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("bomb.dae: its <instance_node> references expand to 4398046511102 nodes, "
                         "over the import limit of 2000000 (--max-instances raises it)"),
              std::string::npos)
        << r.err;
    rusage usage{};
    ::getrusage(RUSAGE_CHILDREN, &usage);
    EXPECT_LT(usage.ru_maxrss, 200L * 1024L) << usage.ru_maxrss << " KiB";
}

TEST(CliImportLimits, FlagsSetTheLimitsAndInfoPrintsThem) {
    hlod::test::TempDir dir;
    const auto file = hlod::test::writeInstancingDae(dir / "small.dae", 4); // 16 instances
    const auto low = runCli({"info", file.string(), "--max-instances", "10"});
    EXPECT_EQ(low.exitCode, 1);
    EXPECT_NE(low.err.find("over the import limit of 10 (--max-instances raises it)"),
              std::string::npos)
        << low.err;
    const auto ok = runCli({"info", file.string(), "--max-triangles", "1000"});
    ASSERT_EQ(ok.exitCode, 0) << ok.err;
    EXPECT_NE(ok.out.find("limits:     1000 triangles (50000000 unique), 2000000 instances, "
                          "536870912 texels"),
              std::string::npos)
        << ok.out;
    const auto j = runCli({"info", file.string(), "--json", "--max-texels", "4096"});
    ASSERT_EQ(j.exitCode, 0) << j.err;
    const auto limits = nlohmann::json::parse(j.out)["import_limits"];
    EXPECT_EQ(limits["max_texels"], 4096);
    EXPECT_EQ(limits["max_instances"], 2000000);
    EXPECT_EQ(limits["max_image_texels"], 67108864);
}
