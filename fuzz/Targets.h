// The fuzzed reader calls, one function per target, shared by the libFuzzer entry points
// (fuzz/fuzz_<target>.cpp) and the regression tests that replay every input checked in under
// fuzz/regressions/<target>/ (tests/pipeline/fuzz/FuzzRegressionTest.cpp).
//
// Each function feeds one input to a reader and checks the reader's contract (FuzzUtil.h):
// hlod::Error for bad input, consistent results for accepted input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz/FuzzUtil.h"
#ifndef HLOD_FUZZ_NO_PROJECT
#include "pipeline/doc/ProjectFile.h"
#endif
#include "pipeline/export/Package.h"
#include "pipeline/io/Import.h"
#include "pipeline/proxy/ContentHash.h"
#include "pipeline/proxy/ProxyCache.h"
#include "pipeline/scene/SceneBinary.h"
#include "pipeline/select/CameraPath.h"

namespace hlod::fuzz {

namespace detail {

inline void check(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "accepted input is inconsistent: %s\n", what);
    std::abort();
}

inline bool safeName(std::string_view name) {
    if (name.empty() || name.size() > 96 || name.front() == '/') return false;
    if (name.find("..") != std::string_view::npos) return false;
    for (char c : name) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                        (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-' || c == '/';
        if (!ok) return false;
    }
    return true;
}

// A package input holds a whole folder as sections "%%HLOD%% <relative path>\n<bytes>"
// (fuzz/pack_package.py makes one from a folder). Names are sanitised so a mutated name can
// only miss, never write outside the scratch folder. False when no section was usable.
inline bool unpackFolder(std::string_view in, const std::filesystem::path& dir) {
    constexpr std::string_view kMark = "%%HLOD%% ";
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
    std::filesystem::create_directories(dir);
    int files = 0;
    std::size_t at = in.find(kMark);
    while (at != std::string_view::npos && files < 32) {
        const std::size_t nameStart = at + kMark.size();
        const std::size_t eol = in.find('\n', nameStart);
        if (eol == std::string_view::npos) break;
        const std::size_t next = in.find(kMark, eol + 1);
        const std::string_view name = in.substr(nameStart, eol - nameStart);
        const std::size_t end = next == std::string_view::npos ? in.size() : next;
        const std::string_view body = in.substr(eol + 1, end - eol - 1);
        if (safeName(name)) {
            const std::filesystem::path file = dir / std::string(name);
            std::filesystem::create_directories(file.parent_path(), ec);
            std::ofstream(file, std::ios::binary)
                .write(body.data(), static_cast<std::streamsize>(body.size()));
            ++files;
        }
        at = next;
    }
    return files > 0;
}

} // namespace detail

// glTF / GLB import: our accessor, meshopt, transform and validation code over tinygltf.
// Inputs starting with '{' are written as .gltf (JSON with data: URIs), others as .glb.
inline void gltf(const std::uint8_t* data, std::size_t size) {
    const bool json = size > 0 && data[0] == '{';
    const auto file = writeInput(json ? "in.gltf" : "in.glb", data, size);
    ImportOptions options;
    // Small limits keep single runs fast; the refusal paths are what counts.
    options.limits.maxElements = 1'000'000;
    options.limits.maxUniqueTriangles = 1'000'000;
    options.limits.maxTexels = 16u << 20;
    expectOnlyHlodErrors([&] { (void)importGltf(file, options); });
}

// Scene validation (Validate.cpp), which every importer's output goes through, fed by the
// scene wire format the isolated importers send back from their child (SceneBinary.cpp).
// A validated scene must have computable statistics and bounds.
inline void scene(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    expectOnlyHlodErrors([&] {
        const Scene s = readSceneBinary(bytes, "fuzz.scene");
        validateScene(s, "fuzz.scene");
        (void)s.stats();
        (void)s.worldBounds();
    });
}

// Camera-path JSON (CameraPath.cpp). An accepted path must also sample.
inline void cameraPath(const std::uint8_t* data, std::size_t size) {
    const auto file = writeInput("path.json", data, size);
    expectOnlyHlodErrors([&] {
        const CameraPath path = readCameraPath(file);
        (void)sampleCameraPath(path, 8, 30.0, 64, 48);
    });
}

#ifndef HLOD_FUZZ_NO_PROJECT
// `.hlodproj` project files (ProjectFile.cpp: JSON, pipeline graph, parameters, hand edits).
// Left out of the sanitized CI build (HLOD_FUZZ_NO_PROJECT): the graph links every step.
inline void project(const std::uint8_t* data, std::size_t size) {
    const auto file = writeInput("in.hlodproj", data, size);
    expectOnlyHlodErrors([&] { (void)openProject(file); });
}
#endif

// Bake-cache entries (ProxyCache.cpp): a corrupt or truncated entry must be a miss (and then
// rebaked), never trusted. Whatever decodeProxy accepts must be a consistent mesh that encodes
// back to an entry decoding to the same mesh. Input: one control byte, then the entry. The
// checksum over the entry would stop almost every mutation at the door, so when the control
// byte is odd the entry's last 8 bytes are replaced by the right checksum first (the decoder's
// own checks are then what is fuzzed); even, the entry is taken as is. The key is taken from
// the entry itself (magic 8, version 4, flags 4, key 8) so mutations reach past the key check.
inline void proxyCache(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return;
    std::vector<std::uint8_t> bytes(data + 1, data + size);
    if ((data[0] & 1) != 0 && bytes.size() >= 8) {
        const std::uint64_t sum = hashBytes(bytes.data(), bytes.size() - 8);
        std::memcpy(bytes.data() + bytes.size() - 8, &sum, 8);
    }
    std::uint64_t key = 0;
    if (bytes.size() >= 24) std::memcpy(&key, bytes.data() + 16, 8);
    expectOnlyHlodErrors([&] {
        const auto mesh = decodeProxy(key, bytes);
        if (!mesh) return;
        const std::size_t n = mesh->positions.size();
        detail::check(mesh->indices.size() % 3 == 0, "index count");
        for (std::uint32_t i : mesh->indices)
            detail::check(i < n, "index out of range");
        detail::check(mesh->normals.empty() || mesh->normals.size() == n, "normals");
        detail::check(mesh->colors.size() == n, "colours");
        const auto again = decodeProxy(key, encodeProxy(key, *mesh));
        detail::check(again && again->positions.size() == n && again->indices == mesh->indices,
                      "re-encoded entry differs");
    });
}

// The package reader (PackageReader.cpp): hlod.json, tileset.json and the tile GLBs
// (KHR_mesh_quantization, EXT_meshopt_compression) decoded by readPackageScene.
inline void package(const std::uint8_t* data, std::size_t size) {
    const std::filesystem::path dir = scratchDir() / "package";
    const std::string_view in(reinterpret_cast<const char*>(data), size);
    if (!detail::unpackFolder(in, dir)) return;
    expectOnlyHlodErrors([&] {
        const PackageInfo info = readPackage(dir);
        (void)info.tree.height(); // what `hlod info PACKAGE` walks
        (void)info.tree.leafCount();
        (void)readPackageScene(info);
    });
}

} // namespace hlod::fuzz
