// `.hlodproj` files (pipeline/doc/ProjectFile.h): round trip with relative scene paths, atomic
// save, clear errors, autosave and recovery.
#include <gtest/gtest.h>

#include <fstream>
#include <thread>

#include "DocumentFixture.h"
#include "pipeline/core/Error.h"
#include "pipeline/doc/Commands.h"
#include "pipeline/doc/ProjectFile.h"

namespace hlod {
namespace {

using ProjectFile = test::DocumentFixture;

std::pair<ErrorCode, std::string> errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return {e.code(), e.what()};
    }
    return {ErrorCode::Io, "no error"};
}

TEST_F(ProjectFile, RoundTripKeepsGraphParametersHandEditsAndView) {
    doc.execute(std::make_unique<SetParameter>(kDefaultCluster, "k", 2.0));
    doc.execute(
        std::make_unique<MergeClusters>(kDefaultCluster, std::vector<InstanceSet>{{0}, {5}}));
    doc.execute(std::make_unique<ExcludeInstance>(kDefaultCluster, InstanceSet{3}));
    doc.setViewState({{"camera", {{"distance", 12.5}}}});
    const auto file = tmp / "p.hlodproj";
    saveProject(doc, file);
    const Document back = openProject(file);
    EXPECT_EQ(back.toJson(), doc.toJson());
    EXPECT_FALSE(back.isDirty());

    // Scene paths are stored relative to the project's folder.
    std::ifstream in(file);
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["version"], 1);
    EXPECT_EQ(j["graph"]["nodes"][0]["sources"][0], "scene/cube_0.glb");
    EXPECT_EQ(j["graph"]["nodes"][1]["hand_edits"]["locked"], nlohmann::json({{0, 5}}));
}

TEST_F(ProjectFile, MovingTheFolderKeepsTheProjectWorking) {
    saveProject(doc, tmp / "p.hlodproj");
    std::filesystem::rename(tmp.path(), tmp.path().string() + "-moved");
    const std::filesystem::path moved = tmp.path().string() + "-moved";
    const Document back = openProject(moved / "p.hlodproj");
    EXPECT_EQ(back.sources()[0], moved / "scene" / "cube_0.glb");
    std::filesystem::rename(moved, tmp.path());
}

TEST_F(ProjectFile, OutputFoldersAreTheProjectsLikeItsScenes) {
    // Each Export's package goes where the project says, whatever folder `hlod build` runs in.
    doc.graph().setParam(kDefaultExport, "output", (tmp / "packages" / "a").string());
    saveProject(doc, tmp / "p.hlodproj");
    std::ifstream in(tmp / "p.hlodproj");
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["graph"]["nodes"][3]["params"]["output"], "packages/a");
    EXPECT_EQ(j["graph"]["nodes"][2]["params"]["cache_dir"], "cache"); // the fixture's cache
    std::filesystem::rename(tmp.path(), tmp.path().string() + "-moved");
    const std::filesystem::path moved = tmp.path().string() + "-moved";
    const Document back = openProject(moved / "p.hlodproj");
    EXPECT_EQ(paramText(back.graph().node(kDefaultExport).params, "output"),
              (moved / "packages" / "a").string());
    std::filesystem::rename(moved, tmp.path());
}

TEST_F(ProjectFile, ErrorsNameTheFileAndTheProblem) {
    const auto file = tmp / "p.hlodproj";
    EXPECT_EQ(errorOf([&] { openProject(tmp / "none.hlodproj"); }),
              std::make_pair(ErrorCode::FileNotFound,
                             (tmp / "none.hlodproj").string() + ": no such file"));
    test::writeFile(file, "{\"format\": \"hlod-project\", ");
    EXPECT_EQ(errorOf([&] { openProject(file); }).first, ErrorCode::Malformed);
    EXPECT_NE(errorOf([&] { openProject(file); }).second.find("not valid JSON"), std::string::npos);

    saveProject(doc, file);
    std::ifstream in(file);
    nlohmann::json j = nlohmann::json::parse(in);
    j["version"] = 7;
    EXPECT_EQ(errorOf([&] { projectFromJson(j, file); }).second,
              file.string() + ": unsupported project version 7 (this build reads 1)");
    j["version"] = 1;
    j["graph"]["nodes"][1]["params"]["k"] = "high";
    EXPECT_EQ(errorOf([&] { projectFromJson(j, file); }).second,
              file.string() + ": k expects a number");
    j["graph"]["nodes"][1]["params"]["k"] = 1.0;
    std::filesystem::remove(tmp / "scene" / "cube_3.glb");
    EXPECT_EQ(errorOf([&] { projectFromJson(j, file); }),
              std::make_pair(ErrorCode::FileNotFound, file.string() + ": scene file " +
                                                          (tmp / "scene" / "cube_3.glb").string() +
                                                          " does not exist"));
}

TEST_F(ProjectFile, SaveReplacesAtomicallyAndLeavesNoTemporaryFiles) {
    const auto file = tmp / "p.hlodproj";
    saveProject(doc, file);
    doc.execute(std::make_unique<SetParameter>(kDefaultCluster, "k", 3.0));
    saveProject(doc, file);
    EXPECT_EQ(paramNumber(openProject(file).graph().node(2).params, "k"), 3.0);
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(tmp.path()))
        files += e.is_regular_file() ? 1 : 0;
    EXPECT_EQ(files, 1); // only p.hlodproj: the temporary was renamed
    // A folder that cannot be written: Io naming the file, the old file untouched.
    EXPECT_EQ(errorOf([&] { saveProject(doc, tmp / "no" / "dir" / "p.hlodproj"); }).first,
              ErrorCode::Io);
}

TEST_F(ProjectFile, AutosaveIsDetectedWhenNewerAndRecovers) {
    const auto file = tmp / "p.hlodproj";
    saveProject(doc, file);
    EXPECT_FALSE(autosaveIsNewer(file));
    doc.execute(std::make_unique<LockCluster>(kDefaultCluster, InstanceSet{3, 4}));
    // Make the autosave's time stamp strictly newer than the project's.
    std::filesystem::last_write_time(file, std::filesystem::last_write_time(file) -
                                               std::chrono::seconds(10));
    writeAutosave(doc, file);
    EXPECT_EQ(autosavePath(file), tmp / "p.hlodproj.autosave");
    EXPECT_TRUE(autosaveIsNewer(file));
    EXPECT_EQ(openAutosave(file).toJson(), doc.toJson());
    removeAutosave(file);
    EXPECT_FALSE(autosaveIsNewer(file));
}

} // namespace
} // namespace hlod
