// The help of `hlod`, generated from the command table (CommandSpec.h) and the parameter
// declarations (pipeline/graph/Parameters.h): every flag with its value, what it does, its
// default, unit and range. `hlod --help` is also the source of the man page (help2man).
#pragma once

#include <string>
#include <vector>

#include "CommandSpec.h"

namespace hlod::cli {

// The synopsis of every command and where to find more (what `hlod` alone prints).
std::string shortUsage();
// Everything: the overview and the help of every command (`hlod --help`, `hlod help`).
std::string fullHelp();
// One command: synopsis, what it does, operands, every flag (`hlod help build`,
// `hlod build --help`).
std::string commandHelp(const CommandSpec& command);

// The help line of a parameter's flag: "--screen-size PX" and "Projected diameter ... Default
// 300 px; 1 to 100000 px." (no default for an empty path or text, choices for an enum).
std::string flagOf(const ParamDecl& decl);
std::string describe(const ParamDecl& decl);

// The candidate closest to `word` when it is close enough to be a likely typo (edit distance
// at most a third of its length, at least 1, at most 3), else empty.
std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates);

} // namespace hlod::cli
