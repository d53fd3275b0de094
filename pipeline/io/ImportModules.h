// The importers built as on-demand modules (core/OnDemand.h): OpenCASCADE's STEP/IGES/BREP
// reader in libhlod-cad.so, assimp's formats in libhlod-assimp.so. importCad and importAssimp
// (Import.h) load them; these are the functions the modules implement.
#pragma once

#include <filesystem>

#include "pipeline/core/Progress.h"
#include "pipeline/io/Import.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct CadModule {
    Scene (*importCad)(const std::filesystem::path& file, const ImportOptions& options,
                       const Progress& progress);
};

struct AssimpModule {
    Scene (*importAssimp)(const std::filesystem::path& file, const ImportOptions& options);
};

// The modules' own implementations (CadImporter.cpp, AssimpImporter.cpp).
Scene importCadHere(const std::filesystem::path& file, const ImportOptions& options,
                    const Progress& progress);
Scene importAssimpHere(const std::filesystem::path& file, const ImportOptions& options);

} // namespace hlod

extern "C" const hlod::CadModule* hlod_module_cad();
extern "C" const hlod::AssimpModule* hlod_module_assimp();
