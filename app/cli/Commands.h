// The `hlod` subcommands. Each takes the arguments after its name, writes results to stdout
// and progress to stderr, and returns the process exit code. Errors are thrown as hlod::Error
// and turned into one stderr line by main().
#pragma once

#include <string>
#include <vector>

namespace hlod::cli {

using CommandArgs = std::vector<std::string>;

int runInfo(const CommandArgs& args);
int runCluster(const CommandArgs& args);
int runBuild(const CommandArgs& args);
int runBench(const CommandArgs& args); // cmd_bench.cpp: thesis evaluation (needs VTK, X)

struct CommandEntry {
    const char* name;
    int (*run)(const CommandArgs&);
    const char* usage;
};

} // namespace hlod::cli
