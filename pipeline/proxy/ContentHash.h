// A stable 64-bit content hash for cache keys (ProxyCache) and file checksums.
//
// Based on the structure of xxHash64 (Y. Collet): 64-bit words mixed with multiply-rotate
// rounds, the byte length folded in, and an avalanche finaliser. It is not xxHash64 itself (one
// lane, not four), so values must only ever be compared with values from this class.
// Stability: the value depends only on the bytes fed and their order, not on how they are split
// into add() calls, on the platform's word size, or on the run. Multi-byte values are fed in
// the machine's byte order; HLOD Studio only targets little-endian machines.
// Not cryptographic: collisions are astronomically unlikely for accidental changes only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace hlod {

class ContentHash {
public:
    explicit ContentHash(std::uint64_t seed = 0);

    void add(const void* data, std::size_t size);
    template <class T> void addValue(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        add(&value, sizeof(T));
    }
    template <class T> void addVector(const std::vector<T>& values) {
        static_assert(std::is_trivially_copyable_v<T>);
        addValue(static_cast<std::uint64_t>(values.size()));
        if (!values.empty()) add(values.data(), values.size() * sizeof(T));
    }
    void addString(std::string_view text) {
        addValue(static_cast<std::uint64_t>(text.size()));
        add(text.data(), text.size());
    }

    std::uint64_t digest() const;

private:
    void mixWord(std::uint64_t word);
    std::uint64_t state_;
    std::uint64_t length_ = 0;
    std::uint64_t pending_ = 0; // bytes not yet forming a full word
    unsigned pendingBytes_ = 0;
};

// One-shot convenience.
std::uint64_t hashBytes(const void* data, std::size_t size, std::uint64_t seed = 0);

// 16 lower-case hex digits.
std::string toHex(std::uint64_t value);

} // namespace hlod
