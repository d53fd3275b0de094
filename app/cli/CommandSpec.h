// What a `hlod` subcommand takes, as data: its synopsis, what it does, its operands, the
// pipeline parameters whose flags it accepts (by node kind, from the declarations in
// pipeline/graph/Parameters.h) and its own flags. The parser (Args.h) accepts exactly these
// flags and the help (Usage.h) lists exactly these, so the two cannot drift apart.
#pragma once

#include <string>
#include <vector>

#include "pipeline/graph/Parameters.h"

namespace hlod::cli {

using CommandArgs = std::vector<std::string>;

// A flag of the command itself (not a pipeline parameter).
struct OptionSpec {
    std::string flag;        // "--out"
    std::string alias;       // "-o", empty when none
    std::string value;       // placeholder of the value ("DIR"); empty for a switch
    std::string help;        // one sentence
    std::string defaultText; // "640x360"; empty when there is none to state
};

struct CommandSpec {
    std::string name;
    int (*run)(const CommandArgs&) = nullptr;
    std::vector<std::string> synopsis; // "hlod info [SCENE|DIR|PACKAGE...] [options]"
    std::string summary;               // what it does
    std::vector<std::pair<std::string, std::string>> operands; // name, meaning
    std::vector<NodeKind> kinds;                               // parameters whose flags it takes
    std::vector<OptionSpec> options;                           // its own flags
    // Single declared parameters (by key) it takes besides those of `kinds`: `hlod bench` bakes
    // with a few Bake and Cluster parameters, checked and documented by their declarations.
    std::vector<std::string> params = {};
};

// Every subcommand, in help order; the one named `name` (nullptr / throws InvalidArgument).
const std::vector<CommandSpec>& commands();
const CommandSpec* findCommand(const std::string& name);
const CommandSpec& command(const std::string& name);

} // namespace hlod::cli
