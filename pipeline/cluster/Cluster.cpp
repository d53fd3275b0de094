// Entry point of clustering: picks the merging strategy and cost model for the volume type
// (contract in Cluster.h; the shared steps in ClusterDriver.h).
#include "pipeline/cluster/Cluster.h"

#include "pipeline/cluster/ClusterDriver.h"
#include "pipeline/cluster/LevelMerger.h"
#include "pipeline/cluster/OctreeClusterer.h"
#include "pipeline/cluster/OriginalHierarchyClusterer.h"

namespace hlod {

ClusterTree buildClusterTree(const Scene& scene, const ClusterParams& params,
                             const Progress& progress) {
    validateConstraints(params, scene.instances.size());
    switch (params.volume) {
    case VolumeType::Sphere:
        return buildConstrainedTree(scene, params, CostModel(VolumeType::Sphere, 0.0), mergeLevels,
                                    progress);
    case VolumeType::Aabb:
        return buildConstrainedTree(scene, params, CostModel(VolumeType::Aabb, params.k),
                                    mergeLevels, progress);
    case VolumeType::Octree:
        // The baselines have no cost of their own: their nodes are boxes, so fill and cost are
        // reported with the AABB model without the proportion term (k = 0).
        return buildConstrainedTree(scene, params, CostModel(VolumeType::Aabb, 0.0), mergeOctree,
                                    progress);
    case VolumeType::Original:
        return buildConstrainedTree(
            scene, params, CostModel(VolumeType::Aabb, 0.0),
            [&scene](TreeBuilder& b, std::vector<Id> units, int maxChildren, const Progress& p) {
                return mergeOriginalHierarchy(scene, b, std::move(units), maxChildren, p);
            },
            progress);
    }
    return {};
}

} // namespace hlod
