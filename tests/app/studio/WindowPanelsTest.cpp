// The main window's docks and windows after a build, as a first-time user meets them (issue
// 20): the Export node of the Pipeline dock after an export (#3), the Clusters tab at the
// default dock width (#5), the viewport's colour legend (#6), the Compare window's Close
// button and Esc (#8), and the Statistics dock saying what "HLOD triangles" counts, with the
// per-level table and the proxy economy's dissolved clusters (#10).
//
// The scene is the embedded sample (97 meshes), built with the document's parameters (no disk
// cache, two threads).
#include <gtest/gtest.h>

#include <QAction>
#include <QDockWidget>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeView>

#include "StudioWindow.h"
#include "pipeline/doc/Commands.h"
#include "widgets/ClusterDisplay.h"
#include "widgets/ClusterTreeModel.h"
#include "widgets/DisplayController.h"
#include "widgets/ExportDialog.h"
#include "widgets/StatsPanel.h"
#include "widgets/StudioModel.h"
#include "widgets/Viewport.h"
#include "widgets/compare/ComparePane.h"
#include "widgets/compare/CompareView.h"
#include "widgets/doc/ProjectSession.h"
#include "widgets/graph/NodeGraphView.h"
#include "widgets/graph/PipelineEditor.h"

namespace hlod::studio::test {
namespace {

using widgets::ClusterTreeModel;
using widgets::StatsPanel;

class WindowPanels : public ::testing::Test {
protected:
    void SetUp() override {
        window = openWindow();
        ASSERT_NE(window, nullptr);
        window->openFiles({});
        ASSERT_TRUE(waitUntil([this] { return window->model()->scene() != nullptr; }));
        auto* undo = window->session()->undo();
        const NodeId bake = kDefaultBake;
        ASSERT_TRUE(undo->execute(std::make_unique<SetParameter>(bake, "cache", false)));
        ASSERT_TRUE(undo->execute(std::make_unique<SetParameter>(bake, "threads", 2)));
        window->findChild<QAction*>(QStringLiteral("actionBuild"))->trigger();
        ASSERT_TRUE(built());
    }
    bool built() { return waitSettled(*window); }
    NodeStatus exportStatus() const {
        auto* pipeline = window->findChild<widgets::PipelineEditor*>();
        return pipeline->view()->shownStatus(kDefaultExport);
    }

