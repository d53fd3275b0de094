// Import dispatch and the failures every format shares.
#include <gtest/gtest.h>

#include <cstring>
#include <unistd.h>

#include "TestUtil.h"
#include "pipeline/core/Error.h"
#include "pipeline/io/Import.h"

using namespace hlod;
using hlod::test::TempDir;

namespace {
ErrorCode codeOf(const std::vector<std::filesystem::path>& inputs, std::string* msg = nullptr) {
    try {
        importScene(inputs);
    } catch (const Error& e) {
        if (msg) *msg = e.what();
        return e.code();
    }
    ADD_FAILURE() << "no error";
    return ErrorCode::Io;
}
} // namespace

TEST(Import, RoutesByExtensionCaseInsensitively) {
    EXPECT_EQ(formatForPath("a.GLB"), SceneFormat::Gltf);
    EXPECT_EQ(formatForPath("a.gltf"), SceneFormat::Gltf);
    EXPECT_EQ(formatForPath("a.STEP"), SceneFormat::Cad); // never assimp
    EXPECT_EQ(formatForPath("a.stp"), SceneFormat::Cad);
    EXPECT_EQ(formatForPath("a.igs"), SceneFormat::Cad);
    EXPECT_EQ(formatForPath("a.brep"), SceneFormat::Cad);
    EXPECT_EQ(formatForPath("a.acc"), SceneFormat::Assimp);
    EXPECT_EQ(formatForPath("a.fbx"), SceneFormat::Assimp);
    EXPECT_EQ(formatForPath("a.docx"), SceneFormat::Unknown);
}

TEST(Import, MissingFileNamesTheFile) {
    std::string msg;
    EXPECT_EQ(codeOf({"/nonexistent/dir/scene.glb"}, &msg), ErrorCode::FileNotFound);
    EXPECT_EQ(msg, "/nonexistent/dir/scene.glb: no such file");
}

TEST(Import, EmptyFileAndUnknownExtensionAndFolder) {
    TempDir dir;
    std::string msg;
    EXPECT_EQ(codeOf({hlod::test::writeFile(dir / "zero.obj", "")}, &msg), ErrorCode::EmptyFile);
    EXPECT_NE(msg.find("zero.obj"), std::string::npos);
    EXPECT_EQ(codeOf({hlod::test::writeFile(dir / "notes.txt", "hello")}),
              ErrorCode::UnknownFormat);
    std::filesystem::create_directories(dir / "empty");
    EXPECT_EQ(codeOf({dir / "empty"}), ErrorCode::UnknownFormat);
}

TEST(Import, UnreadableFileIsReportedNotCrashed) {
    if (geteuid() == 0) GTEST_SKIP() << "root reads any file";
    TempDir dir;
    const auto p = hlod::test::writeFile(dir / "locked.obj", "v 0 0 0\n");
    std::filesystem::permissions(p, std::filesystem::perms::none);
    EXPECT_EQ(codeOf({p}), ErrorCode::FileUnreadable);
}

TEST(Import, PathContainmentResolvesDotDotAndAbsolutePaths) {
    EXPECT_TRUE(isInsideFolder("/a/b/c.bin", "/a/b"));
    EXPECT_TRUE(isInsideFolder("/a/b/sub/../c.bin", "/a/b"));
    EXPECT_FALSE(isInsideFolder("/a/b/../c.bin", "/a/b"));
    EXPECT_FALSE(isInsideFolder("/etc/passwd", "/a/b"));
    EXPECT_FALSE(isInsideFolder("/a/bc/x", "/a/b")); // a prefix of the name is not containment
}

TEST(Import, SeveralFilesBecomeOneSceneWithANodePerFile) {
    TempDir dir;
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    hlod::test::writeFile(dir / "a.obj", tri);
    hlod::test::writeFile(dir / "b.obj", tri);
    const Scene s = importScene({dir / "a.obj", dir / "b.obj"});
    EXPECT_EQ(s.stats().triangles, 2u);
    ASSERT_EQ(s.nodes[0].children.size(), 2u);
    EXPECT_EQ(s.nodes[s.nodes[0].children[0]].name, "a");
    EXPECT_EQ(s.nodes[s.nodes[0].children[1]].name, "b");
    // A folder expands to its loadable files in name order: the same scene.
    const Scene f = importScene({dir.path()});
    EXPECT_EQ(f.stats().triangles, 2u);
    EXPECT_EQ(f.nodes[f.nodes[0].children[1]].name, "b");
}
