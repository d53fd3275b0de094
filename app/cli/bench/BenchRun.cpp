#include "BenchRun.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <tuple>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "../ProgressBar.h"
#include "FrameMetrics.h"
#include "pipeline/core/Error.h"
#include "pipeline/eval/BenchReport.h"
#include "pipeline/eval/Flip.h"
#include "pipeline/eval/ImageError.h"
#include "pipeline/eval/Plot.h"
#include "pipeline/export/PackageLayout.h"
#include "pipeline/export/StackedAtlas.h"
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
    std::shared_ptr<const NodeOutput> build; // the Bake node's output: tree and proxies
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

// A configuration's Cluster node: the bench's cluster parameters with its volume and k.
NodeId addClusterNode(PipelineGraph& graph, const std::string& key, const ParamValues& values) {
    const NodeId id = graph.addNode(NodeKind::Cluster);
    for (const auto& [k, v] : values)
        graph.setParam(id, k, v);
    if (key == "sphere" || key == "octree") {
        graph.setParam(id, "volume", key);
    } else {
        graph.setParam(id, "volume", std::string("aabb"));
        graph.setParam(id, "k", static_cast<double>(key.back() - '0'));
    }
    return id;
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
// (TileContent.h: base colour, texture, alpha, sides, emission, and which vertex streams the
// leaves carry).
// The factor and the texture stand for the colour (a leaf's colour is its factor times its
// texture's mean), as the tile writes them; a stacked leaf's texture is its page.
using MergeKey = std::tuple<std::array<float, 4>, const RgbaImage*, int, float, bool,
                            std::array<float, 6>, bool, bool, bool, bool>;

MergeKey mergeKeyOf(const SurfaceLook& look, const Mesh& mesh) {
    const glm::vec4& f = look.factor;
    const glm::vec3 &e = look.emissive, &em = look.emissiveMean;
    return {{f.r, f.g, f.b, f.a},   look.texture,          static_cast<int>(look.alphaMode),
            look.alphaCutoff,       look.doubleSided,      {e.r, e.g, e.b, em.r, em.g, em.b},
            look.emissiveIsTexture, !mesh.normals.empty(), !mesh.uvs.empty(),
            !mesh.colors.empty()};
}

// A leaf as the package stores it (TileContent.h): a mesh whose texture is stacked into a page
// reads the page through moved uvs (StackedAtlas.h), so leaves of textures on one page merge
// into one drawable as they do in the tile; any other mesh as it is.
struct PackageLeaves {
    const Scene& scene;
    const StackedAtlases& atlases;
    std::deque<Mesh>& store;                // stacked copies (the renderer keys meshes by address)
    std::map<Id, const Mesh*> stacked = {}; // per scene mesh, null when it keeps its texture

    std::pair<const Mesh*, SurfaceLook> leaf(Id instance, const SurfaceLook& look) {
        const Id meshId = scene.instances[instance].mesh;
        const Mesh& mesh = scene.meshes[meshId];
        const AtlasBand* band = atlases.stacks(meshId) ? atlases.band(mesh.material) : nullptr;
        if (!band) return {&mesh, look};
        const RgbaImage& page = atlases.pages()[static_cast<std::size_t>(band->page)];
        auto [it, added] = stacked.try_emplace(meshId, nullptr);
        if (added)
            if (std::optional<StackedUvs> s = stackUvs(mesh, *band, page.height))
                it->second = &store.emplace_back(stackedMesh(mesh, *s));
        if (!it->second) return {&mesh, look};
        SurfaceLook paged = look;
        paged.texture = &page;
        // Its emission, when it has a texture, is the page (as the tile writes it); the mean
        // of the leaf's own texture stands for nothing then.
        if (paged.emissiveIsTexture) paged.emissiveMean = glm::vec3(1.0f);
        return {it->second, paged};
    }
};

// The package's contents as drawables: a proxy draws its node's proxy; a leaf group draws its
// instanced leaves one by one and its other leaves merged per look (one drawable each).
void addPackageDrawables(Config& c, const Scene& scene, const StackedAtlases& atlases,
                         OffscreenRenderer& renderer, const std::vector<glm::vec4>& instColor,
                         const std::vector<SurfaceLook>& instLook) {
    c.layout = std::make_unique<PackageLayout>(planPackage(scene, *c.build->tree, *c.build->bake));
    c.contentDraws.resize(c.layout->contents.size());
    PackageLeaves leaves{scene, atlases, c.mergedMeshes};
    for (std::size_t k = 0; k < c.layout->contents.size(); ++k) {
        const ContentPlan& plan = c.layout->contents[k];
        Config::ContentDraw& draw = c.contentDraws[k];
        if (plan.proxy) {
            if (c.nodeDrawable[plan.node] >= 0) {
                draw.drawables.push_back(c.nodeDrawable[plan.node]);
                draw.triangles = c.build->bake->nodes[plan.node].proxy.triangleCount();
            }
            continue;
        }
        std::map<MergeKey, Mesh*> merged;
        struct FirstMember {
            Mesh* merged;
            Id instance; // its colour stands for all (the key holds it)
            SurfaceLook look;
        };
        std::vector<FirstMember> mergedOrder;
        for (const LeafSlot& slot : plan.leaves) {
            const Id i = slot.instance;
            const auto [mesh, look] = leaves.leaf(i, instLook[i]);
            if (mesh->triangleCount() == 0) continue;
            draw.triangles += mesh->triangleCount();
            if (!slot.merged) {
                draw.drawables.push_back(renderer.addMesh(
                    c.layer, *mesh, scene.instanceTransform(i), instColor[i], look));
                continue;
            }
            auto [it, added] = merged.try_emplace(mergeKeyOf(look, *mesh));
            if (added) {
                Mesh& m = c.mergedMeshes.emplace_back();
                m.name = "merged";
                m.material = mesh->material;
                it->second = &m;
                mergedOrder.push_back({&m, i, look});
            }
            appendPlaced(*it->second, *mesh, scene.instanceTransform(i));
        }
        for (const FirstMember& f : mergedOrder)
            draw.drawables.push_back(renderer.addMesh(c.layer, *f.merged, glm::dmat4(1.0),
                                                      instColor[f.instance], f.look));
    }
}

// Distance from `p` to the box (0 inside).
double distanceToBox(const Aabb& box, const glm::dvec3& p) {
    const glm::dvec3 d = glm::max(glm::max(box.min - p, p - box.max), glm::dvec3(0.0));
    return glm::length(d);
}

// The package's tiles a 3D Tiles runtime draws for `camera` (REPLACE refinement), as
// 3d-tiles-renderer and CesiumJS select them: a tile whose bounding box misses the frustum is
// skipped with everything below it; a tile with children is refined when its screen-space
// error, geometricError x (pixels per unit at distance 1) / (distance from the eye to its box),
// exceeds `maxError` pixels (always inside its box); a tile without children is drawn whenever
// it is reached. (Algorithm 5 measures the distance to a node's centre instead, so a runtime
// refines somewhat farther away than the node count does.)
void selectPackage(const Config& c, const Camera& cam, double maxError, const Frustum& frustum,
                   std::vector<int>& draw, std::vector<int>& tiles, FrameRecord& r) {
    const PackageLayout& layout = *c.layout;
    if (layout.tiles.empty()) return;
    std::vector<int> stack{0};
    while (!stack.empty()) {
        const TilePlan& tile = layout.tiles[static_cast<std::size_t>(stack.back())];
        stack.pop_back();
        ++r.nodesVisited;
        if (!frustum.intersectsSphere(tile.worldBox.center(), tile.worldBox.diagonal() * 0.5))
            continue;
        if (!tile.children.empty()) {
            const double d = distanceToBox(tile.worldBox, cam.eye);
            if (d <= 0.0 || tile.geometricError * cam.pixelsPerUnitAtDistanceOne() > maxError * d) {
                stack.insert(stack.end(), tile.children.begin(), tile.children.end());
                continue;
            }
        }
        if (tile.content < 0) continue;
        const Config::ContentDraw& d = c.contentDraws[static_cast<std::size_t>(tile.content)];
        tiles.push_back(static_cast<int>(&tile - layout.tiles.data()));
        draw.insert(draw.end(), d.drawables.begin(), d.drawables.end());
        r.triangles += d.triangles;
    }
}

// frames/NNNNN-camera.json: the frame's camera, for renderers to draw the same view
// (tests/web/render-tileset.mjs --camera).
void writeFrameCamera(const std::filesystem::path& dir, int frame, const Camera& cam) {
    char name[64];
    std::snprintf(name, sizeof(name), "%05d-camera.json", frame);
    const nlohmann::json j = {
        {"eye", {cam.eye.x, cam.eye.y, cam.eye.z}},
        {"target", {cam.target.x, cam.target.y, cam.target.z}},
        {"up", {cam.up.x, cam.up.y, cam.up.z}},
        {"fovDeg", glm::degrees(cam.fovY)},
        {"near", cam.nearPlane},
        {"far", cam.farPlane},
        {"width", static_cast<int>(std::lround(cam.aspect * cam.viewportHeight))},
        {"height", cam.viewportHeight}};
    writeTextFileAtomic(dir / name, j.dump(1) + "\n");
}

} // namespace

