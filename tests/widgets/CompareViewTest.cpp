// Tests of widgets/compare (the side-by-side comparison of issue #7, issue 29) with real
// viewports (Mesa under xvfb-run): a side is a Bake node of the document or a quick
// configuration built as a temporary branch; both sides build in the background and preview, the
// cameras are linked both ways, the table shows each side's build and frame, one side's selector
// rebuilds that side only, cancel leaves no result, closing mid-build is safe, a document change
// rebuilds only the sides it reaches, two Bake nodes of the document compare, "Use These
// Settings" is one undo step, and the text forms of --compare.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>
#include <vtkCamera.h>

#include "TestBuilds.h"
#include "TestScenes.h"
#include "pipeline/core/Error.h"
#include "pipeline/doc/Commands.h"
#include "pipeline/graph/Parameters.h"
#include "widgets/DisplayController.h"
#include "widgets/GlSupport.h"
#include "widgets/StudioModel.h"
#include "widgets/Viewport.h"
#include "widgets/compare/CameraLink.h"
#include "widgets/compare/CompareConfig.h"
#include "widgets/compare/ComparePane.h"
#include "widgets/compare/CompareTable.h"
#include "widgets/compare/CompareView.h"
#include "widgets/compare/UseConfiguration.h"
#include "widgets/doc/ProjectSession.h"

namespace hlod::widgets {
namespace {

constexpr int kBuildTimeoutMs = 120000;

CompareConfig config(VolumeType volume, double k = 1.0, double screenSize = 300.0) {
    CompareConfig c;
    c.volume = volume;
    c.k = k;
    c.screenSize = screenSize;
    return c;
}

// Waits until `pane` leaves the Building state; true when it did in time.
bool waitUntilIdle(ComparePane& pane) {
    QSignalSpy changed(&pane, &ComparePane::stateChanged);
    while (pane.building())
        if (!changed.wait(kBuildTimeoutMs)) return false;
    return true;
}

class CompareViewTest : public ::testing::Test {
protected:
    void SetUp() override {
        const GlProbeResult gl = probeOpenGl();
        ASSERT_TRUE(gl.ok) << gl.problem.toStdString();
        // The editor's document over the sample scene, with the test bake parameters.
        ASSERT_TRUE(test::useTestBakeParameters(session));
        test::seedScene(graph(), test::sampleBuild().scene);
        view = std::make_unique<CompareView>();
        view->resize(1000, 640);
        view->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(view.get()));
    }
    PipelineGraph& graph() { return session.document().graph(); }

    // The document's Bake #3 (sphere, left) against AABB k=2 over it (right), both building.
    void openBoth() {
        view->open(
            test::sampleBuild().scene, &graph(), kDefaultBake,
            {{kDefaultBake, config(VolumeType::Sphere)}, {kNoNode, config(VolumeType::Aabb, 2.0)}});
    }
    // openBoth() and waits for both sides.
    void openSample() {
        openBoth();
        view->fitView();
        ASSERT_TRUE(waitUntilIdle(*view->left()));
        ASSERT_TRUE(waitUntilIdle(*view->right()));
        ASSERT_TRUE(view->allBuilt());
        // Render both: the previews and the frame rows of the table follow the camera.
        view->left()->viewport()->grabFrame();
        view->right()->viewport()->grabFrame();
    }

