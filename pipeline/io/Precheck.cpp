// Header sanity checks: OFF (Princeton shape benchmark format), PLY (Turk's polygon file
// format: "element NAME COUNT" header lines) and binary STL (80-byte header + uint32 count +
// 50 bytes per triangle).
#include "pipeline/io/Precheck.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "pipeline/core/Error.h"
#include "pipeline/io/DaeInstancing.h"

namespace hlod {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
    for (char& c : s)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

void refuse(const fs::path& file, const std::string& what, std::uint64_t declared,
            std::uint64_t size) {
    throw Error(ErrorCode::TooLarge, file,
                "header declares " + std::to_string(declared) + " " + what + " but the file has " +
                    std::to_string(size) + " bytes; refusing to allocate for it");
}

void checkCount(const fs::path& file, const std::string& what, std::uint64_t count,
                std::uint64_t minBytesEach, std::uint64_t fileSize, std::size_t maxElements) {
    if (count > maxElements || count * minBytesEach > fileSize + 16) {
        refuse(file, what, count, fileSize);
    }
}

void precheckOff(const fs::path& file, std::uint64_t size, std::size_t maxElements) {
    // Tokenise the start of the file without comments: [C|N|ST...]OFF nv nf ne.
    std::ifstream in(file);
    std::string line, text;
    for (int lines = 0; lines < 64 && std::getline(in, line); ++lines) {
        text += line.substr(0, line.find('#')) + " ";
    }
    std::istringstream ts(text);
    std::string first;
    if (!(ts >> first)) return;
    if (first.find("OFF") == std::string::npos) ts.seekg(0);
    std::uint64_t nv = 0, nf = 0;
    if (!(ts >> nv >> nf)) return; // let the parser report the syntax error
    // Shortest vertex line "0 0 0\n" is 6 bytes, shortest face "3 0 1 2\n" is 8.
    checkCount(file, "vertices", nv, 6, size, maxElements);
    checkCount(file, "faces", nf, 8, size, maxElements);
}

std::uint64_t plyTypeSize(const std::string& t) {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "double" || t == "float64") return 8;
    return 4;
}

void precheckPly(const fs::path& file, std::uint64_t size, std::size_t maxElements) {
    std::ifstream in(file, std::ios::binary);
    std::string line;
    bool ascii = true;
    std::string element;
    std::uint64_t count = 0, bytesEach = 0;
    auto flush = [&] {
        if (!element.empty()) {
            checkCount(file, element + " elements", count, std::max<std::uint64_t>(bytesEach, 1),
                       size, maxElements);
        }
    };
    for (int lines = 0; lines < 10000 && std::getline(in, line); ++lines) {
        std::istringstream ls(line);
        std::string key;
        ls >> key;
        if (key == "format") {
            std::string f;
            ls >> f;
            ascii = f == "ascii";
        } else if (key == "element") {
            flush();
            ls >> element >> count;
            bytesEach = 0;
        } else if (key == "property") {
            std::string type, countType;
            ls >> type;
            if (type == "list") {
                ls >> countType;
                bytesEach += ascii ? 2 : plyTypeSize(countType);
            } else {
                bytesEach += ascii ? 2 : plyTypeSize(type);
            }
        } else if (key == "end_header") {
            break;
        }
    }
    flush();
}

void precheckStl(const fs::path& file, std::uint64_t size, std::size_t maxElements) {
    std::ifstream in(file, std::ios::binary);
    char head[84] = {};
    in.read(head, sizeof head);
    if (in.gcount() < 84) return; // too short for binary: ASCII or broken, the parser decides
    std::uint32_t n;
    std::memcpy(&n, head + 80, 4);
    // ASCII STL starts with "solid"; a binary file may too, but then its size matches exactly.
    if (lower(std::string(head, 5)) == "solid" && 84ull + 50ull * n != size) return;
    checkCount(file, "triangles", n, 50, size - 84, maxElements);
}

} // namespace

void precheckElementCounts(const fs::path& file, const ImportLimits& limits) {
    const std::size_t maxElements = limits.maxElements;
    std::error_code ec;
    const std::uint64_t size = fs::file_size(file, ec);
    if (ec) return;
    const std::string ext = lower(file.extension().string());
    if (ext == ".off")
        precheckOff(file, size, maxElements);
    else if (ext == ".ply")
        precheckPly(file, size, maxElements);
    else if (ext == ".stl")
        precheckStl(file, size, maxElements);
    else if (ext == ".dae")
        checkDaeInstancing(file, limits);
}

} // namespace hlod
