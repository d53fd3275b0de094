// Content-addressed proxy files with atomic replace (write temp + rename), see ProxyCache.h.
#include "pipeline/proxy/ProxyCache.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <thread>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "pipeline/core/AtomicFile.h"
#include "pipeline/core/Error.h"
#include "pipeline/io/ImageDecode.h"
#include "pipeline/proxy/ContentHash.h"

namespace hlod {

namespace {

constexpr char kMagic[8] = {'H', 'L', 'O', 'D', 'P', 'R', 'X', '\0'};
constexpr std::uint32_t kVersion = 3; // 3: the error bound after the origin
constexpr std::uint32_t kHasNormals = 1;
constexpr std::uint32_t kHasAtlas = 2; // uvs, then mask byte, mime type, encoded image
constexpr std::size_t kHeaderBytes = 8 + 4 + 4 + 8 + 8 + 8 + 3 * 8 + 4;

template <class T> void put(std::vector<std::uint8_t>& out, const T& value) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
    out.insert(out.end(), p, p + sizeof(T));
}

template <class T> void putArray(std::vector<std::uint8_t>& out, const std::vector<T>& values) {
    if (values.empty()) return;
    const auto* p = reinterpret_cast<const std::uint8_t*>(values.data());
    out.insert(out.end(), p, p + values.size() * sizeof(T));
}

class Reader {
public:
    explicit Reader(const std::vector<std::uint8_t>& bytes) : bytes_(bytes) {}
    template <class T> bool get(T& value) {
        if (bytes_.size() - pos_ < sizeof(T)) return false;
        std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
        pos_ += sizeof(T);
        return true;
    }
    template <class T> bool getArray(std::vector<T>& values, std::uint64_t count) {
        if (count > (bytes_.size() - pos_) / sizeof(T)) return false;
        values.resize(count);
        if (count) std::memcpy(values.data(), bytes_.data() + pos_, count * sizeof(T));
        pos_ += count * sizeof(T);
        return true;
    }
    std::size_t position() const { return pos_; }

private:
    const std::vector<std::uint8_t>& bytes_;
    std::size_t pos_ = 0;
};

// The atlas part of a cache file; the image is decoded from the stored bytes, as the bake
// itself does (ProxyAtlas), so a cached proxy shows exactly what a fresh one shows.
bool readAtlas(Reader& r, ProxyMesh& m, std::uint64_t vertices) {
    auto atlas = std::make_shared<ProxyAtlas>();
    std::uint8_t mask = 0;
    std::uint64_t mimeBytes = 0, imageBytes = 0;
    std::vector<char> mime;
    if (!r.getArray(m.uvs, vertices) || !r.get(mask) || !r.get(mimeBytes) ||
        !r.getArray(mime, mimeBytes) || !r.get(imageBytes) ||
        !r.getArray(atlas->encoded, imageBytes))
        return false;
    atlas->mask = mask != 0;
    atlas->mimeType.assign(mime.begin(), mime.end());
    // Our bakes store PNG or JPEG only; anything else is not an entry of ours (and would reach
    // decoders a cache never needs: fuzz_proxy_cache found a PNM header overflowing in stb).
    const auto& e = atlas->encoded;
    const bool png = e.size() >= 8 && e[0] == 0x89 && e[1] == 'P' && e[2] == 'N' && e[3] == 'G';
    const bool jpeg = e.size() >= 3 && e[0] == 0xFF && e[1] == 0xD8 && e[2] == 0xFF;
    if (!(png && atlas->mimeType == "image/png") && !(jpeg && atlas->mimeType == "image/jpeg"))
        return false;
    std::string why;
    auto image = decodeImage(atlas->encoded, why);
    if (!image) return false;
    atlas->image = std::make_shared<const RgbaImage>(std::move(*image));
    m.atlas = std::move(atlas);
    return true;
}

} // namespace

std::vector<std::uint8_t> encodeProxy(std::uint64_t key, const ProxyMesh& mesh) {
    std::vector<std::uint8_t> out;
    const bool normals = mesh.normals.size() == mesh.positions.size() && !mesh.positions.empty();
    out.reserve(kHeaderBytes + mesh.positions.size() * (normals ? 28 : 16) +
                mesh.indices.size() * 4 + 8);
    out.resize(sizeof kMagic);
    std::memcpy(out.data(), kMagic, sizeof kMagic);
    const bool atlas = mesh.hasAtlas();
    put(out, kVersion);
    put(out, (normals ? kHasNormals : 0u) | (atlas ? kHasAtlas : 0u));
    put(out, key);
    put(out, static_cast<std::uint64_t>(mesh.positions.size()));
    put(out, static_cast<std::uint64_t>(mesh.indices.size()));
    put(out, mesh.origin);
    put(out, mesh.errorBound);
    putArray(out, mesh.positions);
    if (normals) putArray(out, mesh.normals);
    if (mesh.colors.size() == mesh.positions.size()) {
        putArray(out, mesh.colors);
    } else {
        out.insert(out.end(), mesh.positions.size() * 4, 255);
    }
    putArray(out, mesh.indices);
    if (atlas) {
        putArray(out, mesh.uvs);
        put(out, static_cast<std::uint8_t>(mesh.atlas->mask ? 1 : 0));
        put(out, static_cast<std::uint64_t>(mesh.atlas->mimeType.size()));
        out.insert(out.end(), mesh.atlas->mimeType.begin(), mesh.atlas->mimeType.end());
        put(out, static_cast<std::uint64_t>(mesh.atlas->encoded.size()));
        putArray(out, mesh.atlas->encoded);
    }
    put(out, hashBytes(out.data(), out.size()));
    return out;
}

