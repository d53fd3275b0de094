// Report writers of `hlod bench`: summaries, CSV, JSON and markdown.
#include <gtest/gtest.h>

#include <sstream>

#include "TestUtil.h"
#include "pipeline/core/Error.h"
#include "pipeline/eval/BenchReport.h"

using namespace hlod;

namespace {

std::vector<FrameRecord> sampleRecords() {
    std::vector<FrameRecord> r;
    for (int f = 0; f < 20; ++f) {
        r.push_back({f, f * 0.1, "Original", 100, 1000, 50, 10.0 + f, 5.0, 100.0, 0.0});
        // FLIP 0.001 f; a level switch at frames 5, 10 and 15 with a pop of 0.01 f.
        const bool sw = f > 0 && f % 5 == 0;
        r.push_back({f, f * 0.1, "HLOD, AABB k=1", static_cast<std::uint64_t>(10 + f), 300, 30, 2.0,
                     7.0, 40.0 - f * 0.1, 0.01, 0.001 * f, sw, sw ? 0.01 * f : 0.0});
    }
    return r;
}

} // namespace

TEST(BenchReport, Percentile) {
    EXPECT_EQ(percentile({}, 95), 0.0);
    std::vector<double> v;
    for (int i = 1; i <= 100; ++i)
        v.push_back(i);
    EXPECT_EQ(percentile(v, 95), 95.0);
    EXPECT_EQ(percentile(v, 100), 100.0);
    EXPECT_EQ(percentile({3.0, 1.0, 2.0}, 50), 2.0);
}

TEST(BenchReport, SummaryPerConfigInOrder) {
    const auto s = summarizeFrames(sampleRecords());
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[0].config, "Original");
    EXPECT_EQ(s[0].frames, 20);
    EXPECT_DOUBLE_EQ(s[0].drawCallsMean, 100.0);
    EXPECT_DOUBLE_EQ(s[0].frameMsMean, 19.5);
    EXPECT_DOUBLE_EQ(s[0].frameMsP95, 28.0); // nearest rank ceil(0.95 * 20) = 19 of 10..29
    EXPECT_DOUBLE_EQ(s[0].psnrMin, 100.0);
    EXPECT_DOUBLE_EQ(s[1].drawCallsMean, 19.5);
    EXPECT_EQ(s[1].drawCallsMax, 29u);
    EXPECT_NEAR(s[1].psnrMin, 38.1, 1e-9);
    EXPECT_DOUBLE_EQ(s[1].selectionUsMean, 7.0);
    EXPECT_NEAR(s[1].flipMean, 0.0095, 1e-12); // 0.001 x mean of 0..19
    EXPECT_DOUBLE_EQ(s[1].flipMax, 0.019);
    EXPECT_EQ(s[1].switches, 3);
    EXPECT_NEAR(s[1].popMean, 0.10, 1e-12); // (0.05 + 0.10 + 0.15) / 3 switch frames
    EXPECT_DOUBLE_EQ(s[1].popMax, 0.15);
    EXPECT_EQ(s[0].switches, 0);
    EXPECT_EQ(s[0].popMean, 0.0);
}

TEST(BenchReport, CsvHasHeaderAndOneRowPerRecord) {
    const std::string csv = framesCsv(sampleRecords());
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, kFramesCsvHeader);
    int rows = 0;
    while (std::getline(in, line))
        ++rows;
    EXPECT_EQ(rows, 40);
    EXPECT_NE(csv.find("0,0.0000,\"HLOD, AABB k=1\",10,300,30,2.0000,40.000,0.010000,0.000000,0,"
                       "0.000000"),
              std::string::npos)
        << csv.substr(0, 300);
}

TEST(BenchReport, JsonAndMarkdown) {
    const auto s = summarizeFrames(sampleRecords());
    const auto j = summaryJson(s, {{"frames", 20}});
    EXPECT_EQ(j["frames"], 20);
    ASSERT_EQ(j["configs"].size(), 2u);
    EXPECT_EQ(j["configs"][1]["config"], "HLOD, AABB k=1");
    EXPECT_DOUBLE_EQ(j["configs"][1]["draw_calls"]["mean"].get<double>(), 19.5);
    EXPECT_TRUE(j["configs"][0]["frame_ms"].contains("p95"));
    EXPECT_TRUE(j["configs"][0]["selection_us"].contains("mean"));
    EXPECT_EQ(j["configs"][1]["pop"]["switches"], 3);
    EXPECT_DOUBLE_EQ(j["configs"][1]["pop"]["max"].get<double>(), 0.15);
    EXPECT_DOUBLE_EQ(j["configs"][1]["flip"]["max"].get<double>(), 0.019);

    GeometryStats g{"Original", 1250000, 847000, 1317, 65000000};
    const std::string md = tablesMarkdown("scene", {g}, s);
    EXPECT_NE(md.find("| Original | 1.25M | 847K | 1317 | 65.00 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| HLOD, AABB k=1 | 19.5 | 29 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| 0.0095 | 0.0190 | 3 | 0.1000 | 0.1500 |"), std::string::npos) << md;

    hlod::test::TempDir dir;
    writeTextFileAtomic(dir / "a.txt", "hello");
    std::ifstream f(dir / "a.txt");
    std::string text;
    std::getline(f, text);
    EXPECT_EQ(text, "hello");
    EXPECT_FALSE(std::filesystem::exists(dir / "a.txt.tmp"));
    EXPECT_THROW(writeTextFileAtomic(dir / "no" / "such" / "a.txt", "x"), Error);
}
