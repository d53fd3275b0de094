// Cluster tree JSON (pipeline/cluster/ClusterJson.h) and invariant checks
// (pipeline/cluster/ClusterValidate.h).
#include <gtest/gtest.h>

#include "HandScenes.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/ClusterJson.h"
#include "pipeline/cluster/ClusterValidate.h"

namespace hlod {
namespace {

ClusterTree threeCubes() {
    ClusterParams p;
    p.volume = VolumeType::Aabb;
    p.k = 2.0;
    return buildClusterTree(test::cubesAt({{0, 0, 0}, {1, 0, 0}, {50, 0, 0}}), p);
}

TEST(ClusterJson, WritesEveryNodeWithItsFields) {
    const ClusterTree t = threeCubes();
    const nlohmann::json j = clusterTreeToJson(t);
    EXPECT_EQ(j["volume"], "aabb");
    EXPECT_EQ(j["k"], 2.0);
    ASSERT_EQ(j["nodes"].size(), t.nodes.size());
    EXPECT_EQ(j["root"], t.root);
    const nlohmann::json& root = j["nodes"][t.root];
    EXPECT_TRUE(root["parent"].is_null());
    EXPECT_TRUE(root["instance"].is_null());
    EXPECT_EQ(root["children"].size(), t.nodes[t.root].children.size());
    const nlohmann::json& leaf = j["nodes"][2];
    EXPECT_EQ(leaf["instance"], 2);
    EXPECT_EQ(leaf["level"], 0);
    // Cube 2 spans [50, 51] x [0, 1] x [0, 1].
    EXPECT_EQ(leaf["box"]["min"], nlohmann::json({50.0, 0.0, 0.0}));
    EXPECT_EQ(leaf["box"]["max"], nlohmann::json({51.0, 1.0, 1.0}));
    EXPECT_EQ(leaf["fill"], 1.0);
    EXPECT_FALSE(leaf["locked"].get<bool>());
}

TEST(ClusterJson, StreamedTextIsTheBytesNlohmannDumpsAtAnyDepth) {
    // Round and non-round coordinates (1.0 is written "1.0", 3e-06 in exponent form), a locked
    // node, an empty tree: every case of the writer against nlohmann's own dump(2).
    ClusterParams p;
    ClusterTree odd = buildClusterTree(
        test::cubesAt({{0.1, -0.2, 3e-6}, {1.25, 0, 7}, {-50.5, 1e9, 0}, {2, 2, 2}}), p);
    odd.nodes[odd.root].locked = true;
    for (const ClusterTree& t : {threeCubes(), odd, ClusterTree{}}) {
        std::string alone;
        appendClusterTreeJson(alone, t);
        EXPECT_EQ(alone, clusterTreeToJson(t).dump(2));
        // Nested one level down, as `hlod cluster --json` writes it under "tree".
        const nlohmann::json outer = {{"tree", clusterTreeToJson(t)}};
        std::string nested = "{\n  \"tree\": ";
        appendClusterTreeJson(nested, t, 1);
        nested += "\n}";
        EXPECT_EQ(nested, outer.dump(2));
    }
}

TEST(ClusterJson, MetricsHaveNamedFields) {
    const nlohmann::json m = treeMetricsToJson(computeTreeMetrics(threeCubes()));
    EXPECT_EQ(m["leaves"], 3);
    EXPECT_EQ(m["nodes"], 5);
    EXPECT_TRUE(m.contains("meanSpread"));
}

TEST(ClusterValidate, AcceptsBuiltTreesAndNamesBrokenOnes) {
    ClusterTree t = threeCubes();
    EXPECT_EQ(validateClusterTree(t, 3), "");
    ClusterTree shrunk = t;
    shrunk.nodes[t.root].box.max.x = 10.0; // no longer holds cube 2
    EXPECT_NE(validateClusterTree(shrunk, 3).find("box does not contain"), std::string::npos);
    ClusterTree orphan = t;
    orphan.nodes[2].parent = kNoId;
    EXPECT_NE(validateClusterTree(orphan, 3), "");
    EXPECT_NE(validateClusterTree(t, 4).find("has no leaf"), std::string::npos);
    ClusterTree badLevel = t;
    badLevel.nodes[t.root].level = 7;
    EXPECT_NE(validateClusterTree(badLevel, 3).find("level"), std::string::npos);
}

} // namespace
} // namespace hlod
