// Tests of widgets/DisplayController with a real Viewport (Mesa under xvfb-run): the three
// display modes against baselines, the HLOD preview's draw list against Algorithm 5, picking by
// synthesized clicks, the highlight, and the statistics panel's numbers.
#include <algorithm>
#include <gtest/gtest.h>

#include <memory>

#include <QLocale>
#include <QTableWidget>
#include <QTest>
#include <QTreeView>
#include <vtkRenderer.h>

#include "TestBuilds.h"
#include "TestScenes.h"
#include "pipeline/proxy/ProxyEconomy.h"
#include "pipeline/view/TreeViews.h"
#include "widgets/ClusterDisplay.h"
#include "widgets/ClusterTreeModel.h"
#include "widgets/DisplayController.h"
#include "widgets/GlSupport.h"
#include "widgets/SceneActors.h"
#include "widgets/SceneTreeModel.h"
#include "widgets/SelectionSync.h"
#include "widgets/StatsPanel.h"
#include "widgets/StatsPlot.h"
#include "widgets/StudioModel.h"
#include "widgets/Viewport.h"

namespace hlod::widgets {
namespace {

// Mean absolute difference (0..255) tolerated against a baseline, as in ViewportTest.
constexpr double kBaselineTolerance = 2.0;

class DisplayModesTest : public ::testing::Test {
protected:
    void SetUp() override {
        const GlProbeResult gl = probeOpenGl();
        ASSERT_TRUE(gl.ok) << gl.problem.toStdString();
        viewport = std::make_unique<Viewport>();
        viewport->setFixedSize(480, 360);
        model = std::make_unique<StudioModel>();
        display = std::make_unique<DisplayController>(model.get(), viewport.get());
        viewport->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(viewport.get()));
    }

    void open(const BuiltHlod& built) {
        model->setScene(built.scene);
        viewport->setSceneActors(SceneActors::build(*built.scene), suggestedUpAxis(*built.scene));
        model->setBuilt(built);
        ASSERT_TRUE(model->hasBuild());
    }

    // The pixel (widget coordinates) where world point `p` appears.
    QPoint project(const glm::dvec3& p) {
        vtkRenderer* r = viewport->renderer();
        r->SetWorldPoint(p.x, p.y, p.z, 1.0);
        r->WorldToDisplay();
        const double* d = r->GetDisplayPoint();
        const double dpr = viewport->devicePixelRatioF();
        return {static_cast<int>(d[0] / dpr), static_cast<int>(viewport->height() - d[1] / dpr)};
    }

    void click(const QPoint& pos) {
        QTest::mouseClick(viewport.get(), Qt::LeftButton, Qt::NoModifier, pos);
    }

    std::unique_ptr<Viewport> viewport;
    std::unique_ptr<StudioModel> model;
    std::unique_ptr<DisplayController> display;
};

// Pixels close to the highlight colour (1, 0, 0.85) lit or shaded: strongly magenta (red and
// blue high, green far below both), which no scene material of the sample has.
int magentaPixels(const QImage& image) {
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QRgb c = image.pixel(x, y);
            if (qRed(c) > 150 && qBlue(c) > 120 && qGreen(c) + 90 < std::min(qRed(c), qBlue(c)))
                ++n;
        }
    return n;
}

TEST_F(DisplayModesTest, ClustersModeColoursTheLevelsCutAndMatchesBaseline) {
    open(test::sampleBuild());
    const ClusterTree& tree = *model->built().build->tree;
    model->setLevel(model->suggestedLevel());
    model->setMode(DisplayMode::Clusters);
    const QImage frame = viewport->grabFrame();
    EXPECT_FALSE(viewport->sceneActorsVisible());
    const std::vector<Id> cut = nodesAtLevel(tree, model->view().level);
    EXPECT_EQ(display->shownClusters(), cut);
    // suggestedLevel: the lowest level above the leaves with at most 12 clusters.
    EXPECT_LE(cut.size(), 12u);
    // The overlay counts the level's own nodes, as the Statistics' table does (issue 31 #1).
    const auto own = std::count_if(
        cut.begin(), cut.end(), [&](Id n) { return tree.nodes[n].level == model->view().level; });
    EXPECT_TRUE(display->overlayText().contains(
        own == 1 ? QStringLiteral(": 1 level-%1 node").arg(model->view().level)
                 : QStringLiteral(": %1 level-%2 nodes").arg(own).arg(model->view().level)));
    // The baseline (default parameters: level growth 2, proxy ratio 0.35): the sample's tree
    // is the root over 5 clusters and 69 single meshes, so level 1 shows 74 colours and the
    // suggested level is 2, the whole yard in the root's colour inside its bounding sphere,
    // labelled "Level 2 of 2: 1 level-2 node", the legend bottom right.
    const double diff = test::compareWithBaseline(frame, QStringLiteral("mode-clusters"));
    EXPECT_GE(diff, 0.0) << "missing baseline: run with HLOD_UPDATE_BASELINES=1";
    EXPECT_LT(diff, kBaselineTolerance);
}

