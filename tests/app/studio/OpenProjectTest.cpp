// Opening a project the ways a person does (issue 20 #1): on the command line (main() passes
// its arguments to openFiles), File ▸ Open, Open Recent, drag and drop, and with the offer to
// recover an autosave. Each restores the scene, the parameters and the hand edits, and the
// window then shows the project's HLOD (built on open, HLOD preview). A project whose scene is
// missing says so and leaves the open document alone.
//
// The project is the embedded sample scene with AABB k = 2 and instance 3 excluded
// (writeSampleProject): both visible in the built tree (volume type, instance 3 a child of
// the root).
#include <gtest/gtest.h>

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QTemporaryDir>
#include <QTest>
#include <QUrl>

#include "StudioWindow.h"
#include "pipeline/doc/Commands.h"
#include "pipeline/doc/ProjectFile.h"
#include "widgets/StudioModel.h"
#include "widgets/doc/ProjectSession.h"

namespace hlod::studio::test {
namespace {

using widgets::DisplayMode;

class OpenProject : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(dir.isValid());
        project = dir.filePath(QStringLiteral("yard.hlodproj"));
        writeSampleProject(project);
        window = openWindow();
        ASSERT_NE(window, nullptr);
    }

    // Waits for the project's scene, document and HLOD.
    bool opened() {
        return waitUntil([this] {
            return window->session()->projectPath() == project && window->model()->hasBuild() &&
                   !window->model()->building();
        });
    }

    // What the project holds, as the window shows it.
    void expectProjectShown() {
        const Document& doc = window->session()->document();
        const GraphNode& cluster = doc.graph().node(kDefaultCluster);
        EXPECT_EQ(paramText(cluster.params, "volume"), "aabb");
        EXPECT_EQ(paramNumber(cluster.params, "k"), 2.0);
        EXPECT_EQ(cluster.edits.excluded, InstanceSet{3});
        ASSERT_TRUE(window->model()->hasBuild());
        const ClusterTree& tree = *window->model()->built().build->tree;
        EXPECT_EQ(tree.volume, VolumeType::Aabb);
        EXPECT_EQ(tree.k, 2.0);
        EXPECT_EQ(tree.nodes[findCluster(tree, {3})].parent, tree.root);
        // The HLOD it describes, not an empty window or the original scene.
        EXPECT_EQ(window->model()->view().mode, DisplayMode::Hlod);
        EXPECT_TRUE(window->windowTitle().contains(QStringLiteral("yard.hlodproj")));
        EXPECT_FALSE(window->isWindowModified());
    }

    QTemporaryDir dir;
    QString project;
    std::unique_ptr<MainWindow> window;
};

TEST_F(OpenProject, FromTheCommandLineRestoresEverythingAndShowsItsHlod) {
    window->openFiles({project}); // what `hlod-studio yard.hlodproj` does
    ASSERT_TRUE(opened());
    expectProjectShown();
}

TEST_F(OpenProject, DroppedOnTheWindowOpensLikeTheCommandLine) {
    QMimeData data;
    data.setUrls({QUrl::fromLocalFile(project)});
    const QPoint at = window->rect().center();
    QDragEnterEvent enter(at, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window.get(), &enter);
    ASSERT_TRUE(enter.isAccepted());
    QDropEvent drop(at, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window.get(), &drop);
    ASSERT_TRUE(opened());
    expectProjectShown();
}

TEST_F(OpenProject, FileOpenDialogAcceptsProjects) {
    DialogAnswerer answer([this](QDialog* dialog) {
        auto* files = qobject_cast<QFileDialog*>(dialog);
        if (!files) return false;
        // The dialog offers projects among what it opens.
        EXPECT_TRUE(
            files->nameFilters().join(QLatin1Char(' ')).contains(QStringLiteral("*.hlodproj")));
        // Typed into the dialog's file name field, as a person would.
        files->setDirectory(QFileInfo(project).absolutePath());
        auto* name = files->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
        if (!name) return false;
        name->setText(QFileInfo(project).fileName());
        QMetaObject::invokeMethod(files, "accept");
        return true;
    });
    QAction* open = window->findChild<QAction*>(QStringLiteral("actionOpen"));
    ASSERT_NE(open, nullptr);
    open->trigger();
    ASSERT_TRUE(opened());
    expectProjectShown();
}

TEST_F(OpenProject, OpenRecentListsTheProjectAndReopensIt) {
    window->openFiles({project});
    ASSERT_TRUE(opened());
    // Another scene (the sample alone), then the project again from the menu.
    window->openFiles({});
    ASSERT_TRUE(waitUntil([this] { return window->session()->projectPath().isEmpty(); }));
    const QList<QAction*> recent = window->recentMenu()->actions();
    ASSERT_FALSE(recent.isEmpty());
    EXPECT_TRUE(recent.front()->text().contains(QStringLiteral("yard.hlodproj")))
        << recent.front()->text().toStdString();
    recent.front()->trigger();
    ASSERT_TRUE(opened());
    expectProjectShown();
}

TEST_F(OpenProject, RecoveryRestoresTheAutosavedEdits) {
    // The editor stopped after one more edit: the autosave (newer) also excludes instance 5.
    Document edited = openProject(project.toStdString());
    edited.execute(std::make_unique<ExcludeInstance>(kDefaultCluster, InstanceSet{5}));
    writeAutosave(edited, project.toStdString());
    DialogAnswerer answer(clickButton(QMessageBox::Yes));
    window->openFiles({project});
    ASSERT_TRUE(opened());
    ASSERT_EQ(answer.messages().size(), 1);
    EXPECT_TRUE(answer.messages().front().contains(QStringLiteral("autosave")));
    const Document& doc = window->session()->document();
    EXPECT_EQ(doc.graph().node(kDefaultCluster).edits.excluded, (InstanceSet{3, 5}));
    const ClusterTree& tree = *window->model()->built().build->tree;
    EXPECT_EQ(tree.nodes[findCluster(tree, {5})].parent, tree.root);
    EXPECT_TRUE(window->isWindowModified()); // recovered, not saved yet
}

TEST_F(OpenProject, AMissingSceneIsNamedAndTheOpenDocumentStays) {
    window->openFiles({});
    ASSERT_TRUE(waitUntil([this] { return window->model()->scene() != nullptr; }));
    const QString broken = dir.filePath(QStringLiteral("broken.hlodproj"));
    saveProject(Document({dir.filePath(QStringLiteral("gone.glb")).toStdString()}),
                broken.toStdString());
    DialogAnswerer answer(clickButton(QMessageBox::Ok));
    window->openFiles({broken});
    ASSERT_TRUE(waitUntil([&] { return !answer.messages().isEmpty(); }));
    EXPECT_TRUE(answer.messages().front().contains(QStringLiteral("gone.glb")))
        << answer.messages().front().toStdString();
    EXPECT_TRUE(window->session()->projectPath().isEmpty()); // still the untitled sample
    EXPECT_NE(window->model()->scene(), nullptr);
}

} // namespace
} // namespace hlod::studio::test