    std::unique_ptr<MainWindow> window;
};

TEST_F(WindowPanels, ExportNodeIsUpToDateAfterAnExportAndPendingAfterAChange) {
    EXPECT_EQ(exportStatus(), NodeStatus::Pending);
    QTemporaryDir dir;
    const QString folder = dir.filePath(QStringLiteral("package"));
    bool started = false;
    DialogAnswerer answer([&](QDialog* dialog) {
        auto* exportDialog = qobject_cast<widgets::ExportDialog*>(dialog);
        if (!exportDialog) return false;
        if (!started) {
            exportDialog->setFolder(folder);
            started = exportDialog->startExport();
        } else if (!exportDialog->running()) {
            exportDialog->close(); // the Close button once the package is written
        }
        return true;
    });
    window->findChild<QAction*>(QStringLiteral("actionExport"))->trigger(); // returns when closed
    ASSERT_TRUE(started);
    const PipelineGraph& g = window->session()->document().graph();
    EXPECT_EQ(paramText(g.node(kDefaultExport).params, "output"), folder.toStdString());
    EXPECT_EQ(exportStatus(), NodeStatus::UpToDate);
    EXPECT_TRUE(QFileInfo::exists(folder + QStringLiteral("/tileset.json")));
    // Another screen size: a new build, whose package is not written yet.
    const NodeId bake = kDefaultBake;
    ASSERT_TRUE(window->session()->undo()->execute(
        std::make_unique<SetParameter>(bake, "screen_size", 200.0)));
    ASSERT_TRUE(built());
    EXPECT_EQ(exportStatus(), NodeStatus::Pending);
}

TEST_F(WindowPanels, ClustersTabShowsEveryColumnInSceneUnitsAtTheDefaultDockWidth) {
    window->treeTabs()->setCurrentWidget(window->clusterTree());
    QTreeView* view = window->clusterTree();
    QTest::qWait(50); // the header lays out its sections
    const int width = view->viewport()->width();
    for (int c = 0; c < ClusterTreeModel::ColumnCount; ++c) {
        const int right =
            view->header()->sectionViewportPosition(c) + view->header()->sectionSize(c);
        EXPECT_LE(right, width) << "column " << c << " ends at " << right << " of " << width;
        // Wide enough for the header's text; the names keep a useful width.
        EXPECT_GE(view->header()->sectionSize(c), view->header()->sectionSizeHint(c) - 2) << c;
    }
    EXPECT_GE(view->header()->sectionSize(ClusterTreeModel::NameColumn), 100);
    // Sizes in scene units (the header's tooltip names them; issue 31 #6), never in
    // scientific notation.
    auto* model = static_cast<ClusterTreeModel*>(view->model());
    EXPECT_TRUE(model->headerData(ClusterTreeModel::SizeColumn, Qt::Horizontal, Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("scene units")));
    const QRegularExpression readable(QStringLiteral("^[0-9.,]+$"));
    const ClusterTree& tree = *window->model()->built().build->tree;
    for (Id n = 0; n < tree.nodes.size(); ++n) {
        const QString text =
            model->data(model->indexOfNode(n).siblingAtColumn(ClusterTreeModel::SizeColumn))
                .toString();
        EXPECT_TRUE(readable.match(text).hasMatch()) << text.toStdString();
    }
}

TEST_F(WindowPanels, LegendExplainsTheColoursOfClustersModeAndOfTheDepthTint) {
    widgets::DisplayController* display = window->display();
    window->model()->setMode(widgets::DisplayMode::Clusters);
    window->viewport()->grabFrame();
    const auto entries = display->legendEntries();
    ASSERT_FALSE(entries.empty());
    EXPECT_TRUE(entries.front().text.contains(QStringLiteral("one colour per cluster")));
    // The shown clusters (at most six listed), each with its colour on screen.
    const std::vector<int>& labels = window->model()->clusterLabels();
    std::size_t swatches = 0, matched = 0;
    for (const auto& e : entries)
        swatches += e.swatch ? 1 : 0;
    for (Id n : display->shownClusters())
        for (const auto& e : entries)
            if (e.swatch && e.text == QStringLiteral("Cluster %1").arg(labels[n])) {
                EXPECT_EQ(e.color, widgets::clusterColorOf(n, &labels));
                ++matched;
            }
    EXPECT_EQ(swatches, std::min<std::size_t>(display->shownClusters().size(), 6));
    EXPECT_GE(matched, 1u);
    // The HLOD preview tinted by depth: one line per depth drawn, the root's red first.
    window->model()->setMode(widgets::DisplayMode::Hlod);
    window->model()->setTintByDepth(true);
    // Far away: the top of the tree alone (the root, or its children where the root's proxy
    // does not pay for itself and the root is always refined, README "proxy economy").
    window->viewport()->zoom(0.05);
    window->viewport()->grabFrame();
    const auto tint = display->legendEntries();
    ASSERT_GE(tint.size(), 2u);
    const QString first = tint[1].text;
    ASSERT_TRUE(first.startsWith(QStringLiteral("Depth "))) << first.toStdString();
    const int depth = first.mid(6).section(QLatin1Char(' '), 0, 0).toInt();
    EXPECT_LE(depth, 1);
    EXPECT_EQ(tint[1].color, widgets::depthColor(depth));
    if (depth == 0) {
        EXPECT_EQ(first, QStringLiteral("Depth 0 (root)"));
    }
    // Untinted, nothing needs explaining.
    window->model()->setTintByDepth(false);
    window->viewport()->grabFrame();
    EXPECT_TRUE(display->legendEntries().empty());
}

TEST_F(WindowPanels, CompareWindowClosesWithEscAndWithItsCloseButton) {
    window->showCompare();
    widgets::CompareView* compare = window->compareView();
    ASSERT_NE(compare, nullptr);
    ASSERT_TRUE(QTest::qWaitForWindowExposed(compare));
    compare->activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(compare));
    // Both sides building when the window closes (as right after a selector change; a build of
    // the sample takes about a second on two cores, so the builds started with the window may
    // be done by now).
    const auto rebuildBoth = [compare] {
        compare->rebuildAll();
        return compare->left()->building() && compare->right()->building();
    };
    // Closing stops its builds: from then on neither side is building, both are cancelled with
    // no result, and their workers end (the cancel is a flag each sees at its next check).
    const auto expectStopped = [compare](const char* how) {
        EXPECT_FALSE(compare->building()) << how;
        for (widgets::ComparePane* pane : {compare->left(), compare->right()}) {
            EXPECT_EQ(pane->state(), widgets::ComparePane::State::Cancelled) << how;
            EXPECT_EQ(pane->built(), nullptr) << how;
        }
    };
    ASSERT_TRUE(rebuildBoth());
    QTest::keyClick(compare, Qt::Key_Escape);
    EXPECT_TRUE(waitUntil([&] { return !compare->isVisible(); }, 5000));
    expectStopped("closed by Esc");