void runBench(PipelineGraph& graph, NodeId importNode, const BenchOptions& o) {
    namespace fs = std::filesystem;
    const Scene& scene = *graph.output(importNode)->scene;
    const BakeParams bake = bakeParamsFrom(o.bake);
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
    const double selectionS = bake.screen.screenSize * o.height / referenceHeight;
    // A DLOD level is shown where its measured deviation covers at most the pixel error of the
    // reference viewport (as proxies are at their switch): dev * ppu / d <= height / 1080.
    const double dlodPixelError = o.height / referenceHeight;
    // A package tile is refined past this screen-space error: the pixel error at the reference
    // viewport, scaled to the render height like S (so tiles switch at the baked distances).
    const double tileErrorPx = BakeParams{}.screen.pixelError * o.height / referenceHeight;

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

    // Every HLOD configuration is a branch of the graph: Cluster -> Bake from the one import.
    ProgressBar bar;
    std::vector<GeometryStats> stats{originalStats(scene)};
    std::vector<NodeId> bakes(configs.size(), kNoNode);
    for (std::size_t i = 0; i < configs.size(); ++i) {
        if (configs[i].kind != Kind::Hlod) continue;
        const NodeId cluster = addClusterNode(graph, configs[i].key, o.cluster);
        bakes[i] = graph.addNode(NodeKind::Bake);
        for (const auto& [k, v] : o.bake)
            graph.setParam(bakes[i], k, v);
        graph.connect({importNode, 0, cluster, 0});
        graph.connect({cluster, 0, bakes[i], 0});
    }
    std::vector<NodeId> targets;
    std::copy_if(bakes.begin(), bakes.end(), std::back_inserter(targets),
                 [](NodeId id) { return id != kNoNode; });
    graph.run(targets, bar.progress());
    for (std::size_t i = 0; i < configs.size(); ++i) {
        if (bakes[i] == kNoNode) continue;
        configs[i].build = graph.sharedOutput(bakes[i]);
        configs[i].name = hlodVersionName(*configs[i].build->tree);
    }
    bar.finish();

    // DLOD chains, once per unique mesh.
    std::vector<std::vector<Mesh>> chains;
    std::vector<std::vector<double>> deviations; // per mesh, per level (mesh units)
    if (want("dlod")) {
        chains.resize(scene.meshes.size());
        deviations.resize(scene.meshes.size());
        tbb::task_arena arena(bake.threads > 0 ? bake.threads : tbb::task_arena::automatic);
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
            stats.push_back(hlodStats(scene, *c.build->tree, *c.build->bake, c.name));

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
    const StackedAtlases* atlases = nullptr; // the package's texture pages, built on first use
    for (Config& c : configs) {
        c.layer = renderer.addLayer();
        if (c.kind == Kind::Hlod) {
            const ClusterTree& tree = *c.build->tree;
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
                    const ProxyMesh& proxy = c.build->bake->nodes[n].proxy;
                    tris[n] = proxy.triangleCount();
                    if (tris[n] > 0)
                        c.nodeDrawable[n] = renderer.addProxy(
                            c.layer, proxy, c.build->bake->nodes[n].frame.matrix());
                }
            }
            c.selection = std::make_unique<SelectionTree>(tree, std::move(tris),
                                                          rootHasNoProxy(tree, *c.build->bake));
            c.cache = std::make_unique<FrontCache>(*c.selection);
            if (o.draw == HlodDraw::Package) {
                // Never freed, as the renderer (its textures point into the pages).
                if (!atlases) atlases = new StackedAtlases(scene);
                addPackageDrawables(c, scene, *atlases, renderer, instColor, instLook);
            }
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
    FrameMetrics metrics(configs.size(),
                         flipPixelsPerDegree(o.height, glm::radians(path.fovYDegrees)));
    // DLOD units: instance i at level l is unit i * dlodLevels + l, its parent the level below.
    int dlodLevels = 1;
    for (const std::vector<Mesh>& chain : chains)
        dlodLevels = std::max(dlodLevels, static_cast<int>(chain.size()) + 1);
    if (o.frameImages) fs::create_directories(o.out / "frames", ec);
    for (int f = 0; f < o.frames; ++f) {
        const Camera& cam = cameras[static_cast<std::size_t>(f)];
        if (o.frameImages) writeFrameCamera(o.out / "frames", f, cam);
        const Frustum frustum = Frustum::fromCamera(cam);
        const double ppu = cam.pixelsPerUnitAtDistanceOne();
        for (std::size_t ci = 0; ci < configs.size(); ++ci) {
            Config& c = configs[ci];
            FrameRecord r;
            r.frame = f;
            r.timeSeconds = f / fps;
            r.config = c.name;
            std::vector<int> draw;
            std::vector<int> units; // what was selected, for level switches (Popping.h)
            std::function<int(int)> parent = [](int) { return -1; };
            const auto t0 = Clock::now();
            if (c.kind == Kind::Hlod && c.layout) {
                selectPackage(c, cam, tileErrorPx, frustum, draw, units, r);
                r.selectionUs = msSince(t0) * 1000.0;
                parent = [&c](int t) {
                    return c.layout->tiles[static_cast<std::size_t>(t)].parent;
                };
            } else if (c.kind == Kind::Hlod) {
                const SelectionResult sel = c.cache->select(cam, {selectionS});
                r.selectionUs = msSince(t0) * 1000.0;
                r.nodesVisited = sel.nodesVisited;
                for (Id n : sel.drawList) {
                    units.push_back(static_cast<int>(n));
                    if (c.nodeDrawable[n] < 0) continue;
                    draw.push_back(c.nodeDrawable[n]);
                    r.triangles += c.selection->triangles(n);
                }
                parent = [&c](int n) {
                    const Id p = c.build->tree->nodes[static_cast<std::size_t>(n)].parent;
                    return p == kNoId ? -1 : static_cast<int>(p);
                };
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
                    units.push_back(static_cast<int>(i) * dlodLevels + level);
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
            const RgbImage image = renderer.readPixels();
            if (c.kind == Kind::Original) metrics.setReference(image);
            if (c.kind == Kind::Dlod)
                parent = [dlodLevels](int u) { return u % dlodLevels > 0 ? u - 1 : -1; };
            std::sort(units.begin(), units.end());
            metrics.measure(ci, image, std::move(units), parent, r);
            if (o.frameImages) {
                char name[64];
                std::snprintf(name, sizeof(name), "%05d-%s.png", f, c.key.c_str());
                writePng(o.out / "frames" / name, image);
            }
            for (std::size_t m = 0; m < momentFrames.size(); ++m) {
                if (momentFrames[m] != f) continue;
                momentImages[m].push_back(image);
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
    for (const std::string& in : graph.output(importNode)->inputs)
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
    plot("plot_flip.png", "Perceptual error vs Original (mean FLIP)", "FLIP",
         [](const FrameRecord& r) { return r.flip; });
    plot("plot_pop.png", "Popping at level switches (FLIP beyond the Original's change)", "Pop",
         [](const FrameRecord& r) {
             return r.lodSwitch ? r.pop : std::numeric_limits<double>::quiet_NaN();
         });
    for (std::size_t m = 0; m < momentFrames.size(); ++m) {
        char name[64];
        std::snprintf(name, sizeof(name), "side_by_side_%04.1fs.png", momentFrames[m] / fps);
        writePng(o.out / name, composeGrid(momentImages[m], momentCaptions[m], 4));
    }

    nlohmann::json extra;
    extra["inputs"] = graph.output(importNode)->inputs;
    extra["frames"] = o.frames;
    extra["fps"] = fps;
    extra["size"] = {o.width, o.height};
    extra["screen_size_px"] = bake.screen.screenSize;
    extra["selection_screen_size_px"] = selectionS;
    extra["shading"] = o.shading == Shading::Geometry ? "geometry"
                       : o.shading == Shading::Colour ? "colour"
                                                      : "textured";
    extra["proxy_textures"] = bake.atlas.enabled;
    extra["hlod_draw"] = o.draw == HlodDraw::Package ? "package" : "nodes";
    extra["psnr_cap_db"] = kPsnrCapDb;
    extra["flip_pixels_per_degree"] = metrics.pixelsPerDegree();
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
        std::printf(
            "%-18s draws %8.1f (max %6llu)  tris %9s  frame %7.2f ms (p95 %7.2f)  "
            "PSNR %5.1f dB (min %5.1f)  FLIP %.4f (max %.4f)  pop %.4f (max %.4f, %d "
            "switches)  select %7.1f us\n",
            s.config.c_str(), s.drawCallsMean, static_cast<unsigned long long>(s.drawCallsMax),
            formatCount(s.trianglesMean).c_str(), s.frameMsMean, s.frameMsP95, s.psnrMean,
            s.psnrMin, s.flipMean, s.flipMax, s.popMean, s.popMax, s.switches, s.selectionUsMean);
    std::printf("output: %s\n", o.out.string().c_str());
}

} // namespace hlod::cli
