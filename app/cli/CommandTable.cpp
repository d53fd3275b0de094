// The subcommands of `hlod` and what each accepts (see CommandSpec.h). A command's pipeline
// parameters come from their declarations (pipeline/graph/Parameters.cpp): a parameter added
// there is a flag of every command that takes its node kind, with its help, default and range.
#include <algorithm>

#include "Commands.h"
#include "pipeline/core/Error.h"

namespace hlod::cli {

namespace {

const OptionSpec kJson{"--json", "", "", "Print machine-readable JSON on stdout instead of text.",
                       ""};
const OptionSpec kExport{"--export", "", "ID|NAME",
                         "The Export node of a project to run, by id (7 or #7) or by the name "
                         "given in the editor; without it every Export node runs.",
                         ""};

std::vector<CommandSpec> makeCommands() {
    using N = NodeKind;
    const std::pair<std::string, std::string> scene{
        "SCENE...", "Scene files or folders, read as one scene (each file under its own node); "
                    "none: the embedded sample scene."};
    std::vector<CommandSpec> v;
    v.push_back({"info",
                 runInfo,
                 {"hlod info [SCENE|DIR|PACKAGE...] [options]"},
                 "Counts of a scene: nodes, unique meshes, instances, draw calls, triangles, "
                 "vertices, materials, depth, bounds in metres and the file size, a note for "
                 "each CAD face the tessellation budget coarsened, and the import limits it "
                 "loaded under (--max-* options). Given an exported package "
                 "folder, reads it back (tree, proxy triangles, originals).",
                 {scene, {"PACKAGE", "A folder written by hlod build (tileset.json, hlod.json)."}},
                 {N::Import},
                 {{"--json", "", "",
                   "Print JSON on stdout, with every mesh instance (node name, path, mesh, "
                   "material).",
                   ""}}});
    v.push_back({"cluster",
                 runCluster,
                 {"hlod cluster [SCENE...] [options]"},
                 "Builds the HLOD cluster tree (bounding spheres after Sappa & Garcia, AABBs with "
                 "the proportion constraint k, a loose octree, or the original hierarchy) and "
                 "prints it with its quality metrics.",
                 {scene},
                 {N::Import, N::Cluster},
                 {{"--json", "", "",
                   "Print JSON on stdout: every node (parent, children, instance, bounds, fill, "
                   "cost, level).",
                   ""}}});
    v.push_back({"build",
                 runBuild,
                 {"hlod build [SCENE...] -o DIR [options]",
                  "hlod build PROJECT.hlodproj [-o DIR] [options]"},
                 "Clusters the scene, bakes a proxy for every inner node (in parallel, cached on "
                 "disk by content hash) and writes the 3D Tiles package to DIR, then prints the "
                 "thesis-style table (triangles, vertices, meshes, size) for the original, the "
                 "DLOD chain and the HLOD. A project saved by the editor builds as saved, hand "
                 "edits included, every branch (each Export node) into its own output folder "
                 "(relative to the project), with one table per branch; -o sets the folder when "
                 "one Export runs. Flags given here override the project's values.",
                 {scene,
                  {"PROJECT.hlodproj", "A project saved by HLOD Studio (its scene, parameters "
                                       "and hand edits)."}},
                 {N::Import, N::Cluster, N::Bake, N::Export},
                 {{"--shard", "", "I/N",
                   "Distributed bake: bake only shard I (0 to N-1) of the plan hlod plan wrote "
                   "into --cache DIR, then exit; auto/N takes I from SLURM_ARRAY_TASK_ID, "
                   "JOB_COMPLETION_INDEX or AWS_BATCH_JOB_ARRAY_INDEX. The scene and parameters "
                   "come from the plan (only --cache and --threads go with it). A build without "
                   "--shard whose --cache holds its plan is the final step: it checks every "
                   "shard has finished, bakes the nodes above the cut and writes the package.",
                   ""},
                  kExport,
                  kJson}});
    v.push_back({"plan",
                 runPlan,
                 {"hlod plan [SCENE...] --shards N --cache DIR [options]",
                  "hlod plan PROJECT.hlodproj --shards N --cache DIR [options]"},
                 "First step of a distributed bake: imports and clusters the scene once, cuts "
                 "the tree into N shards of balanced estimated bake cost (input triangles) and "
                 "writes the plan into the shared cache folder DIR: the tree, each shard's slice "
                 "of the scene (only its meshes) and the bake parameters. Then run hlod build "
                 "--shard I/N --cache DIR for every I (a Slurm job array: scripts/slurm/), and "
                 "finally hlod build SCENE -o PKG --cache DIR with the same flags as the plan: "
                 "the package is byte-identical to a single machine's.",
                 {scene,
                  {"PROJECT.hlodproj", "A project saved by HLOD Studio (its scene, parameters "
                                       "and hand edits)."}},
                 {N::Import, N::Cluster, N::Bake},
                 {{"--shards", "", "N", "Number of shards (1 to 100000).", ""},
                  {"--compression", "", "meshopt|none",
                   "Compression of the tiles the shards write for the final build (give the final "
                   "build the same).",
                   "meshopt"},
                  kExport,
                  kJson}});
    v.push_back(
        {"bench",
         runBench,
         {"hlod bench [SCENE...] --out DIR [options]"},
         "Renders a deterministic camera path offscreen for each configuration (original, DLOD "
         "chain, HLOD sphere, AABB k=0/1/2, octree) and writes summary.json, frames.csv, "
         "tables.md, plots and side-by-side frames. Needs an X display (xvfb-run -a).",
         {scene},
         {N::Import},
         {{"--out", "-o", "DIR", "Folder for the results.", ""},
          {"--frames", "", "N", "Frames along the camera path (2 to 100000).", "300"},
          {"--size", "", "WxH", "Frame size in pixels (64x64 to 8192x8192).", "640x360"},
          {"--configs", "", "LIST",
           "Comma-separated configurations: original, dlod, sphere, aabb0, aabb1, aabb2, "
           "octree, or all.",
           "all"},
          {"--path", "", "FILE.json", "Camera path to fly instead of the generated one.", ""},
          {"--shading", "", "geometry|colour|textured",
           "geometry: grey, lit; colour: the materials' base colours; textured: base colour "
           "factor x texture x vertex colour, cut-outs honoured.",
           "geometry"},
          {"--draw", "", "package|nodes",
           "How HLOD is drawn: package: the exported tiles as a 3D Tiles runtime draws them (a "
           "leaf group's meshes merged per look, one draw each); nodes: one draw per selected "
           "node or leaf mesh (the thesis' count).",
           "package"},
          {"--frame-images", "", "",
           "Also write every frame of every configuration as frames/NNNNN-KEY.png and its "
           "camera as frames/NNNNN-camera.json.",
           ""}},
         {"level_growth", "screen_size", "proxy_ratio", "proxy_textures", "threads", "cache",
          "cache_dir"}});
    return v;
}

} // namespace

const std::vector<CommandSpec>& commands() {
    static const std::vector<CommandSpec> all = makeCommands();
    return all;
}

const CommandSpec* findCommand(const std::string& name) {
    const auto& all = commands();
    const auto it =
        std::find_if(all.begin(), all.end(), [&](const CommandSpec& c) { return c.name == name; });
    return it == all.end() ? nullptr : &*it;
}

const CommandSpec& command(const std::string& name) {
    if (const CommandSpec* c = findCommand(name)) return *c;
    throw Error(ErrorCode::InvalidArgument, "unknown command '" + name + "'");
}

} // namespace hlod::cli
