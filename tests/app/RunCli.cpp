#include "RunCli.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <signal.h>
#include <sstream>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace hlod::test {

namespace {
std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}
} // namespace

CliResult runCli(const std::vector<std::string>& args, unsigned timeoutSeconds,
                 unsigned long long memoryLimitBytes) {
    std::vector<std::string> argv{HLOD_CLI};
    argv.insert(argv.end(), args.begin(), args.end());
    return runProcess(argv, timeoutSeconds, memoryLimitBytes);
}

CliResult runProcess(const std::vector<std::string>& args, unsigned timeoutSeconds,
                     unsigned long long memoryLimitBytes) {
    char outTmpl[] = "/tmp/hlod-cli-out-XXXXXX";
    char errTmpl[] = "/tmp/hlod-cli-err-XXXXXX";
    const int outFd = mkstemp(outTmpl);
    const int errFd = mkstemp(errTmpl);
    CliResult r;
    const pid_t pid = fork();
    if (pid == 0) {
        if (memoryLimitBytes > 0) {
            rlimit lim{memoryLimitBytes, memoryLimitBytes};
            setrlimit(RLIMIT_AS, &lim);
        }
        dup2(outFd, 1);
        dup2(errFd, 2);
        const int devnull = open("/dev/null", O_RDONLY);
        dup2(devnull, 0);
        std::vector<std::string> copy = args;
        std::vector<char*> argv;
        for (std::string& a : copy)
            argv.push_back(a.data());
        argv.push_back(nullptr);
        execvp(argv[0], argv.data());
        _exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
    int status = 0;
    while (true) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (std::chrono::steady_clock::now() > deadline) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            r.timedOut = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (!r.timedOut) {
        if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
        if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    }
    close(outFd);
    close(errFd);
    r.out = slurp(outTmpl);
    r.err = slurp(errTmpl);
    std::remove(outTmpl);
    std::remove(errTmpl);
    return r;
}

} // namespace hlod::test