TEST_F(DisplayModesTest, HlodPreviewDrawsAlgorithmFivesCutAndMatchesBaseline) {
    open(test::sampleBuild());
    model->setMode(DisplayMode::Hlod);
    const QImage frame = viewport->grabFrame();
    // A fresh full traversal for the same camera gives the same cut as the preview's cache.
    const BuiltHlod& built = model->built();
    std::vector<std::uint64_t> cost(built.build->tree->nodes.size());
    for (Id n = 0; n < cost.size(); ++n)
        cost[n] = built.build->tree->nodes[n].isLeaf()
                      ? model->subtreeTriangles()[n]
                      : built.build->bake->nodes[n].proxy.triangleCount();
    const SelectionTree tree(*built.build->tree, cost);
    const SelectionResult full =
        selectFull(tree, display->currentCamera(), {built.build->bakeParams.screen.screenSize});
    EXPECT_EQ(display->drawList(), full.drawList);
    EXPECT_EQ(display->lastFrame().drawCalls, full.drawList.size());
    EXPECT_EQ(display->lastFrame().triangles, full.triangles);
    EXPECT_TRUE(display->overlayText().contains(
        QStringLiteral("Draw calls: %1").arg(QLocale().toString(qulonglong(full.drawCalls)))));
    const double diff = test::compareWithBaseline(frame, QStringLiteral("mode-hlod"));
    EXPECT_GE(diff, 0.0) << "missing baseline: run with HLOD_UPDATE_BASELINES=1";
    EXPECT_LT(diff, kBaselineTolerance);
}

TEST_F(DisplayModesTest, FarAwayOnlyTheRootProxyIsDrawnTintedAsDepthZero) {
    // Every proxy kept (ratio 1): what is tested is Algorithm 5 stopping at the root and the
    // depth-0 tint, which needs a root proxy; whether the sample's root proxy pays for itself
    // under the default economy is the pipeline's business (a root without one is always
    // refined, ProxyEconomy.h rootHasNoProxy).
    open(test::buildNow(test::sampleBuild().scene, {}, {{"proxy_ratio", 1.0}}));
    ASSERT_FALSE(rootHasNoProxy(*model->built().build->tree, *model->built().build->bake));
    model->setMode(DisplayMode::Hlod);
    model->setTintByDepth(true);
    // Twenty times farther than the fitted view the whole yard spans ~18 px, far below
    // S = 300 px: Algorithm 5 stops at the root.
    viewport->zoom(0.05);
    const QImage frame = viewport->grabFrame();
    const ClusterTree& tree = *model->built().build->tree;
    EXPECT_EQ(display->drawList(), std::vector<Id>{tree.root});
    EXPECT_EQ(display->lastFrame().triangles,
              model->built().build->bake->nodes[tree.root].proxy.triangleCount());
    EXPECT_EQ(display->lastFrame().nodesVisited, 1u);
    // Depth 0 is tinted red (0.90, 0.22, 0.20): the centre of the small yard is reddish.
    const QRgb centre = frame.pixel(frame.width() / 2, frame.height() / 2);
    EXPECT_GT(qRed(centre), qGreen(centre) + 40);
    EXPECT_GT(qRed(centre), qBlue(centre) + 40);
}

TEST_F(DisplayModesTest, ClickingSelectsTheInstanceUnderTheCursorInEveryMode) {
    const auto scene = std::make_shared<const Scene>(test::makeCubeRow());
    // Every proxy kept (ratio 1): the root proxy of three cubes does not pay for itself under
    // the default proxy economy, and the click on the root proxy below needs it drawn.
    open(test::buildNow(scene, {}, {{"proxy_ratio", 1.0}}));
    const ClusterTree& tree = *model->built().build->tree;
    viewport->grabFrame(); // lays out and fits the camera
    for (DisplayMode mode : {DisplayMode::Original, DisplayMode::Clusters}) {
        model->setMode(mode);
        model->clearSelection();
        viewport->grabFrame();
        // Cube 2 sits at x = +4: a click on its centre selects instance 2, its scene node
        // "cube 2" (node 3, after the root) and its leaf.
        click(project({4.0, 0.0, 0.0}));
        EXPECT_EQ(model->selection().instances, std::vector<Id>{2});
        EXPECT_EQ(model->selection().sceneNode, 3u);
        EXPECT_EQ(model->selection().clusterNode, leafOfInstance(tree, 2));
        // The top-left corner shows only background: a click there clears the selection.
        click({3, 3});
        EXPECT_TRUE(model->selection().empty());
    }
    // HLOD preview five times farther: the row (~9 m) projects to well under S = 300 px, the
    // root proxy is drawn alone, and a click on it (the middle cube) selects the root.
    model->setMode(DisplayMode::Hlod);
    viewport->zoom(0.2);
    viewport->grabFrame();
    ASSERT_EQ(display->drawList(), std::vector<Id>{tree.root});
    click(project(tree.nodes[tree.root].sphere.center));
    EXPECT_EQ(model->selection().clusterNode, tree.root);
    EXPECT_EQ(model->selection().instances, (std::vector<Id>{0, 1, 2}));
}

