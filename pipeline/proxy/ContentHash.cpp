// Single-lane variant of the xxHash64 round/avalanche structure (see ContentHash.h).
#include "pipeline/proxy/ContentHash.h"

#include <cstring>

namespace hlod {

namespace {

constexpr std::uint64_t kPrime1 = 0x9E3779B185EBCA87ull;
constexpr std::uint64_t kPrime2 = 0xC2B2AE3D27D4EB4Full;
constexpr std::uint64_t kPrime3 = 0x165667B19E3779F9ull;
constexpr std::uint64_t kPrime4 = 0x85EBCA77C2B2AE63ull;
constexpr std::uint64_t kPrime5 = 0x27D4EB2F165667C5ull;

constexpr std::uint64_t rotl(std::uint64_t x, int r) { return (x << r) | (x >> (64 - r)); }

} // namespace

ContentHash::ContentHash(std::uint64_t seed) : state_(seed + kPrime5) {}

void ContentHash::mixWord(std::uint64_t word) {
    // xxHash64's round, then its merge step, so every bit of the word reaches the state.
    word *= kPrime2;
    word = rotl(word, 31);
    word *= kPrime1;
    state_ ^= word;
    state_ = rotl(state_, 27) * kPrime1 + kPrime4;
}

void ContentHash::add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    length_ += size;
    // Complete a partial word first so splitting the input never changes the value.
    while (pendingBytes_ != 0 && size > 0) {
        pending_ |= static_cast<std::uint64_t>(*bytes++) << (8 * pendingBytes_);
        --size;
        if (++pendingBytes_ == 8) {
            mixWord(pending_);
            pending_ = 0;
            pendingBytes_ = 0;
        }
    }
    while (size >= 8) {
        std::uint64_t word;
        std::memcpy(&word, bytes, 8);
        mixWord(word);
        bytes += 8;
        size -= 8;
    }
    for (; size > 0; --size) {
        pending_ |= static_cast<std::uint64_t>(*bytes++) << (8 * pendingBytes_);
        ++pendingBytes_;
    }
}

std::uint64_t ContentHash::digest() const {
    std::uint64_t h = state_;
    if (pendingBytes_ != 0) {
        h ^= (pending_ * kPrime5);
        h = rotl(h, 11) * kPrime1;
    }
    h += length_;
    // xxHash64 avalanche.
    h ^= h >> 33;
    h *= kPrime2;
    h ^= h >> 29;
    h *= kPrime3;
    h ^= h >> 32;
    return h;
}

std::uint64_t hashBytes(const void* data, std::size_t size, std::uint64_t seed) {
    ContentHash h(seed);
    h.add(data, size);
    return h.digest();
}

std::string toHex(std::uint64_t value) {
    static const char* digits = "0123456789abcdef";
    std::string out(16, '0');
    for (int i = 15; i >= 0; --i) {
        out[static_cast<std::size_t>(i)] = digits[value & 0xf];
        value >>= 4;
    }
    return out;
}

} // namespace hlod
