// Assembles the package of Package.h (layout, contents named by hash, textures, tileset.json,
// hlod.json) into a sink: a temporary sibling folder renamed into place at the end
// (writePackage), or a counter of sizes (measurePackage).
#include <fstream>
#include <map>
#include <random>
#include <set>

#include <unistd.h>

#include "pipeline/core/AtomicFile.h"
#include "pipeline/core/Error.h"
#include "pipeline/export/DiskUsage.h"
#include "pipeline/export/Package.h"
#include "pipeline/export/PackageManifest.h"
#include "pipeline/export/Placement.h"
#include "pipeline/export/TileContent.h"
#include "pipeline/proxy/ContentHash.h"

namespace hlod {

namespace fs = std::filesystem;

namespace {

// Where the package's files go; `rel` is a relative path with '/' separators.
class Sink {
public:
    virtual ~Sink() = default;
    virtual void add(const std::string& rel, std::span<const std::uint8_t> bytes) = 0;
    // A file whose bytes are in `file` (a content encoded elsewhere).
    virtual void addFile(const std::string& rel, const fs::path& file) = 0;
    void addText(const std::string& rel, const std::string& text) {
        add(rel, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
    }
};

// Counts what would be written (measurePackage).
class SizeSink : public Sink {
public:
    SizeSink(PackageSummary& s, std::uintmax_t blockSize) : s_(s), blockSize_(blockSize) {}
    void add(const std::string&, std::span<const std::uint8_t> bytes) override {
        ++s_.files;
        s_.bytes += bytes.size();
        s_.bytesOnDisk += blocksFor(bytes.size(), blockSize_);
    }
    void addFile(const std::string&, const fs::path& file) override {
        std::error_code ec;
        const std::uintmax_t size = fs::file_size(file, ec);
        ++s_.files;
        s_.bytes += size;
        s_.bytesOnDisk += blocksFor(size, blockSize_);
    }

private:
    PackageSummary& s_;
    std::uintmax_t blockSize_;
};

// Writes into the temporary folder; a file the old package already holds with the same bytes
// is hard-linked from it instead (nothing written).
class FolderSink : public Sink {
public:
    FolderSink(fs::path tmp, fs::path old, PackageSummary& s)
        : tmp_(std::move(tmp)), old_(std::move(old)), s_(s) {}
    void add(const std::string& rel, std::span<const std::uint8_t> bytes) override {
        const fs::path target = tmp_ / rel;
        std::error_code ec;
        fs::create_directories(target.parent_path(), ec);
        if (ec) throw Error(ErrorCode::Io, target.parent_path(), "cannot create: " + ec.message());
        if (!old_.empty() && fileHoldsBytes(old_ / rel, bytes)) {
            fs::create_hard_link(old_ / rel, target, ec);
            if (!ec) {
                ++s_.reused;
                return;
            }
        }
        writeFileBytes(target,
                       std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
        ++s_.written;
    }
    // Content-addressed names: a file of the old package with the same name and size holds the
    // same bytes. Otherwise a hard link to `file`, or a copy where links cannot be made.
    void addFile(const std::string& rel, const fs::path& file) override {
        const fs::path target = tmp_ / rel;
        std::error_code ec;
        fs::create_directories(target.parent_path(), ec);
        if (ec) throw Error(ErrorCode::Io, target.parent_path(), "cannot create: " + ec.message());
        const std::uintmax_t size = fs::file_size(file, ec);
        if (ec) throw Error(ErrorCode::FileNotFound, file, "cannot be read: " + ec.message());
        if (!old_.empty() && fs::is_regular_file(old_ / rel, ec) &&
            fs::file_size(old_ / rel, ec) == size && !ec) {
            fs::create_hard_link(old_ / rel, target, ec);
            if (!ec) {
                ++s_.reused;
                return;
            }
        }
        ec.clear();
        fs::create_hard_link(file, target, ec);
        if (ec) {
            ec.clear();
            fs::copy_file(file, target, ec);
            if (ec) throw Error(ErrorCode::Io, target, "cannot write: " + ec.message());
        }
        ++s_.written;
    }

private:
    fs::path tmp_, old_;
    PackageSummary& s_;
};

// Every file of the package laid out as `layout` into `sink`; contents from blocks come from
// `parts` (null: none). Returns the number of tiles.
std::size_t assembleLayout(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                           const BakeParams& bakeParams, const PackageOptions& options,
                           const PackageLayout& layout, const Placement& placement,
                           const PackageParts* parts, Sink& sink, const Progress& progress) {
    TextureStore textures(scene, imageCacheFolder(bakeParams.cacheDir));
    ContentEncoder encoder(scene, bake, textures, options.compression);
    std::vector<std::string> uris;
    std::vector<EncodedContent> encoded;
    std::set<std::string> added;
    std::map<std::uint64_t, std::size_t> byKey; // content key -> first content encoded with it
    for (std::size_t i = 0; i < layout.contents.size(); ++i) {
        progress.throwIfCancelled();
        if (parts && i < layout.sources.size() && layout.sources[i].block != kNoId) {
            const GivenContent& g = parts->given(layout.sources[i]);
            uris.push_back(g.uri);
            if (added.insert(g.uri).second) sink.addFile(g.uri, g.file);
            encoded.push_back(g.encoded);
            progress.emit({"export", i + 1, layout.contents.size(), ""});
            continue;
        }
        const std::uint64_t key = contentKey(layout.contents[i], bake, scene);
        if (auto it = byKey.find(key); it != byKey.end()) { // a copy: the same file
            uris.push_back(uris[it->second]);
            encoded.push_back(encoded[it->second]);
        } else {
            byKey.emplace(key, i);
            EncodedContent e = encoder.encode(layout.contents[i]);
            uris.push_back("tiles/" + toHex(hashBytes(e.bytes.data(), e.bytes.size())) + ".glb");
            if (added.insert(uris.back()).second) sink.add(uris.back(), e.bytes);
            e.bytes = {};
            encoded.push_back(std::move(e));
        }
        progress.emit({"export", i + 1, layout.contents.size(), ""});
    }
    for (const auto& [uri, bytes] : textures.files())
        sink.add("tiles/" + uri, bytes);
    nlohmann::json tileset = buildTileset(layout, uris, options.geo);
    tileset["extras"] = {
        {"hlod", placementTilesetJson(placement, options.geo, bakeParams.screen.pixelError)}};
    sink.addText("tileset.json", tileset.dump());
    const ManifestInput manifest{scene,      tree,    bake,
                                 bakeParams, options, layout,
                                 uris,       encoded, parts ? &parts->sizes : nullptr};
    nlohmann::json hlodJson = buildManifest(manifest);
    hlodJson["placement"] = placementManifestJson(placement, options.geo);
    sink.addText("hlod.json", hlodJson.dump());
    progress.throwIfCancelled();
    return layout.tiles.size();
}

// The whole package of a tree and its proxies.
std::size_t assemble(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                     const BakeParams& bakeParams, const PackageOptions& options, Sink& sink,
                     const Progress& progress) {
    if (tree.root == kNoId || bake.nodes.size() != tree.nodes.size())
        throw Error(ErrorCode::InvalidArgument, "package: the proxies do not match the tree");
    // Where the scene is and how to frame it, for runtimes (Placement.h).
    return assembleLayout(scene, tree, bake, bakeParams, options, planPackage(scene, tree, bake),
                          packagePlacement(scene), nullptr, sink, progress);
}

fs::path siblingTemp(const fs::path& dir, const char* tag) {
    std::random_device rd;
    return dir.parent_path() / ("." + dir.filename().string() + tag + std::to_string(getpid()) +
                                "-" + std::to_string(rd()));
}

// Replaces `dir` by `tmp`; an existing package is moved aside first and removed only once the
// new one is in place (restored if the final rename fails).
void commitFolder(const fs::path& tmp, const fs::path& dir) {
    std::error_code ec;
    fs::path old;
    if (fs::exists(dir, ec)) {
        old = siblingTemp(dir, ".old-");
        fs::rename(dir, old, ec);
        if (ec)
            throw Error(ErrorCode::Io, dir, "cannot replace the existing folder: " + ec.message());
    }
    fs::rename(tmp, dir, ec);
    if (ec) {
        if (!old.empty()) fs::rename(old, dir);
        throw Error(ErrorCode::Io, dir, "cannot move the package into place: " + ec.message());
    }
    if (!old.empty()) fs::remove_all(old, ec);
}

// The package folder `dirIn` written by `fill` into a temporary sibling renamed into place.
PackageSummary writeFolder(const fs::path& dirIn, const std::function<std::size_t(Sink&)>& fill) {
    const fs::path dir = fs::absolute(dirIn).lexically_normal();
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
        throw Error(ErrorCode::Io, dir, "exists and is not a folder");
    }
    fs::create_directories(dir.parent_path(), ec);
    // A read-only folder (or file system) is refused before any work, and named as such.
    if (fs::exists(dir, ec) && ::access(dir.c_str(), W_OK) != 0) {
        throw Error(ErrorCode::Io, dir, "cannot write the package: " + systemReason(errno));
    }
    const fs::path tmp = siblingTemp(dir, ".tmp-");
    PackageSummary summary;
    try {
        if (!fs::create_directories(tmp, ec) || ec) {
            throw Error(ErrorCode::Io, dir.parent_path(),
                        "cannot create the package's temporary folder: " + ec.message());
        }
        FolderSink sink(tmp, isPackageFolder(dir) ? dir : fs::path(), summary);
        summary.tiles = fill(sink);
        commitFolder(tmp, dir);
    } catch (const Error& e) {
        fs::remove_all(tmp, ec);
        if (e.code() != ErrorCode::Io) throw;
        // One line naming the package (not our temporary folder) and what the system said.
        const std::string inside = e.file().lexically_relative(tmp).generic_string();
        const bool ownFile = !inside.empty() && inside.rfind("..", 0) != 0;
        std::string problem = e.problem();
        if (ownFile && problem.rfind("cannot write: ", 0) == 0) {
            problem = "cannot write " + inside + ": " + problem.substr(14);
        }
        throw Error(ErrorCode::Io, dir,
                    problem + (fs::exists(dir, ec) ? " (the previous package is unchanged)" : ""));
    } catch (...) {
        fs::remove_all(tmp, ec);
        throw;
    }
    const DiskFootprint disk = filesFootprint({dir});
    summary.files = disk.files;
    summary.bytes = disk.bytes;
    summary.bytesOnDisk = disk.bytesOnDisk;
    return summary;
}

} // namespace

PackageSummary writePackage(const fs::path& dir, const Scene& scene, const ClusterTree& tree,
                            const BakeResult& bake, const BakeParams& bakeParams,
                            const PackageOptions& options, const Progress& progress) {
    return writeFolder(dir, [&](Sink& sink) {
        return assemble(scene, tree, bake, bakeParams, options, sink, progress);
    });
}

PackageSummary writePackage(const fs::path& dir, const Scene& scene, const ClusterTree& tree,
                            const BakeResult& bake, const BakeParams& bakeParams,
                            const PackageOptions& options, const PackageParts& parts,
                            const Progress& progress) {
    if (tree.root == kNoId || bake.nodes.size() != tree.nodes.size())
        throw Error(ErrorCode::InvalidArgument, "package: the proxies do not match the tree");
    return writeFolder(dir, [&](Sink& sink) {
        return assembleLayout(scene, tree, bake, bakeParams, options, parts.layout, parts.placement,
                              &parts, sink, progress);
    });
}

PackageSummary measurePackage(const Scene& scene, const ClusterTree& tree, const BakeResult& bake,
                              const BakeParams& bakeParams, const PackageOptions& options,
                              std::uintmax_t blockSize, const Progress& progress) {
    PackageSummary summary;
    SizeSink sink(summary, blockSize);
    summary.tiles = assemble(scene, tree, bake, bakeParams, options, sink, progress);
    return summary;
}

} // namespace hlod
