// The whole robustness corpus (../shared/data/robustness: ~500 odd and broken files in ~45
// formats) through `hlod info`, each in its own process under a 3 GiB address-space limit and a
// timeout: every file either loads (exit 0) or fails cleanly (exit 1, one stderr line that
// names the file). A crash, a hang, an abort or memory exhaustion fails the test.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "RunCli.h"

namespace fs = std::filesystem;
using hlod::test::runCli;

namespace {

fs::path corpus() { return fs::path(HLOD_TEST_DATA_DIR) / "robustness"; }

// One test per folder of the corpus, so ctest can run them in parallel.
std::vector<std::string> corpusFolders() {
    std::vector<std::string> out;
    std::error_code ec;
    for (const fs::path& top : {corpus() / "assimp-testmodels", corpus() / "real-world"}) {
        for (const auto& e : fs::directory_iterator(top, ec)) {
            if (e.is_directory()) out.push_back(fs::relative(e.path(), corpus()).string());
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<fs::path> filesUnder(const fs::path& dir) {
    std::vector<fs::path> out;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        if (e.is_regular_file()) out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string testName(const testing::TestParamInfo<std::string>& info) {
    std::string n = info.param;
    for (char& c : n) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    }
    return n;
}

class RobustnessCorpus : public testing::TestWithParam<std::string> {};

} // namespace

TEST_P(RobustnessCorpus, EveryFileLoadsOrFailsWithOneClearLine) {
    std::size_t loaded = 0, refused = 0;
    for (const fs::path& file : filesUnder(corpus() / GetParam())) {
        const auto r = runCli({"info", file.string()}, 120, 3ull << 30);
        ASSERT_FALSE(r.timedOut) << file << " hung";
        ASSERT_EQ(r.signal, 0) << file << " crashed with signal " << r.signal << "\n" << r.err;
        if (r.exitCode == 0) {
            ++loaded;
            EXPECT_NE(r.out.find("triangles:"), std::string::npos) << file;
            continue;
        }
        ++refused;
        EXPECT_EQ(r.exitCode, 1) << file << ": " << r.err;
        // One line, naming the file.
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << file << ":\n" << r.err;
        EXPECT_NE(r.err.find(file.filename().string()), std::string::npos) << file << ": " << r.err;
    }
    RecordProperty("loaded", static_cast<int>(loaded));
    RecordProperty("refused", static_cast<int>(refused));
    EXPECT_GT(loaded + refused, 0u);
}

INSTANTIATE_TEST_SUITE_P(Corpus, RobustnessCorpus, testing::ValuesIn(corpusFolders()), testName);
