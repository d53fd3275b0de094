// `hlod`: the headless HLOD Studio. See README.md (CLI usage) and DESIGN.md (CLI contract).
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "Commands.h"
#include "pipeline/core/Error.h"

namespace {

using hlod::cli::CommandEntry;

const CommandEntry kCommands[] = {
    {"info", hlod::cli::runInfo,
     "hlod info [SCENE|DIR|PACKAGE...] [--json] [--deflection R] [--brep-unit M]"},
    {"cluster", hlod::cli::runCluster,
     "hlod cluster SCENE [--volume sphere|aabb|octree|original] [--k K] [--max-children N] "
     "[--json]"},
    {"build", hlod::cli::runBuild,
     "hlod build SCENE|PROJECT.hlodproj -o DIR [--volume sphere|aabb|octree|original] [--k K] "
     "[--max-children N] [--proxy decimate|remesh|sloppy] [--screen-size PX] [--pixel-error PX] "
     "[--fov DEG] [--viewport-height PX] [--threads N] [--cache DIR] [--no-cache] [--no-dlod] "
     "[--geo LAT,LON,H] [--deflection R] [--brep-unit M] [--json]"},
    {"bench", hlod::cli::runBench,
     "hlod bench SCENE --out DIR [--frames N] [--size WxH] [--configs LIST] [--screen-size PX] "
     "[--path FILE.json] [--threads N] [--shading geometry|colour] [--no-cache] "
     "[--deflection R] [--brep-unit M]"},
};

void printUsage(std::FILE* out) {
    std::fprintf(out, "HLOD Studio command-line tool %s\n\nUsage:\n", HLOD_VERSION);
    for (const CommandEntry& c : kCommands)
        std::fprintf(out, "  %s\n", c.usage);
    std::fprintf(out, "  hlod --version\n\nWith no SCENE, the embedded sample scene is used.\n");
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        printUsage(args.empty() ? stderr : stdout);
        return args.empty() ? 2 : 0;
    }
    if (args[0] == "--version") {
        std::printf("hlod %s\n", HLOD_VERSION);
        return 0;
    }
    for (const CommandEntry& c : kCommands) {
        if (args[0] != c.name) continue;
        try {
            return c.run(std::vector<std::string>(args.begin() + 1, args.end()));
        } catch (const hlod::Error& e) {
            std::fprintf(stderr, "hlod %s: error: %s\n", c.name, e.what());
            return e.code() == hlod::ErrorCode::InvalidArgument ? 2 : 1;
        } catch (const std::bad_alloc&) {
            std::fprintf(stderr, "hlod %s: error: out of memory\n", c.name);
            return 1;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "hlod %s: error: %s\n", c.name, e.what());
            return 1;
        }
    }
    std::fprintf(stderr, "hlod: error: unknown command '%s' (try hlod --help)\n", args[0].c_str());
    return 2;
}
