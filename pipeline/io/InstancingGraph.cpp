// Post-order expansion count over an instancing DAG; see InstancingGraph.h.
#include "pipeline/io/InstancingGraph.h"

#include <utility>

#include "pipeline/core/Error.h"

namespace hlod {

std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b) {
    return a > UINT64_MAX - b ? UINT64_MAX : a + b;
}

std::vector<std::uint64_t> expandInstancing(const InstancingGraph& graph,
                                            const std::vector<std::size_t>& roots,
                                            const std::filesystem::path& file,
                                            const std::function<std::string(std::size_t)>& name) {
    const std::size_t n = graph.vertices.size();
    std::vector<std::uint64_t> expanded(n, 0);
    std::vector<char> state(n, 0);                          // 0 new, 1 on the stack, 2 done
    std::vector<std::pair<std::size_t, std::size_t>> stack; // (vertex, next placement)
    for (std::size_t root : roots) {
        if (root >= n || state[root] != 0) continue;
        state[root] = 1;
        stack.push_back({root, 0});
        while (!stack.empty()) {
            const std::size_t v = stack.back().first;
            const std::vector<std::size_t>& places = graph.vertices[v].places;
            if (stack.back().second < places.size()) {
                const std::size_t w = places[stack.back().second++];
                if (w >= n) continue;
                if (state[w] == 1) {
                    throw Error(ErrorCode::Malformed, file,
                                name(w) + " places itself (an instancing cycle)");
                }
                if (state[w] == 0) {
                    state[w] = 1;
                    stack.push_back({w, 0});
                }
                continue;
            }
            std::uint64_t total = graph.vertices[v].own;
            for (std::size_t w : places) {
                if (w < n) total = saturatingAdd(total, expanded[w]);
            }
            expanded[v] = total;
            state[v] = 2;
            stack.pop_back();
        }
    }
    return expanded;
}

} // namespace hlod
