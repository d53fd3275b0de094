// Faults while writing (issue 22): a full disk or a read-only output folder during export or a
// cache write gives one Error(Io) naming the folder and the system's reason, and leaves the
// previous package and the cache as they were (no temporary files or folders left behind).
//
// The faults are real when the test may mount a file system (root with CAP_SYS_ADMIN, as in
// our CI container): a 1 MiB tmpfs filled up, then remounted read-only. Elsewhere they are
// simulated: RLIMIT_FSIZE (EFBIG past a few bytes, the same code path as ENOSPC) for the full
// disk, a chmod 0555 folder for read-only (skipped as root without mount, where permissions do
// not apply).
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <fstream>
#include <map>
#include <string>

#include <sys/mount.h>
#include <sys/resource.h>
#include <unistd.h>

#include "TestUtil.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/core/AtomicFile.h"
#include "pipeline/core/Error.h"
#include "pipeline/export/Package.h"
#include "pipeline/io/SampleScene.h"
#include "pipeline/proxy/ProxyCache.h"

using namespace hlod;
namespace fs = std::filesystem;

namespace {

struct Built {
    Scene scene = makeSampleScene();
    ClusterTree tree;
    BakeParams params;
    BakeResult bake;
    BakeResult other; // another screen size: different proxies, so different tile files
    Built() {
        tree = buildClusterTree(scene, ClusterParams{});
        params.threads = 2;
        bake = bakeProxies(scene, tree, params);
        BakeParams p = params;
        p.screen.screenSize = 150.0;
        other = bakeProxies(scene, tree, p);
    }
};

const Built& built() {
    static const Built b;
    return b;
}

// Every file under `dir` with its bytes.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        if (!e.is_regular_file()) continue;
        std::ifstream in(e.path(), std::ios::binary);
        files[fs::relative(e.path(), dir).string()] = {std::istreambuf_iterator<char>(in), {}};
    }
    return files;
}

std::size_t entries(const fs::path& dir) {
    return static_cast<std::size_t>(
        std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

// A folder that can be made full or read-only: a small tmpfs when mounting is allowed.
class FaultFolder {
public:
    FaultFolder() {
        mounted_ = ::mount("tmpfs", tmp_.path().c_str(), "tmpfs", MS_NOSUID | MS_NODEV,
                           "size=1m,mode=0755") == 0;
    }
    ~FaultFolder() {
        if (mounted_) ::umount2(tmp_.path().c_str(), MNT_DETACH);
    }
    FaultFolder(const FaultFolder&) = delete;
    FaultFolder& operator=(const FaultFolder&) = delete;

    bool mounted() const { return mounted_; }
    fs::path operator/(const std::string& name) const { return tmp_ / name; }
    const fs::path& path() const { return tmp_.path(); }

    // Fills the file system to the last byte (tmpfs only).
    void fill() const {
        std::ofstream out(tmp_ / "filler", std::ios::binary);
        const std::string block(4096, 'x');
        while (out.write(block.data(), static_cast<std::streamsize>(block.size()))) {
        }
    }
    bool makeReadOnly() const {
        if (mounted_) {
            return ::mount(nullptr, tmp_.path().c_str(), nullptr, MS_REMOUNT | MS_RDONLY,
                           nullptr) == 0;
        }
        if (::geteuid() == 0) return false; // permissions do not stop root
        fs::permissions(tmp_.path(), fs::perms::owner_write, fs::perm_options::remove);
        return true;
    }
    void makeWritable() const {
        if (mounted_) {
            ::mount(nullptr, tmp_.path().c_str(), nullptr, MS_REMOUNT, nullptr);
        } else {
            fs::permissions(tmp_.path(), fs::perms::owner_write, fs::perm_options::add);
        }
    }

private:
    test::TempDir tmp_;
    bool mounted_ = false;
};

// Files written by this process stop growing past `bytes` (EFBIG instead of SIGXFSZ) until
// the object dies: a full disk for the writes under test.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        previousHandler_ = std::signal(SIGXFSZ, SIG_IGN);
        ::getrlimit(RLIMIT_FSIZE, &previous_);
        rlimit limit = previous_;
        limit.rlim_cur = bytes;
        ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    ~FileSizeLimit() {
        ::setrlimit(RLIMIT_FSIZE, &previous_);
        std::signal(SIGXFSZ, previousHandler_);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;

private:
    rlimit previous_{};
    void (*previousHandler_)(int) = SIG_DFL;
};

Error writeError(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e;
    }
    ADD_FAILURE() << "no error";
    return Error(ErrorCode::Io, "none");
}

// A cache entry's mesh: one white triangle.
ProxyMesh oneTriangle() {
    ProxyMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.colors.assign(3, glm::u8vec4(255));
    mesh.indices = {0, 1, 2};
    return mesh;
}

} // namespace

