// `hlod info` on a CAD file whose single dense B-spline face the tessellation budget coarsens
// (issue 22): it loads within a memory bound and says which face was coarsened.
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <nlohmann/json.hpp>

#include "RunCli.h"
#include "tests/pipeline/TestUtil.h"
#include "tests/pipeline/io/DenseBsplineBrep.h"

using hlod::test::runCli;

TEST(CliCadBudget, InfoNotesTheCoarsenedFaceAndStaysUnder500MB) {
    hlod::test::TempDir dir;
    const auto file = dir / "terrain.brep";
    hlod::test::writeDenseBsplineBrep(file, 256, 10000.0);
    const auto r = runCli({"info", file.string()}, 120);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("note:       terrain.brep: face 1 (B-spline surface"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("coarsened by the tessellation budget"), std::string::npos) << r.out;
    // Peak resident memory of the CLI and the import child it waited for (without the budget
    // this file takes well over 1 GB; the bound is 500 MB).
    rusage usage{};
    ::getrusage(RUSAGE_CHILDREN, &usage);
    EXPECT_LT(usage.ru_maxrss, 500L * 1024L) << usage.ru_maxrss << " KiB";

    const auto j = runCli({"info", file.string(), "--json"}, 120);
    ASSERT_EQ(j.exitCode, 0) << j.err;
    const auto notes = nlohmann::json::parse(j.out)["import_notes"];
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].get<std::string>().find("face 1"), std::string::npos);
}