    // Shown again at once, before the stopped workers have returned: the sides that were closed
    // mid-build build again, and finish.
    window->showCompare();
    EXPECT_TRUE(compare->left()->building());
    EXPECT_TRUE(compare->right()->building());
    ASSERT_TRUE(QTest::qWaitForWindowExposed(compare));
    EXPECT_TRUE(waitUntil([&] { return !compare->building(); }));
    EXPECT_TRUE(compare->allBuilt());

    ASSERT_NE(compare->closeButton(), nullptr);
    EXPECT_EQ(compare->closeButton()->text(), QStringLiteral("Close"));
    ASSERT_TRUE(rebuildBoth());
    QTest::mouseClick(compare->closeButton(), Qt::LeftButton);
    EXPECT_TRUE(waitUntil([&] { return !compare->isVisible(); }, 5000));
    expectStopped("closed by its Close button");
    // The workers end without a result and the panes stay cancelled.
    EXPECT_TRUE(waitUntil([&] {
        return !compare->left()->model()->building() && !compare->right()->model()->building();
    }));
    for (widgets::ComparePane* pane : {compare->left(), compare->right()}) {
        EXPECT_FALSE(pane->model()->hasBuild());
        EXPECT_EQ(pane->state(), widgets::ComparePane::State::Cancelled);
    }
}

TEST_F(WindowPanels, StatisticsSayWhatHlodTrianglesCountAndShowTheLevels) {
    StatsPanel* stats = window->statsPanel();
    const widgets::BuiltHlod& b = window->model()->built();
    // The HLOD row counts the originals plus every proxy; the note says so, with the share.
    const std::size_t proxies = b.hlod.meshes - b.original.meshes;
    const QString note = stats->countsNote()->text();
    EXPECT_TRUE(
        note.contains(QStringLiteral("the original meshes plus all %1 proxies").arg(proxies)))
        << note.toStdString();
    EXPECT_TRUE(note.contains(QStringLiteral("not what is drawn at once"))) << note.toStdString();
    EXPECT_TRUE(note.contains(
        QStringLiteral("%1 triangles")
            .arg(QLocale().toString(qulonglong(b.hlod.triangles - b.original.triangles)))))
        << note.toStdString();
    // One row per level of BakeStats' level table (what `hlod build` prints).
    QTableWidget* levels = stats->levelTable();
    ASSERT_EQ(levels->rowCount(), static_cast<int>(b.levels.size()));
    EXPECT_EQ(levels->item(0, StatsPanel::LevelLevelColumn)->text(), QStringLiteral("0"));
    EXPECT_EQ(levels->item(0, StatsPanel::LevelShareColumn)->text(), QStringLiteral("100 %"));
    const LevelRow& top = b.levels.back();
    const int last = levels->rowCount() - 1;
    EXPECT_EQ(levels->item(last, StatsPanel::LevelNodesColumn)->text(),
              QLocale().toString(qulonglong(top.nodes)));
    EXPECT_EQ(levels->item(last, StatsPanel::LevelTrianglesColumn)->text(),
              QLocale().toString(qulonglong(top.triangles)));
    // The proxy economy's decisions.
    const std::size_t dissolved = b.build->bake->dissolved;
    EXPECT_TRUE(stats->economyLabel()->text().startsWith(
        dissolved == 1 ? QStringLiteral("Proxy economy: 1 cluster dissolved")
                       : QStringLiteral("Proxy economy: %1 clusters dissolved").arg(dissolved)))
        << stats->economyLabel()->text().toStdString();
    // The size column is there, with its unit, at the dock's default width.
    QTableWidget* table = stats->table();
    const QString size = table->item(StatsPanel::HlodRow, StatsPanel::SizeColumn)->text();
    EXPECT_TRUE(size.endsWith(QStringLiteral(" MB"))) << size.toStdString();
    const int right = table->horizontalHeader()->sectionViewportPosition(StatsPanel::SizeColumn) +
                      table->horizontalHeader()->sectionSize(StatsPanel::SizeColumn);
    EXPECT_LE(right, table->viewport()->width());
    EXPECT_GE(table->horizontalHeader()->sectionSize(StatsPanel::SizeColumn),
              table->fontMetrics().horizontalAdvance(size));
}

} // namespace
} // namespace hlod::studio::test
