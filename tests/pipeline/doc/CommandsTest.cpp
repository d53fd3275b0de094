// Every document command (pipeline/doc/Commands.h): executing it changes the document, undo
// restores exactly the previous document (the serialized JSON is identical) and redo gives
// exactly the edited one again.
#include <gtest/gtest.h>

#include "DocumentFixture.h"
#include "pipeline/core/Error.h"
#include "pipeline/doc/Commands.h"

namespace hlod {
namespace {

class Commands : public test::DocumentFixture {
protected:
    // Executes `cmd`, then checks undo -> before and redo -> after.
    void expectUndoRedoExact(std::unique_ptr<Command> cmd) {
        const nlohmann::json before = doc.toJson();
        const std::string name = cmd->text();
        doc.execute(std::move(cmd));
        const nlohmann::json after = doc.toJson();
        EXPECT_NE(after, before) << name << " changed nothing";
        doc.undo();
        EXPECT_EQ(doc.toJson(), before) << name;
        doc.redo();
        EXPECT_EQ(doc.toJson(), after) << name;
        doc.undo();
        EXPECT_EQ(doc.toJson(), before) << name;
    }
    NodeId cluster() const { return kDefaultCluster; }
};

TEST_F(Commands, SetParameter) {
    expectUndoRedoExact(std::make_unique<SetParameter>(cluster(), "k", 2.0));
}

TEST_F(Commands, SetSources) {
    const std::vector<std::filesystem::path> all = doc.sources();
    const std::vector<std::filesystem::path> three(all.begin(), all.begin() + 3);
    expectUndoRedoExact(std::make_unique<SetSources>(doc.importNode(), three));
}

TEST_F(Commands, AddNodeGivesItsIdBack) {
    expectUndoRedoExact(std::make_unique<AddNode>(NodeKind::Bake, 5.0, 6.0));
    EXPECT_EQ(doc.graph().nextId(), 5u); // undone: the id is free again
}

TEST_F(Commands, RemoveNodeRestoresItsConnections) {
    expectUndoRedoExact(std::make_unique<RemoveNode>(kDefaultBake));
    EXPECT_EQ(doc.graph().connections().size(), 3u);
}

TEST_F(Commands, ConnectAndDisconnect) {
    auto add = std::make_unique<AddNode>(NodeKind::Cluster);
    AddNode* added = add.get();
    doc.execute(std::move(add));
    expectUndoRedoExact(std::make_unique<ConnectNodes>(Connection{1, 0, added->node(), 0}));
    expectUndoRedoExact(std::make_unique<DisconnectNodes>(Connection{2, 0, 3, 0}));
}

TEST_F(Commands, MoveNode) { expectUndoRedoExact(std::make_unique<MoveNode>(2, 1.0, 2.0)); }

TEST_F(Commands, AddNodeAfterAnotherConnectsItInTheSameStep) {
    expectUndoRedoExact(std::make_unique<AddNode>(NodeKind::Bake, 5.0, 6.0, kDefaultCluster));
    doc.execute(std::make_unique<AddNode>(NodeKind::Bake, 5.0, 6.0, kDefaultCluster));
    EXPECT_EQ(doc.history().undoText(), "Add Bake #5");
    EXPECT_EQ(doc.graph().upstreamOf(5), kDefaultCluster);
    // A Bake cannot take an Import's scene: refused, nothing added.
    EXPECT_THROW(doc.execute(std::make_unique<AddNode>(NodeKind::Bake, 0.0, 0.0, 1)), Error);
    EXPECT_FALSE(doc.graph().hasNode(6));
    EXPECT_EQ(doc.graph().nextId(), 6u);
}

TEST_F(Commands, DisconnectNodeTakesEveryConnectionOfTheNode) {
    expectUndoRedoExact(std::make_unique<DisconnectNode>(kDefaultBake));
    doc.execute(std::make_unique<DisconnectNode>(kDefaultBake));
    EXPECT_EQ(doc.history().undoText(), "Disconnect Bake #3");
    EXPECT_EQ(doc.graph().connections().size(), 1u); // Import -> Cluster stays
}

TEST_F(Commands, RenameNodeChangesOnlyTheName) {
    expectUndoRedoExact(std::make_unique<RenameNode>(kDefaultBake, "coarse"));
    doc.graph().run({kDefaultCluster});
    doc.execute(std::make_unique<RenameNode>(kDefaultCluster, "spheres"));
    EXPECT_EQ(doc.history().undoText(), "Rename Cluster #2 to 'spheres'");
    EXPECT_EQ(describeNode(doc.graph().node(kDefaultCluster)), "Cluster #2 'spheres'");
    EXPECT_EQ(doc.graph().status(kDefaultCluster), NodeStatus::UpToDate); // nothing to rerun
}

TEST_F(Commands, DuplicateBranchMakesASecondVariantFromTheSameImport) {
    doc.graph().setParam(kDefaultExport, "output", std::string("/out/pkg"));
    const std::vector<NodeId> branch = DuplicateNodes::branchFrom(doc.graph(), kDefaultCluster);
    EXPECT_EQ(branch, (std::vector<NodeId>{2, 3, 4}));
    expectUndoRedoExact(std::make_unique<DuplicateNodes>(
        branch, std::vector<std::pair<double, double>>{{0, 100}, {200, 100}, {400, 100}}, true));
    auto dup = std::make_unique<DuplicateNodes>(
        branch, std::vector<std::pair<double, double>>{{0, 100}, {200, 100}, {400, 100}}, true);
    DuplicateNodes* made = dup.get();
    doc.execute(std::move(dup));
    EXPECT_EQ(doc.history().undoText(), "Duplicate the branch of Cluster #2 (3 nodes)");
    EXPECT_EQ(made->copies(), (std::vector<NodeId>{5, 6, 7}));
    const PipelineGraph& g = doc.graph();
    // Import #1 feeds both Cluster nodes; the copies are chained like the originals.
    EXPECT_EQ(g.branchOf(7), (std::vector<NodeId>{1, 5, 6, 7}));
    EXPECT_EQ(g.node(5).params, g.node(2).params);
    EXPECT_EQ(g.node(6).x, 200.0);
    // The copied Export writes its own folder: the original's, with the copy's id.
    EXPECT_EQ(paramText(g.node(7).params, "output"), "/out/pkg-7");
    EXPECT_EQ(g.nodesOf(NodeKind::Export), (std::vector<NodeId>{4, 7}));
}

TEST_F(Commands, MergeClusters) {
    expectUndoRedoExact(
        std::make_unique<MergeClusters>(cluster(), std::vector<InstanceSet>{{3, 4}, {5, 6}}));
}

TEST_F(Commands, SplitCluster) {
    tree(); // the split needs the current tree
    expectUndoRedoExact(std::make_unique<SplitCluster>(cluster(), InstanceSet{0, 1, 2}));
}

TEST_F(Commands, MoveToCluster) {
    expectUndoRedoExact(std::make_unique<MoveToCluster>(cluster(), std::vector<InstanceSet>{{2}},
                                                        InstanceSet{3, 4}));
}

TEST_F(Commands, LockAndUnlockCluster) {
    expectUndoRedoExact(std::make_unique<LockCluster>(cluster(), InstanceSet{3, 4}));
    doc.execute(std::make_unique<LockCluster>(cluster(), InstanceSet{3, 4}));
    expectUndoRedoExact(std::make_unique<UnlockCluster>(cluster(), InstanceSet{3, 4}));
}

TEST_F(Commands, ExcludeAndIncludeInstance) {
    expectUndoRedoExact(std::make_unique<ExcludeInstance>(cluster(), InstanceSet{1}));
    doc.execute(std::make_unique<ExcludeInstance>(cluster(), InstanceSet{1}));
    expectUndoRedoExact(std::make_unique<IncludeInstance>(cluster(), InstanceSet{1}));
}

TEST_F(Commands, ACommandThatDoesNotApplyLeavesNoTrace) {
    const nlohmann::json before = doc.toJson();
    EXPECT_THROW(doc.execute(std::make_unique<SetParameter>(cluster(), "k", 99.0)), Error);
    EXPECT_THROW(doc.execute(std::make_unique<UnlockCluster>(cluster(), InstanceSet{0})), Error);
    EXPECT_THROW(doc.execute(std::make_unique<SplitCluster>(cluster(), InstanceSet{0, 1, 2})),
                 Error); // not clustered yet: no tree to split
    tree();
    EXPECT_THROW(doc.execute(std::make_unique<ExcludeInstance>(cluster(), InstanceSet{7})),
                 Error); // the scene has instances 0..6
    EXPECT_EQ(doc.toJson(), before);
    EXPECT_EQ(doc.history().count(), 0u);
}

TEST_F(Commands, UndoRedoSequencesWalkTheHistory) {
    doc.execute(std::make_unique<SetParameter>(cluster(), "k", 1.0));
    doc.execute(std::make_unique<SetParameter>(cluster(), "max_children", 4));
    doc.execute(std::make_unique<LockCluster>(cluster(), InstanceSet{3, 4}));
    const nlohmann::json three = doc.toJson();
    EXPECT_EQ(doc.history().undoText(), "Lock cluster (Cluster #2)");
    doc.undo();
    doc.undo();
    EXPECT_EQ(paramNumber(doc.graph().node(cluster()).params, "k"), 1.0);
    EXPECT_EQ(paramInt(doc.graph().node(cluster()).params, "max_children"), 8);
    EXPECT_EQ(doc.history().redoText(), "Set Max children of Cluster #2");
    doc.redo();
    doc.redo();
    EXPECT_EQ(doc.toJson(), three);
    doc.redo(); // nothing left: no-op
    EXPECT_EQ(doc.history().index(), 3u);
    // A new command after an undo drops the redo tail.
    doc.undo();
    doc.execute(std::make_unique<ExcludeInstance>(cluster(), InstanceSet{0}));
    EXPECT_EQ(doc.history().count(), 3u);
    EXPECT_FALSE(doc.history().canRedo());
}

TEST_F(Commands, ASliderDragIsOneUndoStep) {
    const std::uint64_t drag = doc.history().newMergeId();
    for (double k : {0.5, 1.0, 1.5, 2.0})
        doc.execute(std::make_unique<SetParameter>(cluster(), "k", k, drag));
    EXPECT_EQ(doc.history().count(), 1u);
    EXPECT_EQ(paramNumber(doc.graph().node(cluster()).params, "k"), 2.0);
    doc.undo();
    EXPECT_EQ(paramNumber(doc.graph().node(cluster()).params, "k"), 0.0); // before the drag
    doc.redo();
    EXPECT_EQ(paramNumber(doc.graph().node(cluster()).params, "k"), 2.0);
    // Another drag, or another parameter with the same id, is a new step.
    doc.execute(std::make_unique<SetParameter>(cluster(), "k", 3.0, doc.history().newMergeId()));
    doc.execute(std::make_unique<SetParameter>(kDefaultBake, "screen_size", 100.0, drag));
    EXPECT_EQ(doc.history().count(), 3u);
}

TEST_F(Commands, DirtyFollowsTheSavedState) {
    EXPECT_FALSE(doc.isDirty());
    doc.execute(std::make_unique<SetParameter>(cluster(), "k", 1.0));
    EXPECT_TRUE(doc.isDirty());
    doc.markSaved();
    EXPECT_FALSE(doc.isDirty());
    doc.undo();
    EXPECT_TRUE(doc.isDirty());
    doc.redo();
    EXPECT_FALSE(doc.isDirty());
}

} // namespace
} // namespace hlod
