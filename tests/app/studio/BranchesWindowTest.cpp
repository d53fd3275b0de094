// A second branch end to end in the main window (issue 29), as a person makes and uses it: the
// Pipeline dock's context menu duplicates the Cluster -> Bake -> Export branch, the Parameters
// dock (showing only the clicked node) makes the copy AABB, Build ▸ Build All Branches builds
// both, the toolbar's branch box shows either (Statistics names it), View ▸ Compare opens on
// the two Bake nodes, the Export nodes get their folders and File ▸ Export All writes both
// packages, and the project saves and reopens with the branch, its name and the branch shown.
//
// The scene is the embedded sample with proxies baked without the disk cache on two threads.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QContextMenuEvent>
#include <QFileInfo>
#include <QGraphicsRectItem>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include "StudioWindow.h"
#include "pipeline/doc/Commands.h"
#include "widgets/BranchBox.h"
#include "widgets/StatsPanel.h"
#include "widgets/StudioModel.h"
#include "widgets/compare/ComparePane.h"
#include "widgets/compare/CompareTable.h"
#include "widgets/compare/CompareView.h"
#include "widgets/doc/ProjectSession.h"
#include "widgets/graph/NodeGraphView.h"
#include "widgets/graph/PipelineEditor.h"
#include "widgets/params/BuildParameters.h"
#include "widgets/params/ParameterPanel.h"

namespace hlod::studio::test {
namespace {

using widgets::NodeGraphView;

class BranchesWindow : public ::testing::Test {
protected:
    void SetUp() override {
        window = openWindow();
        ASSERT_NE(window, nullptr);
        ASSERT_TRUE(openSampleWithoutCache(*window));
        window->findChild<QAction*>(QStringLiteral("actionBuild"))->trigger();
        ASSERT_TRUE(waitSettled(*window));
        pipeline = window->findChild<widgets::PipelineEditor*>();
        ASSERT_NE(pipeline, nullptr);
    }
    NodeGraphView* graphView() const { return pipeline->view(); }
    const PipelineGraph& graph() const { return window->session()->document().graph(); }
    QPoint onNode(NodeId node) const {
        NodeGraphView* view = graphView();
        view->centerOn(view->nodeItem(node));
        return view->mapFromScene(view->nodeItem(node)->sceneBoundingRect().topLeft() +
                                  QPointF(30.0, NodeGraphView::kHeaderHeight / 2));
    }
    void clickNode(NodeId node) {
        QTest::mouseClick(graphView()->viewport(), Qt::LeftButton, {}, onNode(node));
    }
    // Opens the node's context menu and triggers the entry whose text starts with `entry`.
    bool contextMenu(NodeId node, const QString& entry) {
        bool triggered = false;
        QTimer::singleShot(200, [&] {
            auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
            if (!menu) return;
            for (QAction* a : menu->actions()) {
                if (a->text().remove(QLatin1Char('&')).startsWith(entry)) {
                    menu->close();
                    a->trigger();
                    triggered = true;
                    return;
                }
            }
            menu->close();
        });
        const QPoint at = onNode(node);
        QContextMenuEvent event(QContextMenuEvent::Mouse, at,
                                graphView()->viewport()->mapToGlobal(at));
        QApplication::sendEvent(graphView()->viewport(), &event);
        return triggered;
    }
    bool bothBuilt() const {
        return waitUntil([this] {
            return !window->model()->building() &&
                   graph().status(kDefaultBake) == NodeStatus::UpToDate &&
                   graph().status(6) == NodeStatus::UpToDate;
        });
    }

