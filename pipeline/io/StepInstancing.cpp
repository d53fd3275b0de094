// STEP (ISO 10303-21 clear text encoding) NEXT_ASSEMBLY_USAGE_OCCURRENCE scan; see
// StepInstancing.h. Entity syntax: #id=NEXT_ASSEMBLY_USAGE_OCCURRENCE('id','name','description',
// #relating,#related,$); strings are quoted with ' and double it to escape it.
#include "pipeline/io/StepInstancing.h"

#include <cctype>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/io/InstancingGraph.h"

namespace hlod {

namespace {

constexpr std::string_view kNauo = "NEXT_ASSEMBLY_USAGE_OCCURRENCE";

// The top-level arguments of the parameter list opening at text[p] == '(' (strings skipped,
// nested lists kept as text), or empty when it is malformed.
std::vector<std::string> arguments(const std::string& text, std::size_t p) {
    std::vector<std::string> args(1);
    int depth = 0;
    for (; p < text.size(); ++p) {
        const char c = text[p];
        if (c == '\'') {
            // A string: up to the next quote that is not doubled.
            for (++p; p < text.size(); ++p) {
                if (text[p] == '\'' && (p + 1 >= text.size() || text[p + 1] != '\'')) break;
                if (text[p] == '\'') ++p;
            }
            args.back() += "''";
        } else if (c == '(') {
            if (depth++ > 0) args.back() += c;
        } else if (c == ')') {
            if (--depth == 0) return args;
            args.back() += c;
        } else if (c == ',' && depth == 1) {
            args.emplace_back();
        } else if (!std::isspace(static_cast<unsigned char>(c))) {
            args.back() += c;
        }
    }
    return {};
}

} // namespace

void checkStepInstancing(const std::filesystem::path& file, const ImportLimits& limits) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return; // the reader reports it
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    InstancingGraph graph;
    std::map<std::string, std::size_t> vertexOf; // "#12" -> vertex
    std::vector<char> placed;                    // some assembly places it
    const auto vertex = [&](const std::string& ref) {
        auto [it, added] = vertexOf.emplace(ref, graph.vertices.size());
        if (added) {
            graph.vertices.emplace_back();
            placed.push_back(0);
        }
        return it->second;
    };
    for (std::size_t at = text.find(kNauo); at != std::string::npos;
         at = text.find(kNauo, at + kNauo.size())) {
        std::size_t p = at + kNauo.size();
        while (p < text.size() && std::isspace(static_cast<unsigned char>(text[p])))
            ++p;
        if (p >= text.size() || text[p] != '(') continue;
        const std::vector<std::string> args = arguments(text, p);
        if (args.size() < 5 || args[3].empty() || args[4].empty() || args[3][0] != '#' ||
            args[4][0] != '#')
            continue;
        const std::size_t assembly = vertex(args[3]), part = vertex(args[4]);
        graph.vertices[assembly].places.push_back(part);
        placed[part] = 1;
    }
    if (graph.vertices.empty()) return;
    std::vector<std::size_t> roots;
    for (std::size_t v = 0; v < graph.vertices.size(); ++v) {
        if (graph.vertices[v].places.empty()) graph.vertices[v].own = 1; // a part
        if (!placed[v]) roots.push_back(v);
    }
    std::vector<std::string> names(graph.vertices.size());
    for (const auto& [ref, v] : vertexOf)
        names[v] = ref;
    const std::vector<std::uint64_t> expanded = expandInstancing(
        graph, roots, file, [&](std::size_t v) { return "product definition " + names[v]; });
    std::uint64_t parts = 0;
    for (std::size_t r : roots)
        parts = saturatingAdd(parts, expanded[r]);
    if (roots.empty()) {
        // Every product is placed by another: the graph is one big cycle; find it.
        for (std::size_t v = 0; v < graph.vertices.size(); ++v)
            (void)expandInstancing(graph, {v}, file,
                                   [&](std::size_t w) { return "product definition " + names[w]; });
    }
    if (parts > limits.maxInstances) {
        throwOverLimit(file,
                       "its assemblies place " + std::to_string(parts) +
                           " parts once every reused sub-assembly is expanded",
                       limits.maxInstances, "--max-instances");
    }
}

} // namespace hlod
