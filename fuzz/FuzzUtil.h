// Shared by the libFuzzer targets (fuzz/*.cpp): the readers under test take paths, so each input
// is written to a file in a private temporary folder first.
//
// The contract being fuzzed (pipeline/core/Error.h): bad input makes a reader throw hlod::Error
// with a message naming the file; anything else (a crash, a sanitizer report, another
// exception type escaping, a hang) is a finding. `expectOnlyHlodErrors` turns an escaping
// foreign exception into an abort so libFuzzer records the input.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>
#include <string_view>

#include <unistd.h>

#include "pipeline/core/Error.h"

namespace hlod::fuzz {

// A folder of its own per process (libFuzzer -jobs/-workers run several).
inline const std::filesystem::path& scratchDir() {
    static const std::filesystem::path dir = [] {
        const char* base = std::getenv("HLOD_FUZZ_TMP");
        std::filesystem::path d = base ? base : "/tmp";
        d /= "hlod-fuzz-" + std::to_string(::getpid());
        std::filesystem::create_directories(d);
        return d;
    }();
    return dir;
}

inline std::filesystem::path writeInput(const std::string& name, const std::uint8_t* data,
                                        std::size_t size) {
    const std::filesystem::path file = scratchDir() / name;
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return file;
}

template <typename F> void expectOnlyHlodErrors(F&& body) {
    try {
        body();
    } catch (const hlod::Error& e) {
        // The expected way to refuse bad input; the message must name the file it is about.
        if (e.file().empty() || e.problem().empty()) {
            std::fprintf(stderr, "hlod::Error without a file or a problem: %s\n", e.what());
            std::abort();
        }
    } catch (const std::bad_alloc&) {
        // libFuzzer's -malloc_limit_mb reports real runaway allocations itself.
    } catch (const std::exception& e) {
        std::fprintf(stderr, "foreign exception escaped a reader: %s\n", e.what());
        std::abort();
    }
}

} // namespace hlod::fuzz
