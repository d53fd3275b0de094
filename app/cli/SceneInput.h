// Shared by the subcommands: turn positional SCENE arguments into a loaded scene (the embedded
// sample scene when none is given), with import progress on stderr. A folder holding an
// exported package (hlod.json + tileset.json) is read back as a package.
#pragma once

#include <string>
#include <vector>

#include <optional>

#include "Args.h"
#include "pipeline/export/Package.h"
#include "pipeline/io/Import.h"

namespace hlod::cli {

struct LoadedScene {
    Scene scene;
    std::vector<std::string> inputs;    // as given, or {"sample:plant"}
    std::uintmax_t fileBytes = 0;       // total size of the source files
    std::optional<PackageInfo> package; // set when the input is an exported HLOD package
};

// The import options (--deflection, --brep-unit: the Import parameters' declarations in
// pipeline/graph/Parameters.h) given on the command line, defaults for the rest.
ImportOptions importOptionsFromArgs(const Args& args);

LoadedScene loadSceneArgs(const std::vector<std::string>& positionals,
                          const ImportOptions& options);

} // namespace hlod::cli
