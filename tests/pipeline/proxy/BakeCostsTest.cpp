// The cost records of earlier bakes (BakeCosts.h): written per run, merged in name order, and
// a damaged file is skipped (costs are hints), never an error.
#include <gtest/gtest.h>

#include "TestUtil.h"
#include "pipeline/proxy/BakeCosts.h"

using namespace hlod;

TEST(BakeCosts, RecordsMergeInNameOrderAndADamagedFileIsSkipped) {
    test::TempDir cache;
    EXPECT_TRUE(readBakeCosts(cache.path()).empty()); // no folder yet
    writeBakeCosts(cache.path(), "a-0", {{0x10, 1.5}, {0x20, 0.25}});
    writeBakeCosts(cache.path(), "a-1", {{0x20, 2.0}}); // later in name order: wins for 0x20
    writeBakeCosts(cache.path(), "a-2", {});            // nothing baked: no file
    EXPECT_FALSE(std::filesystem::exists(cache / "costs/a-2.costs"));
    test::writeFile(cache / "costs/a-3.costs", "hlod-costs 1\n0000000000000010 oops\n");
    test::writeFile(cache / "costs/b.costs", "not a cost file\n");
    const MeasuredCosts costs = readBakeCosts(cache.path());
    EXPECT_EQ(costs, (MeasuredCosts{{0x10, 1.5}, {0x20, 2.0}}));
}
