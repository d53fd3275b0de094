// The image cache between exports (EncodedImageCache.h): its files hold what was stored and
// nothing else is taken for it (another key, a cut or changed file), a cache that cannot be
// written costs nothing but time, and an export with the cache writes the same package as one
// without it while taking stacked pages and converted source textures from it.
#include <gtest/gtest.h>

#include <fstream>

#include <glm/gtc/matrix_transform.hpp>

#include "TestUtil.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/export/EncodedImageCache.h"
#include "pipeline/export/Package.h"
#include "pipeline/export/TileContent.h"
#include "pipeline/scene/Primitives.h"

using namespace hlod;
namespace fs = std::filesystem;

namespace {

EncodedImage png(int w, int h, std::uint8_t shade) {
    RgbaImage image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            image.set(x, y, glm::u8vec4(shade, static_cast<std::uint8_t>(x * 9), y, 255));
    return encodePng(image);
}

std::string readAll(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeAll(const fs::path& file, const std::string& bytes) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

// A scene of two textured boxes whose textures stack into one page (StackedAtlas.h), and a
// third box whose texture is a TGA file on disk (converted to PNG for glTF).
Scene texturedScene(const fs::path& folder) {
    Scene s;
    for (int i = 0; i < 2; ++i) {
        auto img = std::make_shared<RgbaImage>(32, 32);
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x)
                img->set(x, y, glm::u8vec4(x * 8, y * 8, 100 * i, 255));
        Texture t;
        t.name = i == 0 ? "a.png" : "b.png";
        t.file = "/textures/" + t.name;
        t.image = img;
        const Id texture = s.addTexture(t);
        Material m;
        m.name = t.name;
        m.hasTexture = true;
        m.texture = texture;
        m.baseColorTexture = t.file;
        m.textureMean = meanLinearColor(*img);
        const Id material = s.addMaterial(m);
        Mesh box = makeBox({1, 1, 1});
        box.uvs.assign(box.positions.size(), glm::vec2(0.25f, 0.5f));
        box.material = material;
        const Id node = s.addNode("box", 0, glm::translate(glm::dmat4(1.0), {2.0 * i, 0, 0}));
        s.addInstance(s.addMesh(std::move(box)), node);
    }
    // 2 x 2 uncompressed true-colour TGA with alpha (type 2, 32 bits, origin top left).
    std::string tga(18, '\0');
    tga[2] = 2;
    tga[12] = 2, tga[14] = 2, tga[16] = 32, tga[17] = 0x28;
    for (int i = 0; i < 4; ++i)
        tga += std::string{char(10 * i), char(200 - i), char(60), char(255)};
    writeAll(folder / "wall.tga", tga);
    Material wall;
    wall.name = "wall";
    wall.hasTexture = true;
    wall.baseColorTexture = folder / "wall.tga";
    const Id wallMaterial = s.addMaterial(wall);
    Mesh box = makeBox({1, 1, 1});
    box.uvs.assign(box.positions.size(), glm::vec2(0.5f, 0.5f));
    box.material = wallMaterial;
    s.addInstance(s.addMesh(std::move(box)), s.addNode("wall", 0, glm::dmat4(1.0)));
    s.updateWorldTransforms();
    return s;
}

Id materialNamed(const Scene& s, const std::string& name) {
    for (Id m = 0; m < s.materials.size(); ++m)
        if (s.materials[m].name == name) return m;
    return kNoId;
}

} // namespace

