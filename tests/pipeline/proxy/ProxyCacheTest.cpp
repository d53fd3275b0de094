#include <gtest/gtest.h>

#include <fstream>

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
