// One file per encoded image, checked on load, see EncodedImageCache.h.
#include "pipeline/export/EncodedImageCache.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <libdeflate.h>

#include "pipeline/core/AtomicFile.h"
#include "pipeline/core/Error.h"
#include "pipeline/proxy/ContentHash.h"

namespace hlod {

namespace {

constexpr char kMagic[8] = {'H', 'L', 'O', 'D', 'I', 'M', 'G', '\0'};
constexpr std::size_t kHeaderBytes = 8 + 8 + 8 + 8 + 1; // magic, key, length, hash, mime

template <class T> void put(std::string& out, const T& value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

} // namespace

ContentHash imageCacheKey(std::string_view kind) {
    ContentHash h(kImageCacheVersion);
    h.addString(LIBDEFLATE_VERSION_STRING);
    h.addString(kind);
    return h;
}

std::filesystem::path imageCacheFolder(const std::filesystem::path& proxyCacheDir) {
    return proxyCacheDir.empty() ? proxyCacheDir : proxyCacheDir / "images";
}

std::filesystem::path EncodedImageCache::fileFor(std::uint64_t key) const {
    return folder_ / (toHex(key) + ".hlodimage");
}

std::optional<EncodedImage> EncodedImageCache::load(std::uint64_t key) const {
    if (!enabled()) return std::nullopt;
    std::ifstream in(fileFor(key), std::ios::binary);
    if (!in) return std::nullopt;
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
    if (bytes.size() < kHeaderBytes || std::memcmp(bytes.data(), kMagic, 8) != 0)
        return std::nullopt;
    std::uint64_t storedKey = 0, length = 0, hash = 0;
    std::memcpy(&storedKey, bytes.data() + 8, 8);
    std::memcpy(&length, bytes.data() + 16, 8);
    std::memcpy(&hash, bytes.data() + 24, 8);
    const char mime = bytes[32];
    if (storedKey != key || length != bytes.size() - kHeaderBytes || (mime != 'p' && mime != 'j'))
        return std::nullopt;
    EncodedImage image;
    image.bytes.assign(bytes.begin() + kHeaderBytes, bytes.end());
    if (image.bytes.empty() || hashBytes(image.bytes.data(), image.bytes.size()) != hash)
        return std::nullopt;
    image.mimeType = mime == 'p' ? "image/png" : "image/jpeg";
    ++hits_;
    return image;
}

void EncodedImageCache::store(std::uint64_t key, const EncodedImage& image) const {
    if (!enabled() || image.bytes.empty()) return;
    if (image.mimeType != "image/png" && image.mimeType != "image/jpeg") return;
    std::string out;
    out.reserve(kHeaderBytes + image.bytes.size());
    out.append(kMagic, 8);
    put(out, key);
    put(out, static_cast<std::uint64_t>(image.bytes.size()));
    put(out, hashBytes(image.bytes.data(), image.bytes.size()));
    out.push_back(image.mimeType == "image/png" ? 'p' : 'j');
    out.append(reinterpret_cast<const char*>(image.bytes.data()), image.bytes.size());
    std::error_code ec;
    std::filesystem::create_directories(folder_, ec);
    if (ec) return; // best effort: the export has the bytes
    try {
        writeFileAtomic(fileFor(key), out);
    } catch (const Error&) {
        // A full disk or a read-only cache costs the next export the encoding, nothing else.
    }
}

} // namespace hlod
