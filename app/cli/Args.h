// Minimal command-line parsing for the `hlod` subcommands: positionals, `--name value`,
// `--name=value` and boolean `--switch`. Unknown options are an error (a typo must not be
// silently ignored) that names the closest valid flag ("unknown option --screensize (did you
// mean --screen-size?)").
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "CommandSpec.h"
#include "pipeline/graph/Parameters.h"

namespace hlod::cli {

class Args {
public:
    // `valueOptions` take a value, `switches` do not. Throws hlod::Error(InvalidArgument).
    Args(const std::vector<std::string>& argv, const std::set<std::string>& valueOptions,
         const std::set<std::string>& switches);
    // The flags of `command`: its own and those of the parameters of its node kinds.
    Args(const std::vector<std::string>& argv, const CommandSpec& command);

    const std::vector<std::string>& positionals() const { return positionals_; }
    bool has(const std::string& name) const;
    std::optional<std::string> value(const std::string& name) const;
    std::string value(const std::string& name, const std::string& fallback) const;
    double number(const std::string& name, double fallback, double lo, double hi) const;
    int integer(const std::string& name, int fallback, int lo, int hi) const;

private:
    std::vector<std::string> positionals_;
    std::map<std::string, std::string> values_;
    std::set<std::string> switches_;
};

// CLI flags derived from the parameter declarations (pipeline/graph/Parameters.h): the flags
// (and aliases) of the parameters of `kinds`, and of those named in `keys`, that take a value,
// and the switches (Bool parameters: `--no-cache` sets `cache` to false).
std::set<std::string> paramValueFlags(const std::vector<NodeKind>& kinds,
                                      const std::vector<std::string>& keys = {});
std::set<std::string> paramSwitches(const std::vector<NodeKind>& kinds,
                                    const std::vector<std::string>& keys = {});

// The parameters of `kinds` (and those named in `keys`) given on the command line, parsed and
// validated against their declarations; throws hlod::Error(InvalidArgument) naming the flag
// ("--k must be within [0, 16], got 20").
std::vector<std::pair<const ParamDecl*, ParamValue>>
paramsFromArgs(const Args& args, const std::vector<NodeKind>& kinds,
               const std::vector<std::string>& keys = {});

} // namespace hlod::cli
