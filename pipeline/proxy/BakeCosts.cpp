// Cost records of earlier bakes in the cache folder, see BakeCosts.h.
#include "pipeline/proxy/BakeCosts.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "pipeline/core/AtomicFile.h"
#include "pipeline/core/Error.h"

namespace hlod {

namespace {

constexpr const char* kHeader = "hlod-costs 1";

// One file's records, or nothing when it is not a whole file of this format.
bool readFile(const std::filesystem::path& file, MeasuredCosts& into) {
    std::ifstream in(file);
    std::string line;
    if (!in || !std::getline(in, line) || line != kHeader) return false;
    MeasuredCosts found;
    while (std::getline(in, line)) {
        unsigned long long key = 0;
        double seconds = 0.0;
        char tail = 0;
        if (std::sscanf(line.c_str(), "%16llx %lf %c", &key, &seconds, &tail) != 2 ||
            !(seconds >= 0.0))
            return false;
        found[static_cast<std::uint64_t>(key)] = seconds;
    }
    for (const auto& [key, seconds] : found)
        into[key] = seconds;
    return true;
}

} // namespace

std::filesystem::path bakeCostsFolder(const std::filesystem::path& cacheDir) {
    return cacheDir / "costs";
}

void writeBakeCosts(const std::filesystem::path& cacheDir, const std::string& name,
                    const std::vector<std::pair<std::uint64_t, double>>& costs) {
    if (costs.empty()) return;
    const std::filesystem::path folder = bakeCostsFolder(cacheDir);
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw Error(ErrorCode::Io, folder, "cannot create folder: " + ec.message());
    std::string text = std::string(kHeader) + "\n";
    char line[64];
    for (const auto& [key, seconds] : costs) {
        std::snprintf(line, sizeof line, "%016llx %.6g\n", static_cast<unsigned long long>(key),
                      seconds);
        text += line;
    }
    writeFileAtomic(folder / (name + ".costs"), text);
}

MeasuredCosts readBakeCosts(const std::filesystem::path& cacheDir) {
    MeasuredCosts costs;
    const std::filesystem::path folder = bakeCostsFolder(cacheDir);
    std::error_code ec;
    if (cacheDir.empty() || !std::filesystem::is_directory(folder, ec)) return costs;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        if (entry.path().extension() == ".costs") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    for (const std::filesystem::path& file : files)
        readFile(file, costs);
    return costs;
}

} // namespace hlod
