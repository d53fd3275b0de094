// Helpers of the distributed-bake tests: a temporary folder, and a folder's files with their
// bytes, to check two packages are byte-identical (same files, same bytes).
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <string>

namespace hlod::test {

class ScratchDir {
public:
    explicit ScratchDir(const std::string& prefix = "hlod-test-") {
        std::random_device rd;
        path_ = std::filesystem::temp_directory_path() /
                (prefix + std::to_string(rd()) + std::to_string(rd()));
        std::filesystem::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    const std::filesystem::path& path() const { return path_; }
    std::string operator/(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

inline std::string fileBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Relative path -> bytes of every regular file below `dir`.
inline std::map<std::string, std::string> folderFiles(const std::filesystem::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
        if (e.is_regular_file())
            files[std::filesystem::relative(e.path(), dir).string()] = fileBytes(e.path());
    }
    return files;
}

// Empty when both folders hold the same files with the same bytes, else what differs.
inline std::string folderDifference(const std::filesystem::path& a,
                                    const std::filesystem::path& b) {
    const auto fa = folderFiles(a), fb = folderFiles(b);
    std::string diff;
    for (const auto& [name, bytes] : fa) {
        const auto it = fb.find(name);
        if (it == fb.end())
            diff += name + " only in " + a.string() + "\n";
        else if (it->second != bytes)
            diff += name + " differs\n";
    }
    for (const auto& [name, bytes] : fb) {
        if (!fa.count(name)) diff += name + " only in " + b.string() + "\n";
    }
    if (fa.empty()) diff += a.string() + " holds no files\n";
    return diff;
}

} // namespace hlod::test
