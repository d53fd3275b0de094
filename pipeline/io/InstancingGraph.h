// What an instancing graph expands to (issue 22): COLLADA nodes placing nodes, STEP assemblies
// placing products. Readers copy every placement, so a thing placed twice at each of 30 levels
// becomes 2^30 copies; counted here instead, with each vertex visited once (post-order, an
// explicit stack: chains may be thousands deep) and saturating sums.
// Failure: a vertex that places itself (directly or further down) throws Error(Malformed)
// naming `file` and the vertex (`name(i)`); readers would follow such a cycle until their
// stack or memory ends.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace hlod {

struct InstancingGraph {
    struct Vertex {
        std::uint64_t own = 0;           // what the vertex counts by itself
        std::vector<std::size_t> places; // one entry per placement (repeats allowed)
    };
    std::vector<Vertex> vertices;
};

// expanded[i] = own[i] + the sum of expanded[j] over the placements j of i (saturating at
// UINT64_MAX), for every vertex reachable from `roots`; 0 for the others.
std::vector<std::uint64_t> expandInstancing(const InstancingGraph& graph,
                                            const std::vector<std::size_t>& roots,
                                            const std::filesystem::path& file,
                                            const std::function<std::string(std::size_t)>& name);

std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b);

} // namespace hlod
