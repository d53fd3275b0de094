// Shared by the subcommands: turn positional SCENE arguments into a loaded scene (the embedded
// sample scene when none is given), with import progress on stderr.
#pragma once

#include <string>
#include <vector>

#include "pipeline/io/Import.h"

namespace hlod::cli {

struct LoadedScene {
    Scene scene;
    std::vector<std::string> inputs; // as given, or {"sample:plant"}
    std::uintmax_t fileBytes = 0;    // total size of the source files
};

LoadedScene loadSceneArgs(const std::vector<std::string>& positionals,
                          const ImportOptions& options);

} // namespace hlod::cli