TEST_F(DisplayModesTest, SelectionIsHighlightedAndFollowsBothTrees) {
    const auto scene = std::make_shared<const Scene>(test::makeCubeRow());
    open(test::buildNow(scene));
    SceneTreeModel sceneModel;
    ClusterTreeModel clusterModel;
    QTreeView sceneTree, clusterTree;
    sceneTree.setModel(&sceneModel);
    clusterTree.setModel(&clusterModel);
    SelectionSync sync(model.get(), &sceneTree, &sceneModel, &clusterTree, &clusterModel);
    sceneModel.setScene(scene);
    clusterModel.setBuild(scene, model->built().build);
    EXPECT_EQ(magentaPixels(viewport->grabFrame()), 0);

    // A row chosen in the scene tree selects and highlights cube 0 (node 1).
    sceneTree.selectionModel()->setCurrentIndex(sceneModel.indexOfNode(1),
                                                QItemSelectionModel::ClearAndSelect);
    EXPECT_EQ(model->selection().instances, std::vector<Id>{0});
    EXPECT_GT(magentaPixels(viewport->grabFrame()), 100);
    // ... and the cluster tree shows that cube's leaf.
    const Id leaf = leafOfInstance(*model->built().build->tree, 0);
    EXPECT_EQ(clusterModel.nodeOf(clusterTree.currentIndex()), leaf);

    // A click in the viewport on cube 2 moves both trees to it.
    click(project({4.0, 0.0, 0.0}));
    EXPECT_EQ(sceneModel.nodeOf(sceneTree.currentIndex()), 3u);
    EXPECT_EQ(clusterModel.nodeOf(clusterTree.currentIndex()),
              leafOfInstance(*model->built().build->tree, 2));
    // The cluster root chosen in the cluster tree selects all three cubes; no scene node has
    // exactly those, so the scene tree clears.
    clusterTree.selectionModel()->setCurrentIndex(clusterModel.index(0, 0),
                                                  QItemSelectionModel::ClearAndSelect);
    EXPECT_EQ(model->selection().instances.size(), 3u);
    EXPECT_FALSE(sceneTree.currentIndex().isValid());
}

TEST_F(DisplayModesTest, StatisticsPanelShowsBakeStatsAndTheFramesCounters) {
    open(test::sampleBuild());
    StatsPanel panel(model.get());
    QObject::connect(display.get(), &DisplayController::frameStats, &panel, &StatsPanel::showFrame);
    const BuiltHlod& built = model->built();
    const QLocale locale;
    auto cell = [&](int row, int column) { return panel.table()->item(row, column)->text(); };
    // Exactly the numbers of BakeStats (as `hlod build` prints them).
    EXPECT_EQ(cell(StatsPanel::OriginalRow, StatsPanel::TrianglesColumn),
              locale.toString(qulonglong(built.original.triangles)));
    EXPECT_EQ(cell(StatsPanel::HlodRow, StatsPanel::TrianglesColumn),
              locale.toString(qulonglong(built.hlod.triangles)));
    EXPECT_EQ(cell(StatsPanel::HlodRow, StatsPanel::VerticesColumn),
              locale.toString(qulonglong(built.hlod.vertices)));
    EXPECT_EQ(cell(StatsPanel::HlodRow, StatsPanel::MeshesColumn),
              locale.toString(qulonglong(built.hlod.meshes)));
    EXPECT_EQ(cell(StatsPanel::HlodRow, StatsPanel::SizeColumn),
              locale.toString(double(built.hlod.bytes) / 1.0e6, 'f', 2) + QStringLiteral(" MB"));

    model->setMode(DisplayMode::Hlod);
    viewport->grabFrame();
    panel.plot()->sample();
    ASSERT_FALSE(panel.plot()->samples().empty());
    EXPECT_EQ(panel.plot()->samples().back().drawCalls, display->lastFrame().drawCalls);
    EXPECT_EQ(panel.plot()->samples().back().triangles, display->lastFrame().triangles);
}

TEST(StatsPlot, KeepsOnlyTheLastWindowOfSamples) {
    StatsPlot plot(nullptr, 2.0, 10); // 2 s at 10 samples/s = 20 samples
    ASSERT_EQ(plot.capacity(), 20u);
    for (std::uint64_t i = 1; i <= 50; ++i) {
        plot.setCurrent(i, 100 * i);
        plot.sample();
    }
    ASSERT_EQ(plot.samples().size(), 20u);
    EXPECT_EQ(plot.samples().front().drawCalls, 31u); // samples 31..50 remain
    EXPECT_EQ(plot.samples().back().triangles, 5000u);
}

} // namespace
} // namespace hlod::widgets
