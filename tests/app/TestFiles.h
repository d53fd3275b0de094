// Files the CLI tests read back: the web tooling's scripts (tests/web) and PNG frames.
#pragma once

#include <filesystem>
#include <string>

#include "pipeline/eval/ImageError.h"

namespace hlod::test {

// The path of tests/web/NAME (validators and runtime renderers run with node).
std::string webScript(const char* name);

// An RGB image read from a PNG; empty (width 0) when the file cannot be read.
RgbImage readPng(const std::filesystem::path& file);

} // namespace hlod::test
