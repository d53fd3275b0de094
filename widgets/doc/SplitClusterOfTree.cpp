// Split of a cluster of the editor's current tree (see SplitClusterOfTree.h).
#include "widgets/doc/SplitClusterOfTree.h"

#include <nlohmann/json.hpp>

#include "pipeline/graph/ClusterEdits.h"

namespace hlod::widgets {

SplitClusterOfTree::SplitClusterOfTree(NodeId clusterNode, InstanceSet cluster,
                                       const ClusterTree& tree)
    : HandEditCommand(clusterNode), cluster_(normalizedSet(std::move(cluster))),
      tree_(std::make_shared<const ClusterTree>(tree)) {}

void SplitClusterOfTree::apply(Document& doc) {
    HandEditCommand::apply(doc);
    tree_.reset(); // the edit is computed: a redo repeats it without the tree
}

HandEdits SplitClusterOfTree::edit(const HandEdits& current, const Document&) const {
    return splitCluster(current, *tree_, cluster_);
}

nlohmann::json SplitClusterOfTree::arguments() const { return {{"cluster", cluster_}}; }

} // namespace hlod::widgets
