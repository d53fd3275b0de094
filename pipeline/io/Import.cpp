// Import dispatch: routes each input to its importer, expands folders, and checks the
// preconditions shared by every format (exists, readable, non-empty) so each importer can
// assume a real file.
#include "pipeline/io/Import.h"

#include "pipeline/export/Package.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>

#include "pipeline/core/Error.h"
#include "pipeline/core/OnDemand.h"
#include "pipeline/io/ImportModules.h"
#include "pipeline/io/IsolatedImport.h"

namespace hlod {

namespace fs = std::filesystem;

namespace {

std::string lowerExtension(const fs::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

const std::set<std::string>& gltfExtensions() {
    static const std::set<std::string> s{".gltf", ".glb"};
    return s;
}
const std::set<std::string>& cadExtensions() {
    static const std::set<std::string> s{".step", ".stp", ".iges", ".igs", ".brep", ".brp"};
    return s;
}
// The assimp 5.2 formats we route to assimp (its full importer list minus the ones handled
// above and minus pure animation/skeleton formats that carry no static geometry).
const std::set<std::string>& assimpExtensions() {
    static const std::set<std::string> s{
        ".obj",  ".fbx",     ".dae", ".3ds", ".ply",     ".stl",      ".ac",   ".acc", ".ac3d",
        ".ifc",  ".ifczip",  ".off", ".x",   ".lwo",     ".lws",      ".ase",  ".ask", ".dxf",
        ".ms3d", ".cob",     ".scn", ".xgl", ".zgl",     ".nff",      ".enff", ".raw", ".ter",
        ".hmp",  ".mdl",     ".md2", ".md3", ".md5mesh", ".smd",      ".vta",  ".3d",  ".q3o",
        ".q3s",  ".irrmesh", ".irr", ".sib", ".ogex",    ".3mf",      ".amf",  ".x3d", ".x3db",
        ".wrl",  ".m3d",     ".csm", ".lxo", ".blend",   ".mesh.xml", ".iqm",  ".b3d", ".bsp",
        ".pk3",  ".ndo",     ".uc",  ".mot"};
    return s;
}

void checkReadableFile(const fs::path& file) {
    std::error_code ec;
    const fs::file_status st = fs::status(file, ec);
    if (ec || !fs::exists(st)) throw Error(ErrorCode::FileNotFound, file, "no such file");
    if (fs::is_directory(st)) throw Error(ErrorCode::FileUnreadable, file, "is a folder");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(ErrorCode::FileUnreadable, file, "cannot open for reading");
    const auto size = fs::file_size(file, ec);
    if (ec) throw Error(ErrorCode::FileUnreadable, file, "cannot read the file size");
    if (size == 0) throw Error(ErrorCode::EmptyFile, file, "file is empty (0 bytes)");
}

Scene importFormat(const fs::path& file, const ImportOptions& options, const Progress& progress) {
    switch (formatForPath(file)) {
    case SceneFormat::Gltf:
        return importGltf(file, options);
    case SceneFormat::Cad:
        // OpenCASCADE too: its shape healing can hang on absurd numbers (timeout) and its
        // readers crash on dangling references. Its tessellation reports per face.
        return runIsolated(
            file, [&](const Progress& child) { return importCad(file, options, child); }, {},
            progress);
    case SceneFormat::Assimp:
        // assimp runs out of process: some of its readers crash on bad files.
        return runIsolated(
            file, [&](const Progress&) { return importAssimp(file, options); }, {}, progress);
    case SceneFormat::Unknown:
        break;
    }
    throw Error(ErrorCode::UnknownFormat, file,
                "unknown file extension '" + file.extension().string() + "'");
}

Scene importOne(const fs::path& file, const ImportOptions& options, const Progress& progress) {
    checkReadableFile(file);
    Scene scene = importFormat(file, options, progress);
    checkSceneLimits(scene, file, options.limits);
    return scene;
}

} // namespace

Scene importCad(const fs::path& file, const ImportOptions& options, const Progress& progress) {
    return HLOD_ON_DEMAND(CadModule, cad, "STEP/IGES/BREP import (OpenCASCADE)")
        .importCad(file, options, progress);
}

Scene importAssimp(const fs::path& file, const ImportOptions& options) {
    return HLOD_ON_DEMAND(AssimpModule, assimp, "assimp import").importAssimp(file, options);
}

std::vector<fs::path> expandInputs(const std::vector<fs::path>& inputs) {
    std::vector<fs::path> files;
    for (const fs::path& in : inputs) {
        std::error_code ec;
        if (!fs::is_directory(in, ec)) {
            files.push_back(in);
            continue;
        }
        std::vector<fs::path> inFolder;
        for (const auto& entry : fs::directory_iterator(in, ec)) {
            if (entry.is_regular_file() && isLoadableExtension(entry.path())) {
                inFolder.push_back(entry.path());
            }
        }
        if (ec) throw Error(ErrorCode::FileUnreadable, in, "cannot list the folder");
        if (inFolder.empty()) {
            throw Error(ErrorCode::UnknownFormat, in, "folder holds no loadable scene file");
        }
        std::sort(inFolder.begin(), inFolder.end());
        files.insert(files.end(), inFolder.begin(), inFolder.end());
    }
    return files;
}

SceneFormat formatForPath(const fs::path& path) {
    const std::string ext = lowerExtension(path);
    if (gltfExtensions().count(ext)) return SceneFormat::Gltf;
    if (cadExtensions().count(ext)) return SceneFormat::Cad;
    if (assimpExtensions().count(ext)) return SceneFormat::Assimp;
    return SceneFormat::Unknown;
}

bool isLoadableExtension(const fs::path& path) {
    return formatForPath(path) != SceneFormat::Unknown;
}

std::vector<std::string> loadablePatterns() {
    std::vector<std::string> out;
    for (const auto* set : {&gltfExtensions(), &cadExtensions(), &assimpExtensions()}) {
        for (const std::string& e : *set)
            out.push_back("*" + e);
    }
    return out;
}

bool isInsideFolder(const fs::path& candidate, const fs::path& folder) {
    std::error_code ec;
    const fs::path base = fs::weakly_canonical(fs::absolute(folder), ec);
    if (ec) return false;
    const fs::path target = fs::weakly_canonical(fs::absolute(candidate), ec);
    if (ec) return false;
    auto b = base.begin();
    auto t = target.begin();
    for (; b != base.end(); ++b, ++t) {
        if (t == target.end() || *b != *t) return false;
    }
    return true;
}

Scene importScene(const std::vector<fs::path>& inputs, const ImportOptions& options,
                  const Progress& progress) {
    if (inputs.empty()) throw Error(ErrorCode::InvalidArgument, "no scene file given");
    // An HLOD package (hlod build -o DIR) opens as the scene of its leaf tiles: the originals.
    if (inputs.size() == 1 && isPackageFolder(inputs[0])) {
        progress.emit({"import", 0, 1, inputs[0].filename().string()});
        Scene s = readPackageScene(readPackage(inputs[0]));
        progress.emit({"import", 1, 1, inputs[0].filename().string()});
        return s;
    }
    const std::vector<fs::path> files = expandInputs(inputs);
    if (files.size() == 1) {
        progress.emit({"import", 0, 1, files[0].filename().string()});
        Scene s = importOne(files[0], options, progress);
        progress.emit({"import", 1, 1, files[0].filename().string()});
        return s;
    }
    Scene scene;
    for (std::size_t i = 0; i < files.size(); ++i) {
        progress.throwIfCancelled();
        progress.emit({"import", i, files.size(), files[i].filename().string()});
        scene.append(importOne(files[i], options, progress), files[i].stem().string());
        // The limits hold for what is loaded together, too.
        checkSceneLimits(scene, files[i], options.limits);
    }
    progress.emit({"import", files.size(), files.size(), ""});
    return scene;
}

} // namespace hlod
