#include "BenchRun.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <map>
#include <memory>
#include <tuple>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "../ProgressBar.h"
#include "pipeline/core/Error.h"
#include "pipeline/doc/HlodBuild.h"
#include "pipeline/eval/BenchReport.h"
#include "pipeline/eval/ImageError.h"
#include "pipeline/eval/Plot.h"
#include "pipeline/export/PackageLayout.h"
#include "pipeline/proxy/BakeStats.h"
#include "pipeline/proxy/DlodChain.h"
#include "pipeline/proxy/ProxyEconomy.h"
#include "pipeline/scene/AppendPlaced.h"
#include "pipeline/select/CameraPath.h"
#include "pipeline/select/LodSelection.h"

namespace hlod::cli {

namespace {

enum class Kind { Original, Dlod, Hlod };

struct Config {
    std::string key;
    std::string name;
    Kind kind = Kind::Original;
    int layer = -1;
    // HLOD
    std::unique_ptr<HlodBuild> build;
    std::unique_ptr<SelectionTree> selection;
    std::unique_ptr<FrontCache> cache;
    std::vector<int> nodeDrawable; // per tree node, -1 when it draws nothing
    // HLOD drawn as its package (HlodDraw::Package): the tiles, and per content what it draws.
    struct ContentDraw {
        std::vector<int> drawables;
        std::uint64_t triangles = 0;
    };
    std::unique_ptr<PackageLayout> layout;
    std::vector<ContentDraw> contentDraws; // parallel to layout->contents
    std::deque<Mesh> mergedMeshes; // leaf groups' merged primitives (renderer keys by address)
    // Original / DLOD: per instance, per level (Original: level 0 only)
    std::vector<std::vector<int>> instanceDrawables;
};

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

ClusterParams clusterParamsFor(const std::string& key) {
    ClusterParams p;
    if (key == "sphere") {
        p.volume = VolumeType::Sphere;
    } else if (key == "octree") {
        p.volume = VolumeType::Octree;
    } else {
        p.volume = VolumeType::Aabb;
        p.k = static_cast<double>(key.back() - '0');
    }
    return p;
}

std::string formatCount(double v) {
    char buf[32];
    if (v >= 1e6)
        std::snprintf(buf, sizeof(buf), "%.2fM", v / 1e6);
    else if (v >= 1e3)
        std::snprintf(buf, sizeof(buf), "%.1fK", v / 1e3);
    else
        std::snprintf(buf, sizeof(buf), "%.0f", v);
    return buf;
}

// Per-frame look of merged leaves: one merged primitive per look, as the package merges them
// (TileContent.h: base colour, texture, alpha, and which vertex streams the leaves carry).
using MergeKey = std::tuple<float, float, float, float, float, float, float, float,
                            const RgbaImage*, int, float, bool, bool, bool>;

MergeKey mergeKeyOf(const glm::vec4& color, const SurfaceLook& look, const Mesh& mesh) {
    return {color.r,           color.g,
            color.b,           color.a,
            look.factor.r,     look.factor.g,
            look.factor.b,     look.factor.a,
            look.texture,      static_cast<int>(look.alphaMode),
            look.alphaCutoff,  !mesh.normals.empty(),
            !mesh.uvs.empty(), !mesh.colors.empty()};
}

// The package's contents as drawables: a proxy draws its node's proxy; a leaf group draws its
// instanced leaves one by one and its other leaves merged per look (one drawable each).
void addPackageDrawables(Config& c, const Scene& scene, OffscreenRenderer& renderer,
                         const std::vector<glm::vec4>& instColor,
                         const std::vector<SurfaceLook>& instLook) {
    c.layout = std::make_unique<PackageLayout>(planPackage(scene, c.build->tree, c.build->bake));
    c.contentDraws.resize(c.layout->contents.size());
    for (std::size_t k = 0; k < c.layout->contents.size(); ++k) {
        const ContentPlan& plan = c.layout->contents[k];
        Config::ContentDraw& draw = c.contentDraws[k];
        if (plan.proxy) {
            if (c.nodeDrawable[plan.node] >= 0) {
                draw.drawables.push_back(c.nodeDrawable[plan.node]);
                draw.triangles = c.build->bake.nodes[plan.node].proxy.triangleCount();
            }
            continue;
        }
        std::map<MergeKey, Mesh*> merged;
        std::vector<std::pair<Mesh*, Id>> mergedOrder; // first member's instance, for its look
        for (const LeafSlot& slot : plan.leaves) {
            const Id i = slot.instance;
            const Mesh& mesh = scene.meshes[scene.instances[i].mesh];
            if (mesh.triangleCount() == 0) continue;
            draw.triangles += mesh.triangleCount();
            if (!slot.merged) {
                draw.drawables.push_back(renderer.addMesh(c.layer, mesh, scene.instanceTransform(i),
                                                          instColor[i], instLook[i]));
                continue;
            }
            auto [it, added] = merged.try_emplace(mergeKeyOf(instColor[i], instLook[i], mesh));
            if (added) {
                Mesh& m = c.mergedMeshes.emplace_back();
                m.name = "merged";
                m.material = mesh.material;
                it->second = &m;
                mergedOrder.emplace_back(&m, i);
            }
            appendPlaced(*it->second, mesh, scene.instanceTransform(i));
        }
        for (const auto& [m, i] : mergedOrder)
            draw.drawables.push_back(
                renderer.addMesh(c.layer, *m, glm::dmat4(1.0), instColor[i], instLook[i]));
    }
}

// The package's tiles a 3D Tiles runtime draws for `camera` (REPLACE refinement): a tile whose
// bounding box misses the frustum is skipped with everything below it; a node's tile is
// refined where Algorithm 5 refines the node (its geometric error is set for that, Package.h);
// a leaf-group tile is drawn whenever it is reached.
void selectPackage(const Config& c, const NodeClassifier& cls, const Frustum& frustum,
                   std::vector<int>& draw, FrameRecord& r) {
    const PackageLayout& layout = *c.layout;
    if (layout.tiles.empty()) return;
    std::vector<int> stack{0};
    while (!stack.empty()) {
        const TilePlan& tile = layout.tiles[static_cast<std::size_t>(stack.back())];
        stack.pop_back();
        ++r.nodesVisited;
        if (!frustum.intersectsSphere(tile.worldBox.center(), tile.worldBox.diagonal() * 0.5))
            continue;
        if (tile.node != kNoId && !tile.children.empty() && cls.tooBig(tile.node)) {
            stack.insert(stack.end(), tile.children.begin(), tile.children.end());
            continue;
        }
        if (tile.content < 0) continue;
        const Config::ContentDraw& d = c.contentDraws[static_cast<std::size_t>(tile.content)];
        draw.insert(draw.end(), d.drawables.begin(), d.drawables.end());
        r.triangles += d.triangles;
    }
}

} // namespace

void runBench(const Scene& scene, const BenchOptions& o) {
    namespace fs = std::filesystem;
    if (scene.instances.empty()) throw Error(ErrorCode::NoGeometry, "the scene has no meshes");
    std::error_code ec;
    fs::create_directories(o.out, ec);
    if (ec || !fs::is_directory(o.out))
        throw Error(ErrorCode::Io, o.out, "cannot create the output folder");
    fs::remove(o.out / "summary.json", ec); // present again only when this run finishes

    // Camera path: frame i at t = i / fps, fps = frames / duration (the whole path is flown).
    const Aabb bounds = scene.worldBounds();
    CameraPath path;
    if (o.pathFile) {
        path = readCameraPath(*o.pathFile);
        Aabb all = bounds;
        for (const CameraKey& k : path.keys) {
            all.expand(k.eye);
            all.expand(k.target);
        }
        fitClipPlanes(path, all);
    } else {
        path = automaticCameraPath(scene, 60.0);
    }
    writeCameraPath(o.out / "camera_path.json", path);
    const double fps = o.frames / path.duration();
    const std::vector<Camera> cameras = sampleCameraPath(path, o.frames, fps, o.width, o.height);
    const double referenceHeight = 1080.0;
    const double selectionS = o.screenSize * o.height / referenceHeight;
    // A DLOD level is shown where its measured deviation covers at most the pixel error of the
    // reference viewport (as proxies are at their switch): dev * ppu / d <= height / 1080.
    const double dlodPixelError = o.height / referenceHeight;

    // Configurations; Original first, always (it is the image reference).
    std::vector<Config> configs;
    auto want = [&](const std::string& k) {
        return std::find(o.configs.begin(), o.configs.end(), k) != o.configs.end();
    };
    for (const std::string& key : kBenchConfigs) {
        if (key != "original" && !want(key)) continue;
        Config c;
        c.key = key;
        c.kind = key == "original" ? Kind::Original : key == "dlod" ? Kind::Dlod : Kind::Hlod;
        c.name = key == "original" ? "Original" : key == "dlod" ? "DLOD chain" : "";
        configs.push_back(std::move(c));
    }

    ProgressBar bar;
    std::vector<GeometryStats> stats{originalStats(scene)};
    BakeParams bake;
    bake.screen.screenSize = o.screenSize;
    bake.proxyRatio = o.proxyRatio;
    bake.threads = o.threads;
    bake.cacheDir = o.cacheDir;
    bake.atlas.enabled = o.proxyTextures;
    for (Config& c : configs) {
        if (c.kind != Kind::Hlod) continue;
        HlodSettings settings;
        settings.cluster = clusterParamsFor(c.key);
        settings.cluster.levelGrowth = o.levelGrowth;
        settings.bake = bake;
        c.build = std::make_unique<HlodBuild>(buildHlod(scene, settings, bar.progress()));
        c.name = hlodVersionName(c.build->tree);
    }
    bar.finish();

    // DLOD chains, once per unique mesh.
    std::vector<std::vector<Mesh>> chains;
    std::vector<std::vector<double>> deviations; // per mesh, per level (mesh units)
    if (want("dlod")) {
        chains.resize(scene.meshes.size());
        deviations.resize(scene.meshes.size());
        tbb::task_arena arena(o.threads > 0 ? o.threads : tbb::task_arena::automatic);
        std::fprintf(stderr, "dlod: building chains for %zu meshes\n", scene.meshes.size());
        arena.execute([&] {
            tbb::parallel_for(std::size_t(0), scene.meshes.size(), [&](std::size_t m) {
                chains[m] = buildDlodChain(scene.meshes[m]);
                deviations[m] = dlodDeviations(scene.meshes[m], chains[m]);
            });
        });
        DlodSummary summary;
        for (const MeshInstance& inst : scene.instances) {
            const Mesh& mesh = scene.meshes[inst.mesh];
            summary.triangles += mesh.triangleCount();
            summary.vertices += mesh.vertexCount();
            summary.bytes += meshBytes(mesh);
            summary.meshes += 1;
            for (const Mesh& level : chains[inst.mesh]) {
                summary.triangles += level.triangleCount();
                summary.vertices += level.vertexCount();
                summary.bytes += meshBytes(level);
                summary.meshes += 1;
            }
        }
        stats.push_back(dlodStats(summary));
    }
    for (const Config& c : configs)
        if (c.kind == Kind::Hlod)
            stats.push_back(hlodStats(scene, c.build->tree, c.build->bake, c.name));

    // Per-instance data shared by Original and DLOD.
    const std::size_t nInst = scene.instances.size();
    std::vector<glm::dvec3> instCenter(nInst);
    std::vector<double> instRadius(nInst);
    std::vector<glm::vec4> instColor(nInst);
    std::vector<double> instScale(nInst); // largest scale of the instance's transform
    std::vector<SurfaceLook> instLook(nInst);
    for (Id i = 0; i < nInst; ++i) {
        const Aabb b = scene.instanceBounds(i);
        instCenter[i] = b.center();
        instRadius[i] = b.diagonal() * 0.5;
        const glm::dmat3 linear(scene.instanceTransform(i));
        instScale[i] =
            std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
        const Mesh& mesh = scene.meshes[scene.instances[i].mesh];
        instColor[i] = mesh.material < scene.materials.size()
                           ? scene.materials[mesh.material].effectiveColor()
                           : glm::vec4(0.8f);
        instLook[i] = lookOf(scene, mesh.material);
    }

    // Renderer: one layer per configuration, one actor per drawable.
    std::fprintf(stderr, "render: preparing %zu configurations at %dx%d\n", configs.size(), o.width,
                 o.height);
    // Deliberately never freed: tearing down tens of thousands of VTK actors one by one takes
    // minutes (torcs-spring: 4418 instances x 7 configurations), and `hlod bench` exits right
    // after this function, which closes the display connection anyway.
    OffscreenRenderer& renderer = *new OffscreenRenderer(o.width, o.height, o.shading);
    for (Config& c : configs) {
        c.layer = renderer.addLayer();
        if (c.kind == Kind::Hlod) {
            const ClusterTree& tree = c.build->tree;
            std::vector<std::uint64_t> tris(tree.nodes.size(), 0);
            c.nodeDrawable.assign(tree.nodes.size(), -1);
            for (Id n = 0; n < tree.nodes.size(); ++n) {
                const ClusterNode& node = tree.nodes[n];
                if (node.isLeaf()) {
                    const Id i = node.instance;
                    const Mesh& mesh = scene.meshes[scene.instances[i].mesh];
                    tris[n] = mesh.triangleCount();
                    if (tris[n] > 0)
                        c.nodeDrawable[n] = renderer.addMesh(
                            c.layer, mesh, scene.instanceTransform(i), instColor[i], instLook[i]);
                } else {
                    const ProxyMesh& proxy = c.build->bake.nodes[n].proxy;
                    tris[n] = proxy.triangleCount();
                    if (tris[n] > 0)
                        c.nodeDrawable[n] = renderer.addProxy(
                            c.layer, proxy, c.build->bake.nodes[n].frame.matrix());
                }
            }
            c.selection = std::make_unique<SelectionTree>(tree, std::move(tris),
                                                          rootHasNoProxy(tree, c.build->bake));
            c.cache = std::make_unique<FrontCache>(*c.selection);
            if (o.draw == HlodDraw::Package)
                addPackageDrawables(c, scene, renderer, instColor, instLook);
        } else {
            c.instanceDrawables.resize(nInst);
            for (Id i = 0; i < nInst; ++i) {
                const Id m = scene.instances[i].mesh;
                const glm::dmat4& world = scene.instanceTransform(i);
                c.instanceDrawables[i].push_back(
                    renderer.addMesh(c.layer, scene.meshes[m], world, instColor[i], instLook[i]));
                if (c.kind == Kind::Dlod) {
                    for (const Mesh& level : chains[m])
                        c.instanceDrawables[i].push_back(
                            renderer.addMesh(c.layer, level, world, instColor[i], instLook[i]));
                }
            }
        }
        renderer.warmUp(c.layer, cameras.front());
    }

    // The three moments of the side-by-side comparison: far, flying in, close.
    const std::vector<double> momentShares{0.1, 0.5, 0.9};
    std::vector<int> momentFrames;
    for (double s : momentShares)
        momentFrames.push_back(
            std::clamp(static_cast<int>(std::lround(s * (o.frames - 1))), 0, o.frames - 1));
    std::vector<std::vector<RgbImage>> momentImages(momentFrames.size());
    std::vector<std::vector<std::string>> momentCaptions(momentFrames.size());

    std::vector<FrameRecord> records;
    records.reserve(static_cast<std::size_t>(o.frames) * configs.size());
    Progress progress = bar.progress();
    RgbImage reference;
    for (int f = 0; f < o.frames; ++f) {
        const Camera& cam = cameras[static_cast<std::size_t>(f)];
        const Frustum frustum = Frustum::fromCamera(cam);
        const double ppu = cam.pixelsPerUnitAtDistanceOne();
        for (Config& c : configs) {
            FrameRecord r;
            r.frame = f;
            r.timeSeconds = f / fps;
            r.config = c.name;
            std::vector<int> draw;
            const auto t0 = Clock::now();
            if (c.kind == Kind::Hlod && c.layout) {
                selectPackage(c, NodeClassifier(*c.selection, cam, {selectionS}), frustum, draw, r);
                r.selectionUs = msSince(t0) * 1000.0;
            } else if (c.kind == Kind::Hlod) {
                const SelectionResult sel = c.cache->select(cam, {selectionS});
                r.selectionUs = msSince(t0) * 1000.0;
                r.nodesVisited = sel.nodesVisited;
                for (Id n : sel.drawList) {
                    if (c.nodeDrawable[n] < 0) continue;
                    draw.push_back(c.nodeDrawable[n]);
                    r.triangles += c.selection->triangles(n);
                }
            } else {
                std::vector<std::pair<Id, int>> picks; // instance, level
                for (Id i = 0; i < nInst; ++i) {
                    if (!frustum.intersectsSphere(instCenter[i], instRadius[i])) continue;
                    int level = 0;
                    const int levels = static_cast<int>(c.instanceDrawables[i].size()) - 1;
                    if (levels > 0) {
                        const double d = glm::length(instCenter[i] - cam.eye);
                        const std::vector<double>& dev = deviations[scene.instances[i].mesh];
                        for (int l = 1; l <= levels; ++l) {
                            const double world =
                                dev[static_cast<std::size_t>(l - 1)] * instScale[i];
                            if (world * ppu <= dlodPixelError * d) level = l;
                        }
                    }
                    picks.emplace_back(i, level);
                }
                r.selectionUs = msSince(t0) * 1000.0;
                r.nodesVisited = nInst;
                for (const auto& [i, level] : picks) {
                    const Id m = scene.instances[i].mesh;
                    const Mesh& mesh = level == 0 ? scene.meshes[m]
                                                  : chains[m][static_cast<std::size_t>(level - 1)];
                    if (mesh.triangleCount() == 0) continue;
                    draw.push_back(c.instanceDrawables[i][static_cast<std::size_t>(level)]);
                    r.triangles += mesh.triangleCount();
                }
            }
            r.drawCalls = draw.size();
            renderer.setVisible(c.layer, draw);
            r.frameMs = renderer.render(c.layer, cam);
            RgbImage image = renderer.readPixels();
            if (c.kind == Kind::Original) {
                reference = std::move(image);
                r.psnrDb = kPsnrCapDb;
                r.diffShare = 0.0;
            } else {
                const ImageError e = compareImages(reference, image);
                r.psnrDb = e.psnrDb;
                r.diffShare = e.diffShare;
            }
            for (std::size_t m = 0; m < momentFrames.size(); ++m) {
                if (momentFrames[m] != f) continue;
                momentImages[m].push_back(c.kind == Kind::Original ? reference : image);
                char cap[256];
                if (c.kind == Kind::Original)
                    std::snprintf(cap, sizeof(cap), "%s\n%llu draws, %s tris, %.1f ms",
                                  c.name.c_str(), static_cast<unsigned long long>(r.drawCalls),
                                  formatCount(static_cast<double>(r.triangles)).c_str(), r.frameMs);
                else
                    std::snprintf(cap, sizeof(cap), "%s\n%llu draws, %s tris, %.1f ms, %.1f dB",
                                  c.name.c_str(), static_cast<unsigned long long>(r.drawCalls),
                                  formatCount(static_cast<double>(r.triangles)).c_str(), r.frameMs,
                                  r.psnrDb);
                momentCaptions[m].push_back(cap);
            }
            records.push_back(r);
        }
        progress.emit({"render", static_cast<std::uint64_t>(f + 1),
                       static_cast<std::uint64_t>(o.frames),
                       "frame " + std::to_string(f + 1) + " of " + std::to_string(o.frames)});
    }
    bar.finish();

    // Outputs; summary.json last.
    const std::vector<ConfigSummary> summaries = summarizeFrames(records);
    writeTextFileAtomic(o.out / "frames.csv", framesCsv(records));
    std::string title = "hlod bench:";
    for (const std::string& in : o.inputs)
        title += " " + in;
    writeTextFileAtomic(o.out / "tables.md", tablesMarkdown(title, stats, summaries));

    auto plot = [&](const std::string& file, const std::string& what, const std::string& yLabel,
                    auto value) {
        std::vector<PlotSeries> series;
        for (std::size_t ci = 0; ci < configs.size(); ++ci) {
            PlotSeries s;
            s.name = configs[ci].name;
            s.color = seriesColor(ci);
            for (const FrameRecord& r : records) {
                if (r.config != s.name) continue;
                s.x.push_back(r.timeSeconds);
                s.y.push_back(value(r));
            }
            series.push_back(std::move(s));
        }
        PlotOptions po;
        po.title = what;
        po.xLabel = "Time (s)";
        po.yLabel = yLabel;
        writePng(o.out / file, renderLinePlot(series, po));
    };
    plot("plot_frame_ms.png", "Frame time", "Frame time (ms)",
         [](const FrameRecord& r) { return r.frameMs; });
    plot("plot_draw_calls.png", "Draw calls", "Draw calls",
         [](const FrameRecord& r) { return static_cast<double>(r.drawCalls); });
    plot("plot_triangles.png", "Triangles drawn", "Triangles",
         [](const FrameRecord& r) { return static_cast<double>(r.triangles); });
    plot("plot_psnr.png", "Image error vs Original (PSNR, capped at 100)", "PSNR (dB)",
         [](const FrameRecord& r) { return r.psnrDb; });
    for (std::size_t m = 0; m < momentFrames.size(); ++m) {
        char name[64];
        std::snprintf(name, sizeof(name), "side_by_side_%04.1fs.png", momentFrames[m] / fps);
        writePng(o.out / name, composeGrid(momentImages[m], momentCaptions[m], 4));
    }

    nlohmann::json extra;
    extra["inputs"] = o.inputs;
    extra["frames"] = o.frames;
    extra["fps"] = fps;
    extra["size"] = {o.width, o.height};
    extra["screen_size_px"] = o.screenSize;
    extra["selection_screen_size_px"] = selectionS;
    extra["shading"] = o.shading == Shading::Geometry ? "geometry"
                       : o.shading == Shading::Colour ? "colour"
                                                      : "textured";
    extra["proxy_textures"] = o.proxyTextures;
    extra["hlod_draw"] = o.draw == HlodDraw::Package ? "package" : "nodes";
    extra["psnr_cap_db"] = kPsnrCapDb;
    extra["camera_path"] = o.pathFile ? o.pathFile->string() : std::string("automatic");
    extra["statistics"] = nlohmann::json::array();
    for (const GeometryStats& s : stats)
        extra["statistics"].push_back({{"version", s.version},
                                       {"triangles", s.triangles},
                                       {"vertices", s.vertices},
                                       {"meshes", s.meshes},
                                       {"bytes", s.bytes}});
    writeTextFileAtomic(o.out / "summary.json", summaryJson(summaries, extra).dump(2) + "\n");

    for (const ConfigSummary& s : summaries)
        std::printf("%-18s draws %8.1f (max %6llu)  tris %9s  frame %7.2f ms (p95 %7.2f)  "
                    "PSNR %5.1f dB (min %5.1f)  select %7.1f us\n",
                    s.config.c_str(), s.drawCallsMean,
                    static_cast<unsigned long long>(s.drawCallsMax),
                    formatCount(s.trianglesMean).c_str(), s.frameMsMean, s.frameMsP95, s.psnrMean,
                    s.psnrMin, s.selectionUsMean);
    std::printf("output: %s\n", o.out.string().c_str());
}

} // namespace hlod::cli