    std::unique_ptr<MainWindow> window;
    widgets::PipelineEditor* pipeline = nullptr;
};

TEST_F(BranchesWindow, ASecondBranchBuildsShowsComparesExportsAndReopens) {
    // Duplicate Branch on Cluster #2: Cluster #5 -> Bake #6 -> Export #7, fed by Import #1.
    ASSERT_TRUE(contextMenu(kDefaultCluster, QStringLiteral("Duplicate Branch")));
    ASSERT_EQ(graph().nodeIds(), (std::vector<NodeId>{1, 2, 3, 4, 5, 6, 7}));
    EXPECT_EQ(graph().branchOf(7), (std::vector<NodeId>{1, 5, 6, 7}));
    EXPECT_EQ(window->session()->undo()->stack()->undoText(),
              QStringLiteral("Duplicate the branch of Cluster #2 (3 nodes)"));

    // The copy's Cluster node, clicked: the Parameters dock shows it alone; make it AABB.
    clickNode(5);
    widgets::BuildParameters* params = window->buildParameters();
    ASSERT_EQ(params->shownNode(), 5u);
    auto* volume = params->panel()->findChild<QComboBox*>(QStringLiteral("param_volume"));
    ASSERT_NE(volume, nullptr);
    volume->setCurrentText(QStringLiteral("aabb"));
    EXPECT_EQ(paramText(graph().node(5).params, "volume"), "aabb");
    EXPECT_EQ(paramText(graph().node(kDefaultCluster).params, "volume"), "sphere");
    EXPECT_EQ(window->session()->undo()->stack()->undoText(),
              QStringLiteral("Set Volume of Cluster #5"));
    {
        // Rename… on the copy's Bake node asks for the name in a dialog.
        DialogAnswerer answer([](QDialog* dialog) {
            auto* input = qobject_cast<QInputDialog*>(dialog);
            if (!input) return false;
            input->setTextValue(QStringLiteral("boxes"));
            input->accept();
            return true;
        });
        ASSERT_TRUE(contextMenu(6, QStringLiteral("Rename")));
    }
    EXPECT_EQ(graph().node(6).name, "boxes");

    // Build ▸ Build All Branches: both Bake nodes up to date, each with its own tree.
    window->findChild<QAction*>(QStringLiteral("actionBuildAll"))->trigger();
    ASSERT_TRUE(bothBuilt());
    EXPECT_EQ(graph().output(kDefaultBake)->tree->volume, VolumeType::Sphere);
    EXPECT_EQ(graph().output(6)->tree->volume, VolumeType::Aabb);
    EXPECT_EQ(graph().status(5), NodeStatus::UpToDate);

    // The toolbar's branch box shows the second branch: view, Clusters tab and Statistics.
    auto* box = window->findChild<widgets::BranchBox*>(QStringLiteral("BranchBox"));
    ASSERT_NE(box, nullptr);
    ASSERT_EQ(box->count(), 2);
    EXPECT_EQ(box->itemText(1), QStringLiteral("Cluster #5 → Bake #6 'boxes'"));
    box->setCurrentIndex(1);
    EXPECT_EQ(window->model()->shownBake(), 6u);
    EXPECT_FALSE(window->model()->building()); // built already: shown at once
    EXPECT_EQ(window->model()->built().build, graph().sharedOutput(6));
    EXPECT_EQ(graphView()->shownNode(), 6u);
    const QString branch = window->statsPanel()->branchLabel()->text();
    EXPECT_TRUE(branch.contains(QStringLiteral("Bake #6 'boxes'"))) << branch.toStdString();
    EXPECT_TRUE(branch.contains(QStringLiteral("up to date"))) << branch.toStdString();

    // View ▸ Compare Configurations opens on the two Bake nodes.
    window->showCompare();
    widgets::CompareView* compare = window->compareView();
    ASSERT_NE(compare, nullptr);
    EXPECT_TRUE(waitUntil([&] { return !compare->building(); }));
    ASSERT_TRUE(compare->allBuilt());
    EXPECT_EQ(compare->left()->side().bake, 6u); // the shown branch
    EXPECT_EQ(compare->right()->side().bake, kDefaultBake);
    EXPECT_EQ(compare->left()->built()->build->tree->volume, VolumeType::Aabb);
    EXPECT_EQ(compare->right()->built()->build->tree->volume, VolumeType::Sphere);
    compare->close();

    // Each Export node gets its folder (the Parameters dock), then File ▸ Export All.
    QTemporaryDir dir;
    for (const auto& [node, name] :
         {std::pair<NodeId, QString>{kDefaultExport, QStringLiteral("spheres")},
          {7, QStringLiteral("boxes")}}) {
        clickNode(node);
        auto* output = params->panel()->findChild<QLineEdit*>(QStringLiteral("param_output"));
        ASSERT_NE(output, nullptr);
        output->setText(dir.filePath(name));
        QTest::keyClick(output, Qt::Key_Return);
        EXPECT_EQ(paramText(graph().node(node).params, "output"), dir.filePath(name).toStdString());
    }
    window->findChild<QAction*>(QStringLiteral("actionExportAll"))->trigger();
    ASSERT_TRUE(waitUntil([&] {
        return !window->model()->building() &&
               graph().status(kDefaultExport) == NodeStatus::UpToDate &&
               graph().status(7) == NodeStatus::UpToDate;
    }));
    for (const QString& name : {QStringLiteral("spheres"), QStringLiteral("boxes")})
        EXPECT_TRUE(QFileInfo::exists(dir.filePath(name) + QStringLiteral("/tileset.json")))
            << name.toStdString();

    // Saved and reopened: the branch, its name, the folders and the branch shown.
    const QString project = dir.filePath(QStringLiteral("branches.hlodproj"));
    window->session()->save(project);   // the path File ▸ Save As would ask for
    ASSERT_TRUE(window->saveProject()); // File ▸ Save: with the display and the shown branch
    auto reopened = openWindow();
    ASSERT_NE(reopened, nullptr);
    ASSERT_TRUE(reopened->openProject(project));
    ASSERT_TRUE(waitSettled(*reopened));
    const PipelineGraph& back = reopened->session()->document().graph();
    EXPECT_EQ(back.nodeIds(), (std::vector<NodeId>{1, 2, 3, 4, 5, 6, 7}));
    EXPECT_EQ(back.node(6).name, "boxes");
    EXPECT_EQ(paramText(back.node(7).params, "output"),
              dir.filePath(QStringLiteral("boxes")).toStdString());
    EXPECT_EQ(reopened->model()->shownBake(), 6u);
    EXPECT_EQ(reopened->model()->built().build->tree->volume, VolumeType::Aabb);
    // Removing the shown Bake node shows the other branch.
    auto* dock = reopened->findChild<widgets::PipelineEditor*>();
    ASSERT_TRUE(dock->removeNode(6));
    EXPECT_EQ(reopened->model()->shownBake(), kDefaultBake);
}

} // namespace
} // namespace hlod::studio::test
