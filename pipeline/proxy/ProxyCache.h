// On-disk content cache of baked proxies (one file per proxy, named by its 64-bit key).
//
// The key is computed by the baker (ProxyBaker.cpp) as a Merkle hash: the hash of a node's
// method, parameters, error budget and frame, and of each child's key (inner children) or
// geometry, material colour and transform (leaf children). A node's key therefore changes
// exactly when something that can change its proxy changes, and is known before any baking.
//
// Files: `<dir>/<16 hex digits>.hlodproxy`: magic, format version, key, counts, origin, the
// vertex streams, indices, the baked atlas when there is one (uvs, mask flag, MIME type, the
// encoded JPEG/PNG; decoded on load) and a checksum over everything before it. Writes go to a
// unique temporary file in the same folder and are renamed into place, so a reader (another thread,
// another process, a rerun after a crash or cancellation) sees a complete file or none.
// A file that is truncated, has a bad checksum or belongs to another key is a miss (and is
// overwritten by the next store). Thread-safe: no shared mutable state besides the folder.
// Failure: store() throws Error(Io) naming the file when the folder cannot be written.
// Sharing: several processes, on one machine or on many over NFS, may use one folder at once
// (a distributed bake's shards, ShardPlan.h): complete files only, and claim() keeps them from
// baking the same proxy twice.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>

#include "pipeline/core/Progress.h"
#include "pipeline/proxy/ProxyMesh.h"

namespace hlod {

class ProxyCache {
public:
    // An empty folder disables the cache (load misses, store does nothing).
    explicit ProxyCache(std::filesystem::path folder);

    bool enabled() const { return !folder_.empty(); }
    const std::filesystem::path& folder() const { return folder_; }

    // The proxy stored under `key`, or nothing. `damaged` (when given) is set when a file is
    // there but is not a whole proxy of that key (truncated, bad checksum, another key).
    std::optional<ProxyMesh> load(std::uint64_t key, bool* damaged = nullptr) const;
    void store(std::uint64_t key, const ProxyMesh& mesh) const;

    std::filesystem::path fileFor(std::uint64_t key) const;

    // An exclusive claim on one key across processes and machines sharing the folder: a POSIX
    // record lock (fcntl, which NFS carries to its server) on `<key>.lock`, polled while
    // another process holds it (Error(Cancelled) when `progress` is cancelled meanwhile). The baker
    // takes it after a miss, looks again, and bakes and stores only when the file is still missing,
    // so a proxy another process is baking is waited for instead of baked twice. Holders never wait
    // for another claim, so claims cannot deadlock. Destroying the claim removes the lock file and
    // releases it; a process that dies loses its locks, and a waiter then finds no file and bakes
    // the proxy itself. Without lock support (ENOLCK, a disabled cache) the claim is empty: the
    // bake goes ahead, same result, the work maybe done twice.
    class Claim {
    public:
        Claim() = default;
        Claim(Claim&& other) noexcept;
        Claim& operator=(Claim&& other) noexcept;
        Claim(const Claim&) = delete;
        Claim& operator=(const Claim&) = delete;
        ~Claim();
        bool held() const { return fd_ >= 0; }

    private:
        friend class ProxyCache;
        void release() noexcept;
        int fd_ = -1;
        std::filesystem::path file_;
    };
    Claim claim(std::uint64_t key, const Progress& progress = {}) const;

private:
    std::filesystem::path folder_;
};

// The byte encoding used by the cache files (exposed for tests).
std::vector<std::uint8_t> encodeProxy(std::uint64_t key, const ProxyMesh& mesh);
std::optional<ProxyMesh> decodeProxy(std::uint64_t key, const std::vector<std::uint8_t>& bytes);

} // namespace hlod
