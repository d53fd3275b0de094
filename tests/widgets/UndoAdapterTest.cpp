// widgets/doc/UndoAdapter: the QUndoStack mirrors the document's history one to one, merged
// commands stay one entry, and a command that does not apply is reported, not pushed.
#include <gtest/gtest.h>

#include <QSignalSpy>

#include "pipeline/doc/Commands.h"
#include "widgets/doc/UndoAdapter.h"

namespace hlod::widgets {
namespace {

double kOf(const Document& doc) {
    return paramNumber(doc.graph().node(kDefaultCluster).params, "k");
}

TEST(UndoAdapter, QtUndoAndRedoDriveTheDocument) {
    Document doc;
    UndoAdapter undo(doc);
    QSignalSpy changed(&undo, &UndoAdapter::documentChanged);
    ASSERT_TRUE(undo.execute(std::make_unique<SetParameter>(kDefaultCluster, "k", 2.0)));
    ASSERT_TRUE(undo.execute(std::make_unique<LockCluster>(kDefaultCluster, InstanceSet{0, 1})));
    EXPECT_EQ(undo.stack()->count(), 2);
    EXPECT_EQ(undo.stack()->undoText(), QStringLiteral("Lock cluster (Cluster #2)"));
    undo.stack()->undo();
    undo.stack()->undo();
    EXPECT_EQ(kOf(doc), 1.0); // the default
    EXPECT_EQ(doc.history().index(), 0u);
    undo.stack()->redo();
    EXPECT_EQ(kOf(doc), 2.0);
    EXPECT_EQ(doc.history().index(), 1u);
    EXPECT_EQ(changed.count(), 5); // 2 executes, 2 undos, 1 redo
}

TEST(UndoAdapter, AMergedDragIsOneEntryAndFailuresAreReported) {
    Document doc;
    UndoAdapter undo(doc);
    const std::uint64_t drag = doc.history().newMergeId();
    for (double k : {0.5, 1.5, 2.5})
        undo.execute(std::make_unique<SetParameter>(kDefaultCluster, "k", k, drag));
    EXPECT_EQ(undo.stack()->count(), 1);
    EXPECT_EQ(doc.history().count(), 1u);
    QSignalSpy failed(&undo, &UndoAdapter::commandFailed);
    EXPECT_FALSE(undo.execute(std::make_unique<SetParameter>(kDefaultCluster, "k", 99.0)));
    ASSERT_EQ(failed.count(), 1);
    EXPECT_EQ(failed.at(0).at(0).toString(), QStringLiteral("k must be within [0, 16], got 99"));
    EXPECT_EQ(undo.stack()->count(), 1);
    undo.setClean();
    EXPECT_TRUE(undo.stack()->isClean());
    EXPECT_FALSE(doc.isDirty());
}

} // namespace
} // namespace hlod::widgets
