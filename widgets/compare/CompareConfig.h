// One side of the comparison view (issue #7 "side-by-side comparison", issue 29): either a Bake
// node of the document (any branch of its graph), or a quick configuration: the few parameters a
// technical artist varies when comparing clusterings (the thesis compares sphere against AABB
// with k = 0, 1, 2 in its tables 6.2-6.6) laid over a base branch of the document, which the
// comparison builds as a temporary branch (a copy of the base's Cluster and Bake nodes with these
// values, in a copy of the graph; the document is not changed).
//
// A CompareConfig holds the clustering volume, the AABB proportion exponent k and the screen
// size S; everything else (proxy method, pixel error, max children, hand edits, proxy cache)
// comes from the base branch, so both sides differ only in what the user chose.
// Text form (command line `--compare LEFT:RIGHT`): "#6" is Bake node 6 of the document;
// "sphere", "octree", "original", "aabb" (k of the base), "aabb-k2" / "aabb-k0.5"; "current" is
// the base's own values; any configuration may end in "@S" to set the screen size in pixels
// ("aabb-k2@400"). Nothing here throws: parsing returns false with a message naming what is
// wrong.
#pragma once

#include <utility>

#include <QString>

#include "pipeline/graph/PipelineGraph.h"

namespace hlod::widgets {

struct CompareConfig {
    VolumeType volume = VolumeType::Sphere;
    double k = 1.0;            // used by AABB only
    double screenSize = 300.0; // S, pixels
    bool operator==(const CompareConfig&) const = default;
};

struct CompareSide {
    NodeId bake = kNoNode; // a Bake node of the document; kNoNode: `config` over the base branch
    CompareConfig config;  // of the quick configuration (shown for a Bake node too)
    bool operator==(const CompareSide&) const = default;
};

// The configuration of the branch of Bake node `bake` (its Cluster node's volume and k, its S);
// the declared defaults for what the branch lacks.
CompareConfig configOf(const PipelineGraph& graph, NodeId bake);
// Gives the Cluster node `cluster` and the Bake node `bake` the values of `config` (k is set for
// every volume, so a sphere side does not change when the base's k does; only AABB uses it).
void applyConfig(PipelineGraph& graph, NodeId cluster, NodeId bake, const CompareConfig& config);
// "Sphere", "AABB k=2", "Octree", "Original hierarchy", followed by ", S = 400 px" when
// `withScreenSize`.
QString configLabel(const CompareConfig& config, bool withScreenSize = false);
// The text form (see above) of `config`, always with its screen size.
QString configSpec(const CompareConfig& config);

// Parses the text form over `base` (the base branch's configuration); false with `error` set
// when `text` is not one. A "#N" side is not checked against a graph here.
bool parseSide(const QString& text, const CompareConfig& base, CompareSide& out,
               QString* error = nullptr);
// "LEFT:RIGHT".
bool parseSidePair(const QString& text, const CompareConfig& base,
                   std::pair<CompareSide, CompareSide>& out, QString* error = nullptr);

// What the view opens with: left = the shown Bake node `shown`; right = the first other Bake
// node of `bakes` when there is one, else AABB k=2 over the shown branch (sphere when it already
// uses AABB), at its screen size.
std::pair<CompareSide, CompareSide> defaultSides(const PipelineGraph& graph, NodeId shown,
                                                 const std::vector<NodeId>& bakes);

} // namespace hlod::widgets
