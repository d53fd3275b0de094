// Heavy third-party libraries loaded only by the steps that use them.
//
// Why: linking OpenVDB, OpenCASCADE and assimp into every process cost 62 MB of resident
// memory before main() (measured with /proc/PID/smaps on `hlod --help`: OpenVDB's dynamic
// symbol table alone is 26 MB, read in full by the loader to resolve its 61,000 symbol
// relocations; OCCT's 24 toolkits 25 MB; assimp 4 MB). A farm shard, a clustering run or a
// decimate bake never touches them; every process paid for them.
// How: their code is built into modules (libhlod-cad.so: STEP/IGES; libhlod-assimp.so: the
// assimp formats; libhlod-vdb.so: the voxel shell of the remesh method). Each module exports
// one C function, hlod_module_NAME(), returning a table of plain C++ function pointers
// (the *Module structs of pipeline/io/ImportModules.h and pipeline/proxy/VoxelShell.h);
// onDemandModule() loads the module the first time it is asked for and keeps it loaded.
// The importers run in a forked child (IsolatedImport.h), so OCCT and assimp load there only.
// Where modules are looked for: only in $HLOD_MODULE_DIR when it is set; else, first found
// wins, the folder of the running program, ../lib/hlod-studio next to it (the installed
// layout: /usr/bin and /usr/lib/hlod-studio), the build tree's module folder
// (HLOD_BUILD_MODULE_DIR, for the tests and programs run from the build tree).
// Builds with HLOD_STATIC_MODULES (the sanitized fuzz build) link the module code into the
// program instead and call it directly.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace hlod {

// The module table of libhlod-NAME.so (its hlod_module_NAME()); throws hlod::Error naming the
// module file, what it is for and the loader's message when it cannot be loaded.
const void* onDemandModule(const std::string& name, const std::string& purpose);

// Where the running program's companions are: its own folder and ../lib/hlod-studio next to it
// (the installed layout), in that order; empty when /proc/self/exe cannot be read.
std::vector<std::filesystem::path> programFolders();

} // namespace hlod

// The table of module NAME as an `Api` (a struct of function pointers).
#if defined(HLOD_STATIC_MODULES)
#define HLOD_ON_DEMAND(Api, name, purpose) (*hlod_module_##name())
#else
#define HLOD_ON_DEMAND(Api, name, purpose)                                                         \
    (*static_cast<const Api*>(::hlod::onDemandModule(#name, purpose)))
#endif

// Defines a module's entry (in the module's own source file).
#define HLOD_MODULE_ENTRY(Api, name, ...)                                                          \
    extern "C" __attribute__((visibility("default"))) const Api* hlod_module_##name() {            \
        static const Api table{__VA_ARGS__};                                                       \
        return &table;                                                                             \
    }
