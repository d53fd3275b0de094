// Tests of widgets/ClusterTreeModel on the tiny hand-built scene (three instances) and the
// sample scene: structure, names, counts, volumes and proxy triangles.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <QAbstractItemModelTester>

#include "TestBuilds.h"
#include "TestScenes.h"
#include "pipeline/view/TreeViews.h"
#include "widgets/ClusterTreeModel.h"

namespace hlod::widgets {
namespace {

std::uint64_t value(const ClusterTreeModel& model, Id node, int column) {
    const QModelIndex index = model.indexOfNode(node);
    return model.index(index.row(), column, index.parent())
        .data(ClusterTreeModel::ValueRole)
        .toULongLong();
}

TEST(ClusterTreeModel, TinySceneShowsOneRootAndALeafPerInstance) {
    const auto scene = std::make_shared<const Scene>(test::makeTinyScene());
    const BuiltHlod built = test::buildNow(scene);
    const ClusterTree& tree = *built.build->tree;
    ClusterTreeModel model;
    model.setBuild(scene, built.build);
    ASSERT_EQ(model.rowCount(), 1);
    const QModelIndex root = model.index(0, 0);
    EXPECT_EQ(model.nodeOf(root), tree.root);
    EXPECT_EQ(root.data().toString(), QStringLiteral("Cluster %1").arg(tree.root));
    // tri (1) + scaled tri (1) + quad (2): the root's subtree holds 4 triangles.
    EXPECT_EQ(value(model, tree.root, ClusterTreeModel::TrianglesColumn), 4u);
    EXPECT_EQ(value(model, tree.root, ClusterTreeModel::LevelColumn),
              static_cast<std::uint64_t>(tree.height()));
    EXPECT_EQ(value(model, tree.root, ClusterTreeModel::ProxyTrianglesColumn),
              built.build->bake->nodes[tree.root].proxy.triangleCount());

    // Leaves carry the names of the scene nodes holding their instance: "left" (instance 0),
    // "right" (instance 1) and the scene root "root" (instance 2), one triangle, one, two.
    const char* names[] = {"left", "right", "root"};
    const std::uint64_t triangles[] = {1, 1, 2};
    for (Id instance = 0; instance < 3; ++instance) {
        const Id leaf = leafOfInstance(tree, instance);
        ASSERT_NE(leaf, kNoId);
        const QModelIndex index = model.indexOfNode(leaf);
        EXPECT_EQ(index.data().toString(), QString::fromLatin1(names[instance]));
        EXPECT_EQ(model.parent(index), model.indexOfNode(tree.nodes[leaf].parent));
        EXPECT_EQ(value(model, leaf, ClusterTreeModel::TrianglesColumn), triangles[instance]);
        EXPECT_EQ(value(model, leaf, ClusterTreeModel::LevelColumn), 0u);
        EXPECT_EQ(value(model, leaf, ClusterTreeModel::ProxyTrianglesColumn), 0u);
    }
    // Sphere tree: the volume column is the bounding sphere's volume, 4/3 pi r^3.
    const double r = tree.nodes[tree.root].sphere.radius;
    EXPECT_NEAR(model.volume(tree.root), 4.0 / 3.0 * std::numbers::pi * r * r * r, 1e-9);
}

TEST(ClusterTreeModel, EveryNodeOfTheSampleIsReachableFromTheRootAndQtChecksPass) {
    const BuiltHlod& built = test::sampleBuild();
    ClusterTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    model.setBuild(built.scene, built.build);
    // Walking rows from the root visits each cluster node exactly once.
    std::vector<int> seen(built.build->tree->nodes.size(), 0);
    std::vector<QModelIndex> stack{model.index(0, 0)};
    while (!stack.empty()) {
        const QModelIndex index = stack.back();
        stack.pop_back();
        ++seen[model.nodeOf(index)];
        for (int row = 0; row < model.rowCount(index); ++row)
            stack.push_back(model.index(row, 0, index));
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(seen.size()));
    model.setBuild(nullptr, nullptr);
    EXPECT_EQ(model.rowCount(), 0);
}

} // namespace
} // namespace hlod::widgets
