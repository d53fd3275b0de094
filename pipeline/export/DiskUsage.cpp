// Bytes on disk of files and of a scene's source (see DiskUsage.h).
#include "pipeline/export/DiskUsage.h"

#include <set>
#include <utility>

#include <sys/stat.h>
#include <sys/statvfs.h>

namespace hlod {

namespace fs = std::filesystem;

namespace {

struct Counter {
    DiskFootprint total;
    std::set<std::pair<dev_t, ino_t>> seen;

    void file(const fs::path& p) {
        struct stat st {};
        if (::stat(p.c_str(), &st) != 0) return;
        if (S_ISDIR(st.st_mode)) {
            std::error_code ec;
            for (auto it = fs::recursive_directory_iterator(p, ec);
                 !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
                if (it->is_regular_file(ec)) file(it->path());
            }
            return;
        }
        if (!S_ISREG(st.st_mode) || !seen.insert({st.st_dev, st.st_ino}).second) return;
        ++total.files;
        total.bytes += static_cast<std::uintmax_t>(st.st_size);
        total.bytesOnDisk += static_cast<std::uintmax_t>(st.st_blocks) * 512u;
    }
};

} // namespace

DiskFootprint filesFootprint(const std::vector<fs::path>& paths) {
    Counter c;
    for (const fs::path& p : paths)
        c.file(p);
    return c.total;
}

DiskFootprint sourceFootprint(const Scene& scene) {
    std::vector<fs::path> paths = scene.sourceFiles;
    paths.insert(paths.end(), scene.referencedFiles.begin(), scene.referencedFiles.end());
    for (const Material& m : scene.materials) {
        if (!m.baseColorTexture.empty()) paths.push_back(m.baseColorTexture);
    }
    return filesFootprint(paths);
}

std::uintmax_t blockSizeAt(const fs::path& dir) {
    struct statvfs st {};
    if (::statvfs(dir.c_str(), &st) != 0 || st.f_bsize == 0) return 4096;
    return st.f_bsize;
}

} // namespace hlod
