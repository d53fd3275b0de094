// Every clusterer on every shared test scene (../shared/data/scenes): the tree is valid, has one
// leaf per instance, and the level merger's rule shape holds. Each scene is imported once.
#include <filesystem>
#include <map>

#include <gtest/gtest.h>

#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/ClusterValidate.h"
#include "pipeline/cluster/TreeMetrics.h"
#include "pipeline/io/Import.h"

namespace hlod {
namespace {

const Scene& sharedScene(const std::string& name) {
    static std::map<std::string, Scene> cache;
    auto it = cache.find(name);
    if (it == cache.end()) {
        const auto dir = std::filesystem::path(HLOD_TEST_DATA_DIR) / "scenes" / name;
        it = cache.emplace(name, importScene({dir})).first;
    }
    return it->second;
}

class RealSceneClusters : public ::testing::TestWithParam<std::string> {};

TEST_P(RealSceneClusters, EveryVolumeTypeBuildsAValidTree) {
    const auto dir = std::filesystem::path(HLOD_TEST_DATA_DIR) / "scenes" / GetParam();
    if (!std::filesystem::exists(dir)) GTEST_SKIP() << dir << " not present";
    const Scene& scene = sharedScene(GetParam());
    ASSERT_GT(scene.instances.size(), 0u);
    for (VolumeType v :
         {VolumeType::Sphere, VolumeType::Aabb, VolumeType::Octree, VolumeType::Original}) {
        ClusterParams p;
        p.volume = v;
        const ClusterTree t = buildClusterTree(scene, p);
        EXPECT_EQ(validateClusterTree(t, scene.instances.size()), "") << toString(v);
        EXPECT_EQ(t.leafCount(), scene.instances.size()) << toString(v);
        const TreeMetrics m = computeTreeMetrics(t);
        if (v == VolumeType::Sphere || v == VolumeType::Aabb) {
            // Level merging: 2..maxChildren children everywhere.
            EXPECT_GE(m.minChildren, 2u) << toString(v);
            EXPECT_LE(m.maxChildren, 8u) << toString(v);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(SharedScenes, RealSceneClusters,
                         ::testing::Values("as1-assembly", "cg57-cruiser", "engine-2cylinder",
                                           "godot-room", "occt-kitchen", "torcs-spring"),
                         [](const auto& testInfo) {
                             std::string n = testInfo.param;
                             for (char& c : n) {
                                 if (c == '-') c = '_';
                             }
                             return n;
                         });

} // namespace
} // namespace hlod