std::optional<ProxyMesh> decodeProxy(std::uint64_t key, const std::vector<std::uint8_t>& bytes) {
    if (bytes.size() < kHeaderBytes + 8 || std::memcmp(bytes.data(), kMagic, 8) != 0) {
        return std::nullopt;
    }
    std::uint64_t stored = 0;
    std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
    if (stored != hashBytes(bytes.data(), bytes.size() - 8)) return std::nullopt;
    Reader r(bytes);
    char magic[8];
    std::uint32_t version = 0, flags = 0;
    std::uint64_t fileKey = 0, vertices = 0, indices = 0;
    ProxyMesh m;
    if (!r.get(magic) || !r.get(version) || !r.get(flags) || !r.get(fileKey) || !r.get(vertices) ||
        !r.get(indices) || !r.get(m.origin) || !r.get(m.errorBound)) {
        return std::nullopt;
    }
    if (!(m.errorBound >= 0.0f) || !std::isfinite(m.errorBound)) return std::nullopt;
    if (version != kVersion || fileKey != key || indices % 3 != 0) return std::nullopt;
    if (!r.getArray(m.positions, vertices)) return std::nullopt;
    if ((flags & kHasNormals) && !r.getArray(m.normals, vertices)) return std::nullopt;
    if (!r.getArray(m.colors, vertices) || !r.getArray(m.indices, indices)) return std::nullopt;
    if ((flags & kHasAtlas) && !readAtlas(r, m, vertices)) return std::nullopt;
    if (r.position() + 8 != bytes.size()) return std::nullopt;
    for (std::uint32_t i : m.indices) {
        if (i >= vertices) return std::nullopt;
    }
    return m;
}

ProxyCache::ProxyCache(std::filesystem::path folder) : folder_(std::move(folder)) {}

std::filesystem::path ProxyCache::fileFor(std::uint64_t key) const {
    return folder_ / (toHex(key) + ".hlodproxy");
}

std::optional<ProxyMesh> ProxyCache::load(std::uint64_t key, bool* damaged) const {
    if (damaged) *damaged = false;
    if (!enabled()) return std::nullopt;
    std::ifstream in(fileFor(key), std::ios::binary);
    if (!in) return std::nullopt;
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
    std::optional<ProxyMesh> mesh = decodeProxy(key, bytes);
    if (!mesh && damaged) *damaged = true;
    return mesh;
}

ProxyCache::Claim::Claim(Claim&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), file_(std::move(other.file_)) {}

ProxyCache::Claim& ProxyCache::Claim::operator=(Claim&& other) noexcept {
    if (this != &other) {
        release();
        fd_ = std::exchange(other.fd_, -1);
        file_ = std::move(other.file_);
    }
    return *this;
}

ProxyCache::Claim::~Claim() { release(); }

void ProxyCache::Claim::release() noexcept {
    if (fd_ < 0) return;
    // Unlink while still holding the lock: a waiter that then gets the lock sees that its
    // file is no longer the one at the path and starts over (claim() below).
    ::unlink(file_.c_str());
    ::close(fd_);
    fd_ = -1;
}

ProxyCache::Claim ProxyCache::claim(std::uint64_t key, const Progress& progress) const {
    Claim c;
    if (!enabled()) return c;
    std::error_code ec;
    std::filesystem::create_directories(folder_, ec);
    const std::filesystem::path file = folder_ / (toHex(key) + ".lock");
    auto wait = std::chrono::milliseconds(5);
    for (;;) {
        const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0) return c; // read-only folder: store() will say so
        struct flock lock {};
        lock.l_type = F_WRLCK;
        lock.l_whence = SEEK_SET;
        // Polled rather than blocking (F_SETLKW), so a cancel is seen while waiting.
        while (::fcntl(fd, F_SETLK, &lock) != 0) {
            if (errno != EACCES && errno != EAGAIN && errno != EINTR) {
                ::close(fd); // ENOLCK and the like: no locks on this file system
                return c;
            }
            if (progress.cancelled()) {
                ::close(fd);
                progress.throwIfCancelled();
            }
            std::this_thread::sleep_for(wait);
            wait = std::min(wait * 2, std::chrono::milliseconds(200));
        }
        struct stat held {
        }, current{};
        if (::fstat(fd, &held) == 0 && ::stat(file.c_str(), &current) == 0 &&
            held.st_dev == current.st_dev && held.st_ino == current.st_ino) {
            c.fd_ = fd;
            c.file_ = file;
            return c;
        }
        ::close(fd); // the holder removed that file when it finished: take the new one
    }
}

void ProxyCache::store(std::uint64_t key, const ProxyMesh& mesh) const {
    if (!enabled()) return;
    const std::filesystem::path target = fileFor(key);
    std::error_code ec;
    std::filesystem::create_directories(folder_, ec);
    if (ec) throw Error(ErrorCode::Io, folder_, "cannot create cache folder: " + ec.message());
    const std::vector<std::uint8_t> bytes = encodeProxy(key, mesh);
    writeFileAtomic(target,
                    std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

} // namespace hlod
