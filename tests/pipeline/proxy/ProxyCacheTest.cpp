#include <gtest/gtest.h>

#include <atomic>
#include <csignal>
#include <fstream>

#include <sys/wait.h>
#include <unistd.h>

#include "TestUtil.h"
#include "pipeline/proxy/ContentHash.h"
#include "pipeline/proxy/ProxyCache.h"

using namespace hlod;

namespace {

ProxyMesh triangle() {
    ProxyMesh m;
    m.origin = {1000.5, -2.25, 3.0};
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    m.colors = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}};
    m.indices = {0, 1, 2};
    return m;
}

} // namespace

TEST(ProxyCache, StoredProxyLoadsBitIdentical) {
    test::TempDir dir;
    const ProxyCache cache(dir.path() / "cache"); // created on first store
    const ProxyMesh m = triangle();
    EXPECT_FALSE(cache.load(42).has_value());
    cache.store(42, m);
    const std::optional<ProxyMesh> back = cache.load(42);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(encodeProxy(42, *back), encodeProxy(42, m));
    EXPECT_EQ(back->origin, m.origin);
    // One file named by the key, no temporary file left behind.
    std::size_t files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir.path() / "cache")) {
        EXPECT_EQ(e.path().filename(), "000000000000002a.hlodproxy");
        ++files;
    }
    EXPECT_EQ(files, 1u);
}

TEST(ProxyCache, DamagedOrForeignFilesAreMisses) {
    test::TempDir dir;
    const ProxyCache cache(dir.path());
    cache.store(7, triangle());
    const std::filesystem::path file = cache.fileFor(7);
    // A file stored under another key (renamed by hand) is refused: the key is inside.
    std::filesystem::copy_file(file, cache.fileFor(8));
    EXPECT_FALSE(cache.load(8).has_value());
    // One flipped byte breaks the checksum.
    std::vector<std::uint8_t> bytes = encodeProxy(7, triangle());
    bytes[60] ^= 0x01;
    test::writeFile(file, std::string(bytes.begin(), bytes.end()));
    EXPECT_FALSE(cache.load(7).has_value());
    // Truncated (a crash mid-copy by some other tool) is a miss too, and a new store heals it.
    test::writeFile(file, "HLODPRX");
    EXPECT_FALSE(cache.load(7).has_value());
    cache.store(7, triangle());
    EXPECT_TRUE(cache.load(7).has_value());
}

TEST(ProxyCache, DisabledCacheNeverHitsNorWrites) {
    const ProxyCache cache{std::filesystem::path()};
    EXPECT_FALSE(cache.enabled());
    cache.store(1, triangle());
    EXPECT_FALSE(cache.load(1).has_value());
}

TEST(ContentHash, ValueDoesNotDependOnHowBytesAreSplit) {
    const std::string text = "hierarchical level of detail, 2018";
    ContentHash whole;
    whole.add(text.data(), text.size());
    ContentHash pieces;
    pieces.add(text.data(), 3);
    pieces.add(text.data() + 3, 10);
    pieces.add(text.data() + 13, text.size() - 13);
    EXPECT_EQ(whole.digest(), pieces.digest());
    EXPECT_EQ(whole.digest(), hashBytes(text.data(), text.size()));
}

TEST(ContentHash, IsStableAcrossBuildsAndSensitiveToEveryByte) {
    // Pinned values: cache keys written by one build must be found by the next.
    EXPECT_EQ(toHex(hashBytes("abc", 3)), "be028c78c710bc1e");
    EXPECT_NE(hashBytes("abc", 3), hashBytes("abd", 3));
    EXPECT_NE(hashBytes("abc", 3), hashBytes("abc", 3, 1)); // seeded
    const std::uint8_t zeros[9] = {};
    EXPECT_NE(hashBytes(zeros, 8), hashBytes(zeros, 9)); // length counts
}

TEST(ProxyCache, DamagedFilesAreReportedAsSuch) {
    test::TempDir dir;
    const ProxyCache cache(dir.path());
    bool damaged = true;
    EXPECT_FALSE(cache.load(7, &damaged));
    EXPECT_FALSE(damaged); // missing is not damaged
    cache.store(7, triangle());
    std::filesystem::resize_file(cache.fileFor(7), 20); // a half-written file
    EXPECT_FALSE(cache.load(7, &damaged));
    EXPECT_TRUE(damaged);
}

// Claims exclude other processes (the shards of a distributed bake): a child process holds the
// claim on a key while it "bakes" and stores the proxy; the parent's claim on that key returns
// only after the child let go, so the parent then finds the proxy instead of baking it again.
// Claims end with their process: a key claimed by a process that died is free again.
TEST(ProxyCache, AClaimMakesOtherProcessesWaitForTheProxy) {
    test::TempDir dir;
    const ProxyCache cache(dir.path());
    int ready[2];
    ASSERT_EQ(::pipe(ready), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ProxyCache::Claim claim = cache.claim(99);
        const char held = claim.held() ? 'y' : 'n';
        (void)!::write(ready[1], &held, 1);
        ::usleep(300 * 1000); // baking
        cache.store(99, triangle());
        ::_exit(0); // the claim's lock goes with the process
    }
    char held = 0;
    ASSERT_EQ(::read(ready[0], &held, 1), 1);
    ASSERT_EQ(held, 'y');
    {
        ProxyCache::Claim claim = cache.claim(99);
        EXPECT_TRUE(claim.held());
        EXPECT_TRUE(cache.load(99).has_value()); // stored by the child before it let go
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    EXPECT_TRUE(WIFEXITED(status));
    ::close(ready[0]);
    ::close(ready[1]);
    // Released: no lock file is left behind (the dead child's was taken over and removed).
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "0000000000000063.lock"));
}

TEST(ProxyCache, AWaitingClaimHonoursCancel) {
    test::TempDir dir;
    const ProxyCache cache(dir.path());
    int ready[2];
    ASSERT_EQ(::pipe(ready), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ProxyCache::Claim claim = cache.claim(5);
        (void)!::write(ready[1], "y", 1);
        ::usleep(2000 * 1000);
        ::_exit(0);
    }
    char c = 0;
    ASSERT_EQ(::read(ready[0], &c, 1), 1);
    std::atomic<bool> cancel{true};
    Progress progress;
    progress.cancel = &cancel;
    EXPECT_THROW(cache.claim(5, progress), Error);
    ::kill(child, SIGKILL);
    ::waitpid(child, nullptr, 0);
    ::close(ready[0]);
    ::close(ready[1]);
    EXPECT_TRUE(cache.claim(5).held()); // the killed holder's lock is gone
}
