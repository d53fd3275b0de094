// Encoded texture images kept between exports: the PNG of a page of stacked leaf textures
// (StackedAtlas.h) or of a source texture converted for glTF (TextureImage.h) is a pure function
// of its pixels or source bytes, and deflating it at the level packages use is the slowest step
// of a rebuild whose proxies all come from the cache (torcs-spring: 0.73 of 1.4 s). Files live
// in a folder of the proxy cache, one per key: "<key>.hlodimage" holding a magic, the key, the
// length and hash of the encoded bytes, the MIME type and the bytes.
// Keys: the caller's hash of everything the bytes depend on, started by imageCacheKey (the
// cache's version and the PNG encoder's: a newer libdeflate may deflate the same pixels to other
// bytes, and a cached file must never stand in for what this build would write).
// A file that is short, damaged or holds another key is a miss (and is replaced by the next
// store); a store that cannot be written is skipped (the export has the bytes already), so the
// cache never changes what an export writes, only how long it takes. Writes are atomic (temp +
// rename): concurrent processes sharing the folder see whole files or none. One object per
// export (its hit count is not synchronised).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>

#include "pipeline/io/TextureImage.h"
#include "pipeline/proxy/ContentHash.h"

namespace hlod {

// Bumped whenever the bytes an encoder writes for the same input change.
inline constexpr std::uint64_t kImageCacheVersion = 1;

// A key's hash, started with the versions above and `kind` (what the bytes are of).
ContentHash imageCacheKey(std::string_view kind);

class EncodedImageCache {
public:
    // An empty folder disables the cache (load misses, store does nothing).
    explicit EncodedImageCache(std::filesystem::path folder = {}) : folder_(std::move(folder)) {}

    bool enabled() const { return !folder_.empty(); }
    std::optional<EncodedImage> load(std::uint64_t key) const;
    void store(std::uint64_t key, const EncodedImage& image) const;
    std::filesystem::path fileFor(std::uint64_t key) const;

    // Lookups answered from the folder (for tests and statistics).
    std::size_t hits() const { return hits_; }

private:
    std::filesystem::path folder_;
    mutable std::size_t hits_ = 0;
};

// The folder of the image cache inside a proxy cache folder (empty stays empty).
std::filesystem::path imageCacheFolder(const std::filesystem::path& proxyCacheDir);

} // namespace hlod