    ProjectSession session;
    std::unique_ptr<CompareView> view;
};

TEST_F(CompareViewTest, BothSidesBuildInTheBackgroundAndShowTheirPreview) {
    QSignalSpy finished(view.get(), &CompareView::buildsFinished);
    openBoth();
    view->fitView();
    // Both sides are building at once, off the GUI thread (open returned).
    EXPECT_TRUE(view->left()->building());
    EXPECT_TRUE(view->right()->building());
    const QImage emptyLeft = view->left()->viewport()->grabFrame();
    const QImage emptyRight = view->right()->viewport()->grabFrame();
    ASSERT_TRUE(waitUntilIdle(*view->left()));
    ASSERT_TRUE(waitUntilIdle(*view->right()));
    ASSERT_TRUE(view->allBuilt());
    EXPECT_EQ(finished.count(), 1); // once, when the second side finished
    // The status texts changed meanwhile; the views kept their size (and equal widths).
    EXPECT_EQ(view->left()->viewport()->size(), emptyLeft.size() / emptyLeft.devicePixelRatio());
    EXPECT_LE(std::abs(view->left()->viewport()->width() - view->right()->viewport()->width()), 1);
    EXPECT_EQ(view->left()->viewport()->height(), view->right()->viewport()->height());

    // The left side is the document's Bake node, run through the document's graph (its status
    // came in); the right side its configuration over that branch, in a temporary branch that
    // the document does not get.
    const ClusterTree& sphere = *view->left()->built()->build->tree;
    const ClusterTree& aabb = *view->right()->built()->build->tree;
    EXPECT_EQ(sphere.volume, VolumeType::Sphere);
    EXPECT_EQ(aabb.volume, VolumeType::Aabb);
    EXPECT_EQ(aabb.k, 2.0);
    EXPECT_EQ(view->left()->built()->build, graph().sharedOutput(kDefaultBake));
    EXPECT_EQ(graph().status(kDefaultBake), NodeStatus::UpToDate);
    EXPECT_EQ(graph().nodeIds(), (std::vector<NodeId>{1, 2, 3, 4}));
    EXPECT_EQ(view->right()->built()->build->bakeParams.method, ProxyMethod::Decimate);

    for (ComparePane* pane : {view->left(), view->right()}) {
        const QImage frame = pane->viewport()->grabFrame();
        const QImage& empty = pane == view->left() ? emptyLeft : emptyRight;
        // The fitted sample scene covers a good part of each view; before the build, nothing.
        EXPECT_GT(test::foregroundShare(frame, empty), 0.05);
        EXPECT_EQ(pane->model()->view().mode, DisplayMode::Hlod);
        EXPECT_FALSE(pane->display()->drawList().empty());
        EXPECT_GT(pane->display()->lastFrame().triangles, 0u);
        EXPECT_TRUE(pane->display()->overlayText().startsWith(QStringLiteral("Draw calls: ")));
    }
}

TEST_F(CompareViewTest, TableRowsAreEachSidesBuildAndFrameWithTheLowerHighlighted) {
    openSample();
    CompareTable* table = view->table();
    for (ComparePane* pane : {view->left(), view->right()}) {
        const auto side = pane == view->left() ? CompareTable::Left : CompareTable::Right;
        const BuiltHlod& built = *pane->built();
        EXPECT_EQ(table->value(CompareTable::NodesRow, side), built.build->tree->nodes.size());
        EXPECT_EQ(table->value(CompareTable::ProxyTrianglesRow, side),
                  built.build->bake->proxyTriangles);
        EXPECT_EQ(table->value(CompareTable::PackageRow, side), built.package.bytesOnDisk);
        EXPECT_EQ(table->value(CompareTable::DrawCallsRow, side),
                  pane->display()->lastFrame().drawCalls);
        EXPECT_EQ(table->value(CompareTable::TrianglesRow, side),
                  pane->display()->lastFrame().triangles);
        EXPECT_EQ(table->item(CompareTable::NodesRow, side)->data(Qt::UserRole).toULongLong(),
                  built.build->tree->nodes.size());
    }
    // The package holds the leaves' meshes plus the proxies: more bytes than proxy triangles.
    EXPECT_GT(*table->value(CompareTable::PackageRow, CompareTable::Left),
              *table->value(CompareTable::ProxyTrianglesRow, CompareTable::Left));
    for (int r = 0; r < CompareTable::RowCount; ++r) {
        const auto row = static_cast<CompareTable::Row>(r);
        const std::uint64_t l = *table->value(row, CompareTable::Left);
        const std::uint64_t rv = *table->value(row, CompareTable::Right);
        if (l == rv) {
            EXPECT_FALSE(table->better(row).has_value());
            continue;
        }
        const auto best = l < rv ? CompareTable::Left : CompareTable::Right;
        EXPECT_EQ(table->better(row), best) << "row " << r;
        EXPECT_TRUE(table->item(row, best)->font().bold());
        EXPECT_FALSE(table->item(row, 1 - best)->font().bold());
    }
    EXPECT_EQ(table->horizontalHeaderItem(CompareTable::Left)->text(),
              QStringLiteral("Left: Bake #3: Sphere"));
    EXPECT_EQ(table->horizontalHeaderItem(CompareTable::Right)->text(),
              QStringLiteral("Right: AABB k=2 (over Bake #3)"));
}

TEST_F(CompareViewTest, CamerasAreLinkedBothWaysWithoutEcho) {
    openSample();
    vtkCamera* left = view->left()->viewport()->camera();
    vtkCamera* right = view->right()->viewport()->camera();
    ASSERT_TRUE(CameraLink::samePose(left, right)); // fitted alike
    const glm::dvec3 before(right->GetPosition()[0], right->GetPosition()[1],
                            right->GetPosition()[2]);

    view->left()->viewport()->orbit(40.0, 15.0);
    EXPECT_TRUE(CameraLink::samePose(left, right));
    const glm::dvec3 after(right->GetPosition()[0], right->GetPosition()[1],
                           right->GetPosition()[2]);
    EXPECT_GT(glm::length(after - before), 1e-3);

    // Moving the right one moves the left one (both directions).
    view->right()->viewport()->zoom(1.5);
    EXPECT_TRUE(CameraLink::samePose(left, right));

    // Rendering resets clipping ranges (camera modifications): that is no reason to copy.
    const int copies = view->cameraLink()->copies();
    view->left()->viewport()->grabFrame();
    view->right()->viewport()->grabFrame();
    EXPECT_EQ(view->cameraLink()->copies(), copies);
    // Both LOD selections now run for the same camera.
    EXPECT_EQ(view->left()->display()->currentCamera().eye,
              view->right()->display()->currentCamera().eye);

    // Unlinked, each side keeps its own camera.
    view->linkBox()->setChecked(false);
    view->left()->viewport()->orbit(-30.0, 0.0);
    EXPECT_FALSE(CameraLink::samePose(left, right));
    // Linked again, the right side catches up.
    view->linkBox()->setChecked(true);
    EXPECT_TRUE(CameraLink::samePose(left, right));
}

TEST_F(CompareViewTest, ChangingOneSidesVolumeRebuildsOnlyThatSide) {
    openSample();
    const std::shared_ptr<const NodeOutput> leftBuild = view->left()->built()->build;
    QComboBox* volume = view->right()->volumeBox();
    volume->setCurrentIndex(volume->findData(QStringLiteral("octree")));
    EXPECT_TRUE(view->right()->building());
    EXPECT_FALSE(view->left()->building());
    EXPECT_EQ(view->right()->config().volume, VolumeType::Octree);
    EXPECT_FALSE(view->right()->kBox()->isEnabled()); // k is for AABB only
    ASSERT_TRUE(waitUntilIdle(*view->right()));
    ASSERT_EQ(view->right()->state(), ComparePane::State::Built);
    EXPECT_EQ(view->right()->built()->build->tree->volume, VolumeType::Octree);
    EXPECT_EQ(view->left()->built()->build, leftBuild); // the left side was not touched
    EXPECT_EQ(view->table()->value(CompareTable::NodesRow, CompareTable::Right),
              view->right()->built()->build->tree->nodes.size());
    EXPECT_EQ(view->table()->horizontalHeaderItem(CompareTable::Right)->text(),
              QStringLiteral("Right: Octree (over Bake #3)"));
}

TEST_F(CompareViewTest, CancelLeavesNoResult) {
    openSample();
    view->right()->kBox()->setValue(1.0); // AABB k=1: a new build of the right side
    ASSERT_TRUE(view->right()->building());
    view->right()->cancelButton()->click();
    ASSERT_TRUE(waitUntilIdle(*view->right()));
    EXPECT_EQ(view->right()->state(), ComparePane::State::Cancelled);
    EXPECT_EQ(view->right()->built(), nullptr);
    EXPECT_FALSE(view->right()->model()->hasBuild());
    for (int r = 0; r < CompareTable::RowCount; ++r)
        EXPECT_FALSE(view->table()->value(static_cast<CompareTable::Row>(r), CompareTable::Right));
    EXPECT_EQ(view->table()->item(CompareTable::NodesRow, CompareTable::Right)->text(),
              QStringLiteral("–"));
    // Nothing drawn on the cancelled side, the other side keeps its result.
    view->right()->viewport()->grabFrame();
    EXPECT_TRUE(view->right()->display()->drawList().empty());
    EXPECT_EQ(view->left()->state(), ComparePane::State::Built);
    EXPECT_FALSE(view->allBuilt());
}

TEST_F(CompareViewTest, ClosingOrDestroyingMidBuildIsSafe) {
    openBoth();
    ASSERT_TRUE(view->building());
    view->close(); // cancels both
    ASSERT_TRUE(waitUntilIdle(*view->left()));
    ASSERT_TRUE(waitUntilIdle(*view->right()));
    EXPECT_EQ(view->left()->state(), ComparePane::State::Cancelled);
    EXPECT_EQ(view->right()->state(), ComparePane::State::Cancelled);

    view->show();
    view->rebuildAll();
    ASSERT_TRUE(view->building());
    view.reset(); // joins both workers; their queued results go nowhere
    QTest::qWait(300);
    SUCCEED();
}

TEST_F(CompareViewTest, DocumentChangesRebuildOnlyTheSidesTheyReach) {
    openSample();
    // Volume and k of Bake #3's Cluster node: the left side shows that node, so it rebuilds;
    // the right side sets its own volume and k over the branch, so it does not.
    ASSERT_TRUE(session.undo()->execute(
        std::make_unique<SetParameter>(kDefaultCluster, "volume", std::string("octree"))));
    view->documentChanged();
    EXPECT_TRUE(view->left()->building());
    EXPECT_FALSE(view->right()->building());
    EXPECT_EQ(view->left()->config().volume, VolumeType::Octree);
    ASSERT_TRUE(waitUntilIdle(*view->left()));
    // Max children is shared: both sides rebuild.
    ASSERT_TRUE(session.undo()->execute(
        std::make_unique<SetParameter>(kDefaultCluster, "max_children", 4)));
    view->documentChanged();
    EXPECT_TRUE(view->left()->building());
    EXPECT_TRUE(view->right()->building());
    EXPECT_EQ(view->right()->config().volume, VolumeType::Aabb);
    view->cancelAll();
}

TEST_F(CompareViewTest, TwoBakeNodesOfTheDocumentCompareSideBySide) {
    // A second branch: Duplicate Branch of Cluster #2, made AABB k = 2 (Cluster #5 -> Bake #6).
    ASSERT_TRUE(session.undo()->execute(std::make_unique<DuplicateNodes>(
        DuplicateNodes::branchFrom(graph(), kDefaultCluster),
        std::vector<std::pair<double, double>>{{0, 200}, {200, 200}, {400, 200}}, true)));
    ASSERT_TRUE(
        session.undo()->execute(std::make_unique<SetParameter>(5, "volume", std::string("aabb"))));
    ASSERT_TRUE(session.undo()->execute(std::make_unique<SetParameter>(5, "k", 2.0)));
    const auto sides = defaultSides(graph(), kDefaultBake, {kDefaultBake, 6});
    EXPECT_EQ(sides.second.bake, 6u); // the other branch, not a configuration
    view->open(test::sampleBuild().scene, &graph(), kDefaultBake, sides);
    ASSERT_TRUE(waitUntilIdle(*view->left()));
    ASSERT_TRUE(waitUntilIdle(*view->right()));
    ASSERT_TRUE(view->allBuilt());
    // Both ran through the document's graph: both branches are up to date there.
    EXPECT_EQ(graph().status(kDefaultBake), NodeStatus::UpToDate);
    EXPECT_EQ(graph().status(6), NodeStatus::UpToDate);
    EXPECT_EQ(view->right()->built()->build, graph().sharedOutput(6));
    EXPECT_EQ(view->right()->built()->build->tree->volume, VolumeType::Aabb);
    EXPECT_EQ(view->table()->horizontalHeaderItem(CompareTable::Right)->text(),
              QStringLiteral("Right: Bake #6: AABB k=2"));
    // A Bake-node side offers no "Use These Settings" (it is the document's already), and its
    // source box lists both Bake nodes and Custom.
    EXPECT_TRUE(view->right()->useButton()->isHidden());
    EXPECT_EQ(view->right()->sourceBox()->count(), 3);
    // Editing its selector makes it a configuration over Bake #6.
    view->right()->screenSizeBox()->setValue(150.0);
    EXPECT_EQ(view->right()->side().bake, kNoNode);
    EXPECT_EQ(view->right()->baseBake(), 6u);
    EXPECT_EQ(view->right()->config().screenSize, 150.0);
    view->cancelAll();
}

TEST_F(CompareViewTest, UseTheseSettingsIsOneUndoableCommand) {
    Document& doc = session.document();
    view->setUndo(session.undo());
    openSample();
    ASSERT_FALSE(view->right()->useButton()->isHidden());
    EXPECT_TRUE(view->left()->useButton()->isHidden()); // the document's own node
    const ParamValues& cluster = doc.graph().node(kDefaultCluster).params;
    ASSERT_EQ(paramText(cluster, "volume"), "sphere");
    ASSERT_EQ(paramNumber(cluster, "k"), 1.0);
    const int steps = session.undo()->stack()->count();

    view->right()->useButton()->click(); // AABB k=2, S = 300 (already the document's)
    const ParamValues& after = doc.graph().node(kDefaultCluster).params;
    EXPECT_EQ(paramText(after, "volume"), "aabb");
    EXPECT_EQ(paramNumber(after, "k"), 2.0);
    EXPECT_EQ(session.undo()->stack()->count(), steps + 1);
    EXPECT_EQ(session.undo()->stack()->undoText(),
              QStringLiteral("Use AABB k=2, S = 300 px for Bake #3 from the comparison"));

    session.undo()->stack()->undo();
    const ParamValues& undone = doc.graph().node(kDefaultCluster).params;
    EXPECT_EQ(paramText(undone, "volume"), "sphere");
    EXPECT_EQ(paramNumber(undone, "k"), 1.0);
    view->cancelAll();
}

TEST(CompareConfig, UseCommandSetsOnlyWhatDiffersAndRevertsOnFailure) {
    Document doc;
    auto command = useConfigurationCommand(doc, kDefaultBake, config(VolumeType::Aabb, 2.0, 400.0));
    ASSERT_NE(command, nullptr);
    EXPECT_EQ(command->size(), 3u); // volume, k, screen size
    EXPECT_EQ(useConfigurationCommand(doc, kDefaultBake, config(VolumeType::Sphere, 7.0)), nullptr)
        << "k is not set for a sphere, the rest already matches";
    const nlohmann::json before = doc.toJson();
    // A screen size outside its declared range fails on the last part: the first two revert.
    auto bad = useConfigurationCommand(doc, kDefaultBake, config(VolumeType::Aabb, 2.0, 1e9));
    ASSERT_NE(bad, nullptr);
    EXPECT_THROW(doc.execute(std::move(bad)), Error);
    EXPECT_EQ(doc.toJson(), before);
}

TEST(CompareConfig, TextFormsParseOverTheBaseBranch) {
    const CompareConfig base = config(VolumeType::Sphere, 0.5, 250.0);
    CompareSide c;
    ASSERT_TRUE(parseSide(QStringLiteral("aabb-k2@400"), base, c));
    EXPECT_EQ(c, (CompareSide{kNoNode, config(VolumeType::Aabb, 2.0, 400.0)}));
    ASSERT_TRUE(parseSide(QStringLiteral("AABB"), base, c)); // k and S of the base
    EXPECT_EQ(c.config, config(VolumeType::Aabb, 0.5, 250.0));
    ASSERT_TRUE(parseSide(QStringLiteral("current"), base, c));
    EXPECT_EQ(c.config, base);
    ASSERT_TRUE(parseSide(configSpec(config(VolumeType::Aabb, 1.5, 312.5)), base, c));
    EXPECT_EQ(c.config, config(VolumeType::Aabb, 1.5, 312.5)); // configSpec round-trips
    ASSERT_TRUE(parseSide(QStringLiteral("#6"), base, c));     // a Bake node of the document
    EXPECT_EQ(c.bake, 6u);
    QString error;
    EXPECT_FALSE(parseSide(QStringLiteral("sphere-k2"), base, c, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("aabb only")));
    EXPECT_FALSE(parseSide(QStringLiteral("cube"), base, c, &error));
    EXPECT_FALSE(parseSide(QStringLiteral("aabb-k20"), base, c, &error)); // k in [0, 16]
    EXPECT_FALSE(parseSide(QStringLiteral("sphere@0"), base, c, &error)); // S >= 1

    std::pair<CompareSide, CompareSide> pair;
    ASSERT_TRUE(parseSidePair(QStringLiteral("#3:aabb-k2"), base, pair));
    EXPECT_EQ(pair.first.bake, 3u);
    EXPECT_EQ(pair.second.config, config(VolumeType::Aabb, 2.0, 250.0));
    EXPECT_FALSE(parseSidePair(QStringLiteral("sphere"), base, pair));

    // Defaults: the shown branch against AABB k=2 (sphere when it is AABB already) when the
    // document has no other branch.
    PipelineGraph g = PipelineGraph::makeDefault();
    const auto fromSphere = defaultSides(g, kDefaultBake, {kDefaultBake});
    EXPECT_EQ(fromSphere.first, (CompareSide{kDefaultBake, configOf(g, kDefaultBake)}));
    EXPECT_EQ(fromSphere.second, (CompareSide{kNoNode, config(VolumeType::Aabb, 2.0, 300.0)}));
    g.setParam(kDefaultCluster, "volume", std::string("aabb"));
    EXPECT_EQ(defaultSides(g, kDefaultBake, {kDefaultBake}).second.config.volume,
              VolumeType::Sphere);
    applyConfig(g, kDefaultCluster, kDefaultBake, config(VolumeType::Octree, 3.0, 90.0));
    EXPECT_EQ(configOf(g, kDefaultBake), config(VolumeType::Octree, 3.0, 90.0));
}

} // namespace
} // namespace hlod::widgets
