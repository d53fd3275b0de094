// Tests of widgets/SceneTreeModel on a hand-built hierarchy.
#include <gtest/gtest.h>

#include <QAbstractItemModelTester>

#include "TestScenes.h"
#include "widgets/SceneTreeModel.h"

namespace hlod::widgets {
namespace {

TEST(SceneTreeModel, RowsFollowTheNodeHierarchy) {
    // makeTinyScene: root -> {left, group -> {right}}.
    SceneTreeModel model;
    model.setScene(std::make_shared<const Scene>(test::makeTinyScene()));
    ASSERT_EQ(model.rowCount(), 1); // the root node only
    const QModelIndex root = model.index(0, 0);
    EXPECT_EQ(model.nodeOf(root), 0u);
    ASSERT_EQ(model.rowCount(root), 2);
    const QModelIndex left = model.index(0, 0, root);
    const QModelIndex group = model.index(1, 0, root);
    EXPECT_EQ(model.data(left).toString(), QStringLiteral("left"));
    EXPECT_EQ(model.data(group).toString(), QStringLiteral("group"));
    ASSERT_EQ(model.rowCount(group), 1);
    const QModelIndex right = model.index(0, 0, group);
    EXPECT_EQ(model.data(right).toString(), QStringLiteral("right"));
    EXPECT_EQ(model.rowCount(right), 0);
    EXPECT_EQ(model.parent(right), group);
    EXPECT_EQ(model.parent(group), root);
    EXPECT_FALSE(model.parent(root).isValid());
    EXPECT_EQ(model.indexOfNode(3), right);
    EXPECT_EQ(model.columnCount(), 3);
}

TEST(SceneTreeModel, CountsAreSubtreeTotals) {
    // Instances: tri on "left" (1 triangle), tri on "right" (1), quad on root (2).
    SceneTreeModel model;
    model.setScene(std::make_shared<const Scene>(test::makeTinyScene()));
    const QModelIndex root = model.index(0, 0);
    const QModelIndex group = model.index(1, 0, root);
    auto text = [&](const QModelIndex& index, int column) {
        return model.data(model.index(index.row(), column, index.parent())).toString();
    };
    EXPECT_EQ(text(root, SceneTreeModel::MeshesColumn), QStringLiteral("3"));
    EXPECT_EQ(text(root, SceneTreeModel::TrianglesColumn), QStringLiteral("4"));
    EXPECT_EQ(text(group, SceneTreeModel::MeshesColumn), QStringLiteral("1"));
    EXPECT_EQ(text(group, SceneTreeModel::TrianglesColumn), QStringLiteral("1"));
    EXPECT_EQ(model.counts(0).ownMeshes, 1u); // the quad
    EXPECT_EQ(model.counts(0).ownTriangles, 2u);
    EXPECT_EQ(model.counts(2).ownMeshes, 0u); // "group" holds nothing itself
}

TEST(SceneTreeModel, PassesQtModelConsistencyChecks) {
    SceneTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    model.setScene(std::make_shared<const Scene>(test::makeCubeGrid(40)));
    EXPECT_EQ(model.rowCount(model.index(0, 0)), 40);
    model.setScene(nullptr);
    EXPECT_EQ(model.rowCount(), 0);
}

TEST(SceneTreeModel, UnnamedNodesGetAGeneratedName) {
    Scene scene;
    scene.addNode("", 0);
    SceneTreeModel model;
    model.setScene(std::make_shared<const Scene>(std::move(scene)));
    const QModelIndex child = model.index(0, 0, model.index(0, 0));
    EXPECT_EQ(model.data(child).toString(), QStringLiteral("(unnamed 1)"));
}

} // namespace
} // namespace hlod::widgets
