// Runs the built `hlod` binary in a child process with an address-space limit and a wall-clock
// timeout, capturing stdout and stderr: the CLI tests see exactly what a user would.
#pragma once

#include <string>
#include <vector>

namespace hlod::test {

struct CliResult {
    int exitCode = -1; // valid when !signalled && !timedOut
    int signal = 0;    // the signal that killed it, 0 if none
    bool timedOut = false;
    std::string out;
    std::string err;
};

CliResult runCli(const std::vector<std::string>& args, unsigned timeoutSeconds = 60,
                 unsigned long long memoryLimitBytes = 4ull << 30);

// Any program (argv[0] is looked up in PATH), same capture and limits.
CliResult runProcess(const std::vector<std::string>& argv, unsigned timeoutSeconds = 60,
                     unsigned long long memoryLimitBytes = 0);

} // namespace hlod::test
