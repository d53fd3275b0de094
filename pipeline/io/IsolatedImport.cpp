// fork + pipe + waitpid isolation (POSIX). The child only runs the importer and serialises its
// result, then leaves with _exit so no parent state (atexit handlers, buffered streams) runs
// twice.
#include "pipeline/io/IsolatedImport.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "pipeline/core/Error.h"
#include "pipeline/scene/SceneBinary.h"

namespace hlod {

namespace {

bool writeAll(int fd, const char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        size -= static_cast<std::size_t>(n);
    }
    return true;
}

// Child side: 'S' + scene bytes, or 'E' + code byte + message.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

[[noreturn]] void childMain(int fd, const std::function<Scene()>& import,
                            const IsolationLimits& limits) {
    // AddressSanitizer reserves terabytes of shadow address space up front, so under it (the
    // sanitized build, scripts/sanitize.sh) an address-space limit fails every allocation;
    // there the sanitizer's own allocator limits (ASAN_OPTIONS) take its place.
    if (!kAddressSanitizer) {
        rlimit lim{limits.memoryLimitBytes, limits.memoryLimitBytes};
        setrlimit(RLIMIT_AS, &lim);
    }
    // Some readers print diagnostics themselves; the pipeline never prints.
    const int devnull = ::open("/dev/null", O_WRONLY);
    if (devnull >= 0) {
        ::dup2(devnull, STDOUT_FILENO);
        ::dup2(devnull, STDERR_FILENO);
        ::close(devnull);
    }
    std::string msg;
    try {
        msg = "S" + writeSceneBinary(import());
    } catch (const Error& e) {
        msg = std::string("E") + static_cast<char>(e.code()) + e.problem();
    } catch (const std::bad_alloc&) {
        msg = std::string("E") + static_cast<char>(ErrorCode::TooLarge) +
              "reading it needs more memory than the import limit allows";
    } catch (const std::exception& e) {
        msg = std::string("E") + static_cast<char>(ErrorCode::Malformed) + e.what();
    }
    const bool ok = writeAll(fd, msg.data(), msg.size());
    ::close(fd);
    _exit(ok ? 0 : 3);
}

std::string readUntilEof(int fd, pid_t pid, const std::filesystem::path& file,
                         unsigned timeoutSeconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
    std::string data;
    char buf[1 << 16];
    while (true) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, nullptr, 0);
            ::close(fd);
            throw Error(ErrorCode::Malformed, file,
                        "reading did not finish within " + std::to_string(timeoutSeconds) +
                            " s (the reader hangs on this file)");
        }
        pollfd p{fd, POLLIN, 0};
        const int r = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) continue;
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        data.append(buf, static_cast<std::size_t>(n));
    }
    ::close(fd);
    return data;
}

} // namespace

Scene runIsolated(const std::filesystem::path& file, const std::function<Scene()>& import,
                  const IsolationLimits& limits) {
    int fds[2];
    if (::pipe(fds) != 0) {
        throw Error(ErrorCode::Io, file, std::string("cannot create a pipe: ") + strerror(errno));
    }
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        throw Error(ErrorCode::Io, file, std::string("cannot start a reader: ") + strerror(errno));
    }
    if (pid == 0) {
        ::close(fds[0]);
        childMain(fds[1], import, limits);
    }
    ::close(fds[1]);
    const std::string data = readUntilEof(fds[0], pid, file, limits.timeoutSeconds);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFSIGNALED(status)) {
        const int sig = WTERMSIG(status);
        throw Error(ErrorCode::Malformed, file,
                    std::string("the reader crashed on this file (") + strsignal(sig) +
                        "); the file is corrupt or uses an unsupported variant");
    }
    if (data.size() >= 2 && data[0] == 'E') {
        throw Error(static_cast<ErrorCode>(data[1]), file, data.substr(2));
    }
    if (data.empty() || data[0] != 'S') {
        throw Error(ErrorCode::Malformed, file, "the reader stopped without a result");
    }
    return readSceneBinary(data.substr(1), file);
}

} // namespace hlod
