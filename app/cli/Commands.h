// The `hlod` subcommands. Each takes the arguments after its name, writes results to stdout
// and progress to stderr, and returns the process exit code. Errors are thrown as hlod::Error
// and turned into one stderr line by main(). What each accepts is declared in CommandTable.cpp
// (CommandSpec.h).
#pragma once

#include "CommandSpec.h"

namespace hlod::cli {

int runInfo(const CommandArgs& args);
int runCluster(const CommandArgs& args);
int runBuild(const CommandArgs& args);
int runPlan(const CommandArgs& args);  // cmd_plan.cpp: first step of a distributed bake
int runBench(const CommandArgs& args); // cmd_bench.cpp: thesis evaluation (needs VTK, X)

} // namespace hlod::cli
