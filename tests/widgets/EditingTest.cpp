// The editor's editing wiring (issue #7): the document as the one source of parameters
// (ProjectSession + BuildParameters + StudioModel), project save/open with the dirty mark and
// autosave recovery, cluster hand edits from the Clusters tab, and the export dialog.
#include <gtest/gtest.h>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QGroupBox>
#include <QItemSelectionModel>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>
#include <QTreeView>
#include <QUndoStack>

#include "TestBuilds.h"
#include "pipeline/doc/Commands.h"
#include "widgets/ClusterEditActions.h"
#include "widgets/ClusterTreeModel.h"
#include "widgets/ExportDialog.h"
#include "widgets/StudioModel.h"
#include "widgets/doc/AutoRebuild.h"
#include "widgets/doc/ProjectSession.h"
#include "widgets/params/BuildParameters.h"
#include "widgets/params/ParameterPanel.h"

namespace hlod::widgets {
namespace {

double clusterK(const Document& doc) {
    return paramNumber(doc.graph().node(kDefaultCluster).params, "k");
}

TEST(Editing, ParameterEditsGoThroughTheDocumentAndUndo) {
    ProjectSession session;
    StudioModel model;
    model.setGraph(&session.document().graph());
    BuildParameters params(*session.undo(), &model);
    std::unique_ptr<QAction> undo(session.undo()->stack()->createUndoAction(nullptr));
    std::unique_ptr<QAction> redo(session.undo()->stack()->createRedoAction(nullptr));
    EXPECT_FALSE(undo->isEnabled());

    // The dock shows the selected node only: the Cluster node, then the Bake node.
    params.showNode(kDefaultCluster);
    auto* k = params.panel()->findChild<QDoubleSpinBox*>(QStringLiteral("param_k"));
    auto* volume = params.panel()->findChild<QComboBox*>(QStringLiteral("param_volume"));
    ASSERT_NE(k, nullptr);
    ASSERT_NE(volume, nullptr);
    EXPECT_EQ(params.panel()->findChild<QDoubleSpinBox*>(QStringLiteral("param_screen_size")),
              nullptr);
    volume->setCurrentText(QStringLiteral("aabb"));
    k->setValue(2.0);
    params.showNode(kDefaultBake);
    auto* size = params.panel()->findChild<QDoubleSpinBox*>(QStringLiteral("param_screen_size"));
    ASSERT_NE(size, nullptr);
    size->setValue(450.0);
    const PipelineGraph& g = session.document().graph();
    EXPECT_EQ(clusterK(session.document()), 2.0);
    EXPECT_EQ(paramText(g.node(kDefaultCluster).params, "volume"), "aabb");
    EXPECT_EQ(paramNumber(g.node(kDefaultBake).params, "screen_size"), 450.0);
    EXPECT_EQ(session.document().history().count(), 3u);
    EXPECT_EQ(session.undo()->stack()->undoText(), QStringLiteral("Set Screen size of Bake #3"));
    EXPECT_TRUE(undo->isEnabled());
    EXPECT_FALSE(redo->isEnabled());
    EXPECT_TRUE(session.isDirty());

    session.undo()->stack()->undo(); // screen size
    session.undo()->stack()->undo(); // k
    EXPECT_EQ(clusterK(session.document()), 1.0);
    EXPECT_EQ(size->value(), 300.0);
    EXPECT_EQ(paramNumber(g.node(kDefaultBake).params, "screen_size"), 300.0);
    EXPECT_TRUE(redo->isEnabled());

    session.undo()->stack()->redo();
    EXPECT_EQ(clusterK(session.document()), 2.0);
    params.showNode(kDefaultCluster);
    k = params.panel()->findChild<QDoubleSpinBox*>(QStringLiteral("param_k"));
    EXPECT_EQ(k->value(), 2.0);
    EXPECT_EQ(params.panel()->findChild<QComboBox*>(QStringLiteral("param_volume"))->currentText(),
              QStringLiteral("aabb"));
    EXPECT_EQ(params.group()->title(), QStringLiteral("Cluster #2 — Clustering"));
}

TEST(Editing, ProjectRoundTripAndDirtyMark) {
    QTemporaryDir dir;
    const QString scene = dir.filePath(QStringLiteral("scene.obj"));
    {
        QFile f(scene);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    }
    const QString path = dir.filePath(QStringLiteral("plant.hlodproj"));
    ProjectSession session;
    QSignalSpy dirty(&session, &ProjectSession::dirtyChanged);
    session.newDocument({scene.toStdString()});
    EXPECT_FALSE(session.isDirty());
    EXPECT_EQ(session.displayName(), QStringLiteral("Untitled"));
    ASSERT_TRUE(session.undo()->execute(std::make_unique<SetParameter>(kDefaultCluster, "k", 3.0)));
    ASSERT_TRUE(session.undo()->execute(
        std::make_unique<SetParameter>(kDefaultBake, "screen_size", 120.0)));
    EXPECT_TRUE(session.isDirty());
    ASSERT_EQ(dirty.count(), 1);
    EXPECT_TRUE(dirty.at(0).at(0).toBool());

    session.save(path);
    EXPECT_FALSE(session.isDirty());
    ASSERT_EQ(dirty.count(), 2);
    EXPECT_FALSE(dirty.at(1).at(0).toBool());
    EXPECT_EQ(session.displayName(), QStringLiteral("plant.hlodproj"));
    EXPECT_FALSE(session.shouldPromptOnClose());

    ProjectSession reopened;
    reopened.open(path);
    const Document& back = reopened.document();
    EXPECT_FALSE(reopened.isDirty());
    ASSERT_EQ(back.sources().size(), 1u);
    EXPECT_EQ(QFileInfo(QString::fromStdString(back.sources()[0].string())).canonicalFilePath(),
              QFileInfo(scene).canonicalFilePath());
    EXPECT_EQ(clusterK(back), 3.0);
    EXPECT_EQ(paramNumber(back.graph().node(kDefaultBake).params, "screen_size"), 120.0);

    // An edit after the save: dirty, autosaved, recoverable; the plain project keeps k = 3.
    QThread::msleep(20); // the autosave must be strictly newer than the project
    ASSERT_TRUE(session.undo()->execute(std::make_unique<SetParameter>(kDefaultCluster, "k", 5.0)));
    EXPECT_TRUE(session.shouldPromptOnClose());
    ASSERT_TRUE(session.autosave());
    EXPECT_TRUE(ProjectSession::hasNewerAutosave(path));
    ProjectSession recovered;
    recovered.open(path, true);
    EXPECT_EQ(clusterK(recovered.document()), 5.0);
    EXPECT_TRUE(recovered.isDirty()); // recovered content is not saved yet
    recovered.save(path);
    EXPECT_FALSE(recovered.isDirty());
    EXPECT_FALSE(QFileInfo::exists(path + QStringLiteral(".autosave")));
    EXPECT_EQ(session.autosaveTimer()->interval(), 120000);
}

TEST(Editing, MergeTwoClustersByHandRebuildsAndUndoRestores) {
    const BuiltHlod& sample = test::sampleBuild();
    ProjectSession session;
    Document& doc = session.document();
    StudioModel model;
    ASSERT_TRUE(test::showSampleBuild(session, model));
    ClusterTreeModel treeModel;
    QTreeView tree;
    tree.setModel(&treeModel);
    treeModel.setBuild(sample.scene, sample.build);
    ClusterEditActions edits(&session, &model, &tree, &treeModel);
    AutoRebuild rebuild(&session, &model);
    rebuild.setDelay(0);

    const QModelIndex root = treeModel.index(0, 0);
    ASSERT_GE(treeModel.rowCount(root), 2);
    const QModelIndex a = treeModel.index(0, 0, root);
    const QModelIndex b = treeModel.index(1, 0, root);
    tree.selectionModel()->select(a, QItemSelectionModel::Select | QItemSelectionModel::Rows);
    tree.selectionModel()->select(b, QItemSelectionModel::Select | QItemSelectionModel::Rows);
    const ClusterTree& before = *sample.build->tree;
    InstanceSet merged = leafSet(before, treeModel.nodeOf(a));
    const InstanceSet second = leafSet(before, treeModel.nodeOf(b));
    merged.insert(merged.end(), second.begin(), second.end());
    merged = normalizedSet(merged);
    ASSERT_EQ(edits.selectedClusters().size(), 2u);
    edits.updateActions();
    EXPECT_TRUE(edits.mergeAction()->isEnabled());

    ASSERT_TRUE(edits.merge());
    const HandEdits& now = doc.graph().node(kDefaultCluster).edits;
    ASSERT_EQ(now.locked.size(), 1u);
    EXPECT_EQ(now.locked[0], merged);
    ASSERT_TRUE(test::waitForBuild(model)); // the merge rebuilt the HLOD
    const ClusterTree& after = *model.built().build->tree;
    const Id group = findCluster(after, merged);
    ASSERT_NE(group, kNoId); // the merged clusters are exactly one subtree
    EXPECT_TRUE(after.nodes[group].locked);
    EXPECT_EQ(model.built().build->cluster.lockedGroups.size(), 1u);
    EXPECT_EQ(session.undo()->stack()->undoText(), QStringLiteral("Merge clusters (Cluster #2)"));

    session.undo()->stack()->undo();
    EXPECT_TRUE(doc.graph().node(kDefaultCluster).edits.empty());
    ASSERT_TRUE(test::waitForBuild(model)); // undo rebuilds without the lock
    EXPECT_TRUE(model.built().build->cluster.lockedGroups.empty());
    EXPECT_EQ(session.undo()->stack()->undoText(), QStringLiteral("Set Threads of Bake #3"));
}

TEST(Editing, ExportDialogRunsTheExportNodeWithItsFolder) {
    QTemporaryDir dir;
    ProjectSession session;
    StudioModel model;
    ASSERT_TRUE(test::showSampleBuild(session, model));
    const QString out = dir.filePath(QStringLiteral("package"));
    ExportDialog dialog(*session.undo(), &model, kDefaultExport, out);
    dialog.findChild<QCheckBox*>(QStringLiteral("exportDlod"))->setChecked(false);
    QSignalSpy exported(&dialog, &ExportDialog::exported);
    QSignalSpy progressed(&model, &StudioModel::nodeProgress);
    ASSERT_TRUE(dialog.startExport());
    EXPECT_TRUE(model.building());
    EXPECT_FALSE(dialog.startExport()); // one run at a time
    // The folder and the DLOD choice are the Export node's, set as one undoable step.
    const PipelineGraph& g = session.document().graph();
    EXPECT_EQ(paramText(g.node(kDefaultExport).params, "output"), out.toStdString());
    EXPECT_FALSE(paramBool(g.node(kDefaultExport).params, "dlod"));
    EXPECT_EQ(session.undo()->stack()->undoText(),
              QStringLiteral("Export Export #4 to %1").arg(out));
    ASSERT_TRUE(exported.wait(120000));
    EXPECT_FALSE(model.building());
    EXPECT_EQ(dialog.result(), QDialog::Accepted);
    EXPECT_TRUE(QFileInfo::exists(out + QStringLiteral("/tileset.json")));
    EXPECT_TRUE(QFileInfo::exists(out + QStringLiteral("/hlod.json")));
    EXPECT_GT(exported.at(0).at(1).toLongLong(), 2); // tileset, hlod.json and tiles
    EXPECT_GT(progressed.count(), 0);
    // The run's status: the Export node is up to date (the Bake node was: only Export ran).
    EXPECT_EQ(g.status(kDefaultExport), NodeStatus::UpToDate);
    EXPECT_EQ(g.output(kDefaultExport)->exported->output.string(), out.toStdString());
}

TEST(Editing, CancelledExportLeavesNoPackage) {
    QTemporaryDir dir;
    ProjectSession session;
    StudioModel model;
    ASSERT_TRUE(test::showSampleBuild(session, model));
    const QString out = dir.filePath(QStringLiteral("package"));
    ExportDialog dialog(*session.undo(), &model, kDefaultExport, out);
    dialog.findChild<QCheckBox*>(QStringLiteral("exportDlod"))->setChecked(true);
    QSignalSpy cancelled(&model, &StudioModel::buildCancelled);
    QSignalSpy finished(&model, &StudioModel::runFinished);
    ASSERT_TRUE(dialog.startExport());
    dialog.reject(); // Cancel while it runs: stops the export, the dialog stays
    ASSERT_TRUE(cancelled.wait(120000) || !finished.isEmpty());
    if (!cancelled.isEmpty()) {
        EXPECT_FALSE(QFileInfo::exists(out)); // atomic: a cancelled export writes nothing
        EXPECT_EQ(session.document().graph().status(kDefaultExport), NodeStatus::Pending);
    }
}

} // namespace
} // namespace hlod::widgets
