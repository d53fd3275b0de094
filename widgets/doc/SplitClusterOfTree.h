// The "split cluster" hand edit for the editor. The document's SplitCluster command reads the
// children of the cluster from the tree the Cluster node computed last (Document::currentTree);
// the editor shows the tree of a Bake node instead (after the proxy economy, which dissolves
// clusters whose proxy does not pay), so this command is given the tree the user sees: the shown
// build's. Everything else is SplitCluster's: the same edit (splitCluster in ClusterEdits.h:
// the cluster is dissolved, its children hang from its parent; a lock moves to its inner
// children), the same text and JSON, undo restores the previous hand edits exactly.
// Failure: apply() throws InvalidArgument (the root, a leaf, an unknown cluster) and changes
// nothing. The tree is copied (node ids and leaf sets only matter for the first apply) and
// released after it.
#pragma once

#include <memory>

#include "pipeline/doc/Commands.h"

namespace hlod::widgets {

class SplitClusterOfTree : public InstanceSetEdit {
public:
    SplitClusterOfTree(NodeId clusterNode, InstanceSet cluster, const ClusterTree& tree);
    std::string what() const override { return "Split cluster"; }
    void apply(Document& doc) override;

protected:
    HandEdits edit(const HandEdits& current, const Document& doc) const override;

private:
    std::shared_ptr<const ClusterTree> tree_;
};

} // namespace hlod::widgets