TEST(WriteFaults, ExportOnAFullDiskFailsOnceAndKeepsThePreviousPackage) {
    const Built& b = built();
    FaultFolder folder;
    const fs::path pkg = folder / "pkg";
    writePackage(pkg, b.scene, b.tree, b.bake, b.params, {});
    const auto before = snapshot(pkg);
    const std::size_t siblings = entries(folder.path());
    Error e = [&] {
        if (folder.mounted()) {
            folder.fill();
            return writeError([&] { writePackage(pkg, b.scene, b.tree, b.other, b.params, {}); });
        }
        const FileSizeLimit limit(64);
        return writeError([&] { writePackage(pkg, b.scene, b.tree, b.other, b.params, {}); });
    }();
    EXPECT_EQ(e.code(), ErrorCode::Io);
    EXPECT_EQ(e.file(), fs::absolute(pkg).lexically_normal());
    const std::string reason = folder.mounted() ? "No space left on device" : "File too large";
    EXPECT_NE(e.problem().find(reason), std::string::npos) << e.what();
    EXPECT_NE(e.problem().find("the previous package is unchanged"), std::string::npos) << e.what();
    EXPECT_EQ(e.problem().find('\n'), std::string::npos); // one line
    EXPECT_EQ(snapshot(pkg), before);
    EXPECT_EQ(entries(folder.path()), siblings + (folder.mounted() ? 1 : 0)); // + the filler
}

TEST(WriteFaults, ExportIntoAReadOnlyFolderFailsAndKeepsThePreviousPackage) {
    const Built& b = built();
    FaultFolder folder;
    const fs::path pkg = folder / "pkg";
    writePackage(pkg, b.scene, b.tree, b.bake, b.params, {});
    const auto before = snapshot(pkg);
    if (!folder.makeReadOnly()) GTEST_SKIP() << "cannot make a read-only folder here";
    const Error e = writeError([&] { writePackage(pkg, b.scene, b.tree, b.other, b.params, {}); });
    folder.makeWritable();
    EXPECT_EQ(e.code(), ErrorCode::Io);
    EXPECT_EQ(e.file(), fs::absolute(pkg).lexically_normal());
    EXPECT_NE(e.problem().find(folder.mounted() ? "Read-only file system" : "Permission denied"),
              std::string::npos)
        << e.what();
    EXPECT_EQ(snapshot(pkg), before);
    EXPECT_EQ(entries(folder.path()), 1u); // no temporary sibling left
}

TEST(WriteFaults, CacheStoreOnAFullDiskFailsAndKeepsTheEntriesItHad) {
    FaultFolder folder;
    const ProxyCache cache(folder / "cache");
    ProxyMesh mesh = oneTriangle();
    cache.store(1, mesh);
    const auto before = snapshot(folder / "cache");
    mesh.positions.resize(30000, glm::vec3(0.5f)); // a bigger entry than the space left
    mesh.colors.resize(30000, glm::u8vec4(255));
    const Error e = [&] {
        if (folder.mounted()) {
            folder.fill();
            return writeError([&] { cache.store(2, mesh); });
        }
        const FileSizeLimit limit(64);
        return writeError([&] { cache.store(2, mesh); });
    }();
    EXPECT_EQ(e.code(), ErrorCode::Io);
    EXPECT_EQ(e.file(), cache.fileFor(2));
    EXPECT_NE(e.problem().find("cannot write: "), std::string::npos) << e.what();
    EXPECT_EQ(snapshot(folder / "cache"), before); // no partial entry, no temporary file
    EXPECT_TRUE(cache.load(1).has_value());
    EXPECT_FALSE(cache.load(2).has_value());
}

TEST(WriteFaults, CacheStoreIntoAReadOnlyFolderFailsAndKeepsTheEntries) {
    FaultFolder folder;
    const ProxyCache cache(folder / "cache");
    ProxyMesh mesh = oneTriangle();
    cache.store(1, mesh);
    const auto before = snapshot(folder / "cache");
    if (!folder.mounted()) {
        if (::geteuid() == 0) GTEST_SKIP() << "cannot make a read-only folder here";
        fs::permissions(folder / "cache", fs::perms::owner_write, fs::perm_options::remove);
    } else {
        ASSERT_TRUE(folder.makeReadOnly());
    }
    const Error e = writeError([&] { cache.store(2, mesh); });
    if (folder.mounted()) {
        folder.makeWritable();
    } else {
        fs::permissions(folder / "cache", fs::perms::owner_write, fs::perm_options::add);
    }
    EXPECT_EQ(e.code(), ErrorCode::Io);
    EXPECT_EQ(e.file(), cache.fileFor(2));
    EXPECT_NE(e.problem().find(folder.mounted() ? "Read-only file system" : "Permission denied"),
              std::string::npos)
        << e.what();
    EXPECT_EQ(snapshot(folder / "cache"), before);
    EXPECT_TRUE(cache.load(1).has_value());
}

TEST(WriteFaults, AtomicWriteOnAFullDiskKeepsTheOldFile) {
    FaultFolder folder;
    const fs::path file = folder / "project.hlodproj";
    writeFileAtomic(file, "old");
    const std::string big(200'000, 'n');
    const Error e = [&] {
        if (folder.mounted()) {
            folder.fill();
            return writeError([&] { writeFileAtomic(file, big); });
        }
        const FileSizeLimit limit(64);
        return writeError([&] { writeFileAtomic(file, big); });
    }();
    EXPECT_EQ(e.file(), file);
    EXPECT_EQ(snapshot(folder.path()).at("project.hlodproj"), "old");
    EXPECT_EQ(entries(folder.path()), folder.mounted() ? 2u : 1u); // file (+ filler), no temp
}