TEST(EncodedImageCache, GivesBackWhatWasStoredAndNothingElse) {
    hlod::test::TempDir tmp;
    const EncodedImageCache cache(tmp / "images");
    const EncodedImage a = png(5, 3, 7);
    EXPECT_FALSE(cache.load(1)); // empty folder
    cache.store(1, a);
    const std::optional<EncodedImage> back = cache.load(1);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->bytes, a.bytes);
    EXPECT_EQ(back->mimeType, "image/png");
    EXPECT_FALSE(cache.load(2)); // another key
    // The file of key 1 renamed to key 2 holds key 1: not taken for key 2.
    fs::copy_file(cache.fileFor(1), cache.fileFor(2));
    EXPECT_FALSE(cache.load(2));
    // One byte of the image changed, or the file cut short: a miss, not other bytes.
    std::string bytes = readAll(cache.fileFor(1));
    bytes[bytes.size() - 5] ^= 0x40;
    writeAll(cache.fileFor(1), bytes);
    EXPECT_FALSE(cache.load(1));
    cache.store(1, a); // replaced whole
    ASSERT_TRUE(cache.load(1));
    writeAll(cache.fileFor(1), readAll(cache.fileFor(1)).substr(0, 40));
    EXPECT_FALSE(cache.load(1));
    EXPECT_EQ(cache.hits(), 2u);
    // A disabled cache and one that cannot be written: nothing stored, no error.
    const EncodedImageCache off;
    off.store(3, a);
    EXPECT_FALSE(off.load(3));
    hlod::test::writeFile(tmp / "file", "a file where the folder would be");
    const EncodedImageCache blocked(tmp / "file" / "images");
    EXPECT_NO_THROW(blocked.store(3, a));
    EXPECT_FALSE(blocked.load(3));
}

TEST(EncodedImageCache, PagesAndConvertedTexturesComeFromTheCacheTheSameBytes) {
    hlod::test::TempDir tmp;
    const Scene s = texturedScene(tmp.path());
    const fs::path folder = tmp / "images";
    TextureStore first(s, folder);
    ASSERT_FALSE(first.atlases().pages().empty());
    const std::string page = first.pageUri(0);
    const Id wallMaterial = materialNamed(s, "wall");
    ASSERT_NE(wallMaterial, kNoId);
    const std::string wall = first.uriFor(wallMaterial);
    ASSERT_FALSE(wall.empty());
    EXPECT_EQ(first.cachedImages(), 0u);
    TextureStore second(s, folder);
    EXPECT_EQ(second.pageUri(0), page);
    EXPECT_EQ(second.uriFor(wallMaterial), wall);
    EXPECT_EQ(second.cachedImages(), 2u); // the page and the TGA, not encoded again
    EXPECT_EQ(second.files(), first.files());
    TextureStore without(s);
    EXPECT_EQ(without.pageUri(0), page);
    EXPECT_EQ(without.uriFor(wallMaterial), wall);
    EXPECT_EQ(without.files(), first.files());
    EXPECT_EQ(without.cachedImages(), 0u);
}

TEST(EncodedImageCache, AnExportWithTheCacheWritesThePackageOneWithoutItWrites) {
    hlod::test::TempDir tmp;
    const Scene s = texturedScene(tmp.path());
    const ClusterTree tree = buildClusterTree(s, ClusterParams{});
    BakeParams params;
    params.threads = 1;
    const BakeResult bake = bakeProxies(s, tree, params);
    PackageOptions options;
    writePackage(tmp / "plain", s, tree, bake, params, options);
    params.cacheDir = tmp / "cache";
    writePackage(tmp / "cold", s, tree, bake, params, options);
    ASSERT_TRUE(fs::exists(imageCacheFolder(params.cacheDir)));
    std::size_t stored = 0;
    for (const auto& e : fs::directory_iterator(imageCacheFolder(params.cacheDir))) {
        EXPECT_EQ(e.path().extension(), ".hlodimage");
        ++stored;
    }
    EXPECT_EQ(stored, 2u);
    writePackage(tmp / "warm", s, tree, bake, params, options);
    // Every cached image damaged: encoded again, the same package.
    for (const auto& e : fs::directory_iterator(imageCacheFolder(params.cacheDir))) {
        std::string bytes = readAll(e.path());
        bytes.back() ^= 0x01;
        writeAll(e.path(), bytes);
    }
    writePackage(tmp / "damaged", s, tree, bake, params, options);
    for (const char* name : {"cold", "warm", "damaged"}) {
        std::size_t files = 0;
        for (const auto& e : fs::recursive_directory_iterator(tmp / "plain")) {
            if (!e.is_regular_file()) continue;
            const fs::path other = tmp / name / fs::relative(e.path(), tmp / "plain");
            EXPECT_EQ(readAll(other), readAll(e.path())) << name << ": " << other;
            ++files;
        }
        EXPECT_GT(files, 3u);
    }
}
