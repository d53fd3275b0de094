// A document over the seven cubes of CubeFiles.h, clustered with AABB and k = 0 (tree: ABC,
// DE, FG, {ABC, DE}, root) and baked into a private cache folder, shared by the document tests.
#pragma once

#include <gtest/gtest.h>

#include "TestUtil.h"
#include "doc/CubeFiles.h"
#include "pipeline/doc/Document.h"

namespace hlod::test {

class DocumentFixture : public ::testing::Test {
protected:
    DocumentFixture() : doc(makeSources()) {
        PipelineGraph& g = doc.graph();
        g.setParam(kDefaultCluster, "volume", std::string("aabb"));
        g.setParam(kDefaultCluster, "k", 0.0);
        // The thesis' merges and every proxy kept: the trees the tests describe (level growth
        // and the proxy economy have tests of their own).
        g.setParam(kDefaultCluster, "level_growth", 1.0);
        g.setParam(kDefaultBake, "proxy_ratio", 1.0);
        g.setParam(kDefaultBake, "cache_dir", (tmp / "cache").string());
        g.setParam(kDefaultBake, "threads", 2);
    }

    std::vector<std::filesystem::path> makeSources() {
        std::filesystem::create_directories(tmp / "scene");
        return writeSevenCubes(tmp / "scene");
    }

    // Runs up to the Bake node and returns its result.
    const BakeResult& bake() {
        doc.graph().run({kDefaultBake});
        return *doc.graph().output(kDefaultBake)->bake;
    }
    const ClusterTree& tree() {
        doc.graph().run({kDefaultCluster});
        return *doc.currentTree(kDefaultCluster);
    }

    TempDir tmp;
    Document doc;
};

} // namespace hlod::test
