// Replays every input checked in under fuzz/regressions/<target>/ (inputs that once crashed
// or broke a reader's contract, kept once fixed) and fuzz/seeds/<target>/ (the hand-made seeds)
// through the same calls the libFuzzer targets make (fuzz/Targets.h). A crash, a sanitizer
// report or an escaping foreign exception fails the test run; what each input was is told in
// fuzz/regressions/README.md.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "fuzz/Targets.h"

namespace {

namespace fs = std::filesystem;

using Target = std::function<void(const std::uint8_t*, std::size_t)>;

const std::map<std::string, Target>& targets() {
    static const std::map<std::string, Target> t = {{"gltf", hlod::fuzz::gltf},
                                                    {"scene", hlod::fuzz::scene},
                                                    {"camera_path", hlod::fuzz::cameraPath},
#ifndef HLOD_FUZZ_NO_PROJECT
                                                    {"project", hlod::fuzz::project},
#endif
                                                    {"proxy_cache", hlod::fuzz::proxyCache},
                                                    {"package", hlod::fuzz::package}};
    return t;
}

// Inputs of one target from both folders, sorted for a stable order.
std::vector<fs::path> inputsOf(const std::string& target) {
    std::vector<fs::path> files;
    for (const char* kind : {"regressions", "seeds"}) {
        const fs::path dir = fs::path(HLOD_TEST_SOURCE_DIR) / ".." / "fuzz" / kind / target;
        if (!fs::is_directory(dir)) continue;
        for (const auto& e : fs::directory_iterator(dir)) {
            if (e.is_regular_file() && e.path().extension() != ".md") files.push_back(e.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

class FuzzRegression : public ::testing::TestWithParam<std::string> {};

TEST_P(FuzzRegression, EveryCheckedInInputIsRefusedCleanlyOrRead) {
    if (!targets().contains(GetParam())) GTEST_SKIP() << "not in this build";
    const Target& run = targets().at(GetParam());
    for (const fs::path& file : inputsOf(GetParam())) {
        SCOPED_TRACE(file.string());
        std::ifstream in(file, std::ios::binary);
        const std::string bytes{std::istreambuf_iterator<char>(in), {}};
        run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    }
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzRegression,
                         ::testing::Values("gltf", "scene", "camera_path", "project", "proxy_cache",
                                           "package"),
                         [](const auto& p) { return p.param; });

} // namespace
