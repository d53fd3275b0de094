// Split of a cluster of the editor's current tree (see SplitClusterOfTree.h).
#include "widgets/doc/SplitClusterOfTree.h"

#include "pipeline/graph/ClusterEdits.h"

namespace hlod::widgets {

SplitClusterOfTree::SplitClusterOfTree(NodeId clusterNode, InstanceSet cluster,
                                       const ClusterTree& tree)
    : InstanceSetEdit(clusterNode, std::move(cluster), "cluster"),
      tree_(std::make_shared<const ClusterTree>(tree)) {}

void SplitClusterOfTree::apply(Document& doc) {
    HandEditCommand::apply(doc);
    tree_.reset(); // the edit is computed: a redo repeats it without the tree
}

HandEdits SplitClusterOfTree::edit(const HandEdits& current, const Document&) const {
    return splitCluster(current, *tree_, set_);
}

} // namespace hlod::widgets
