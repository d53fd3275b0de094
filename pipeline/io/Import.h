// Scene import: one entry point that routes each file to the importer for its format.
//
// Routing: .gltf/.glb -> tinygltf; .step/.stp/.iges/.igs/.brep/.brp -> OpenCASCADE XCAF (never
// assimp, which claims STEP but cannot read it); everything assimp knows -> assimp.
// A folder expands to the loadable files directly inside it (sorted by name).
// Failure: throws hlod::Error naming the file and the problem. Every importer validates what it
// produced (indices in range, finite positions, a tree hierarchy, at least one triangle), so a
// returned Scene is always safe to use.
#pragma once

#include <filesystem>
#include <vector>

#include "pipeline/core/Progress.h"
#include "pipeline/io/ImportLimits.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct ImportOptions {
    // CAD tessellation (OpenCASCADE): linear deflection relative to the shape's bounding-box
    // diagonal, and angular deflection in radians.
    double cadRelativeDeflection = 0.001;
    double cadAngularDeflection = 0.5;
    // Metres per BREP coordinate unit. A .brep file stores no unit; OpenCASCADE tools write
    // millimetres (their default "xstep.cascade.unit"), hence 0.001. The OCCT sample kitchen
    // (data/scenes/occt-kitchen) is the exception: it is modelled in centimetres (0.01).
    // STEP/IGES ignore this: they declare their unit and are converted to metres from it.
    double cadBrepUnitMetres = 0.001;
    // How much work and memory one file may expand into (ImportLimits.h).
    ImportLimits limits;
};

enum class SceneFormat { Gltf, Cad, Assimp, Unknown };

SceneFormat formatForPath(const std::filesystem::path& path);

// True for extensions some importer claims (used to expand folders and for file dialogs).
bool isLoadableExtension(const std::filesystem::path& path);

// The file dialog filter pattern list, e.g. {"*.glb", "*.gltf", ...}.
std::vector<std::string> loadablePatterns();

// The files importScene reads for `inputs`: a folder becomes the loadable files directly inside
// it, sorted by name. Throws Error naming a folder that cannot be listed or holds none.
std::vector<std::filesystem::path> expandInputs(const std::vector<std::filesystem::path>& inputs);

// Loads one or more files (or folders) into one scene. With several inputs, each file's
// content goes under its own child of the root, named after the file.
Scene importScene(const std::vector<std::filesystem::path>& inputs,
                  const ImportOptions& options = {}, const Progress& progress = {});

Scene importGltf(const std::filesystem::path& file, const ImportOptions& options);
Scene importAssimp(const std::filesystem::path& file, const ImportOptions& options);
// CAD tessellation reports per face on `progress` (stage "tessellate": faces done of the faces
// of every distinct part) and stops with Error(Cancelled) when its cancel flag is raised.
Scene importCad(const std::filesystem::path& file, const ImportOptions& options,
                const Progress& progress = {});

// Checks a freshly imported scene and throws Malformed/NoGeometry naming `file`: indices in
// range, positions finite, the hierarchy a tree, at least one triangle.
void validateScene(const Scene& scene, const std::filesystem::path& file);

// Throws TooLarge naming `file` when the scene holds more unique triangles, instances or
// instanced triangles than `limits` allow (ImportLimits.h).
void checkSceneLimits(const Scene& scene, const std::filesystem::path& file,
                      const ImportLimits& limits);

// Refuses a path that escapes `folder` (after resolving "..", symlinks and absolute paths).
// Used for every external reference (buffers, images, material libraries).
bool isInsideFolder(const std::filesystem::path& candidate, const std::filesystem::path& folder);

} // namespace hlod
