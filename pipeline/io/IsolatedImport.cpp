// fork + pipe + waitpid isolation (POSIX). The child only runs the importer, sends its progress
// and serialises its result, then leaves with _exit so no parent state (atexit handlers,
// buffered streams) runs twice.
#include "pipeline/io/IsolatedImport.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <fcntl.h>
#include <memory>
#include <poll.h>
#include <string>
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

// The pipe carries frames: one type byte, the payload length (8 bytes, little-endian), the
// payload. 'P' progress (done, total as 8 bytes each, the stage's length as 4, the stage, the
// detail), then exactly one of 'S' (scene bytes) or 'E' (code byte + message).
void appendU64(std::string& out, std::uint64_t v, int bytes = 8) {
    for (int i = 0; i < bytes; ++i)
        out.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
}

std::uint64_t readU64(const char* p, int bytes = 8) {
    std::uint64_t v = 0;
    for (int i = bytes; i-- > 0;)
        v = (v << 8) | static_cast<unsigned char>(p[i]);
    return v;
}

constexpr std::size_t kFrameHeader = 9;

std::string frame(char type, const std::string& payload) {
    std::string out(1, type);
    appendU64(out, payload.size());
    return out + payload;
}

std::string progressFrame(const ProgressInfo& info) {
    std::string payload;
    appendU64(payload, info.done);
    appendU64(payload, info.total);
    appendU64(payload, info.stage.size(), 4);
    payload += info.stage;
    payload += info.detail;
    return frame('P', payload);
}

ProgressInfo parseProgress(const char* p, std::size_t size) {
    ProgressInfo info;
    if (size < 20) return info;
    info.done = readU64(p);
    info.total = readU64(p + 8);
    const std::size_t stage = std::min<std::size_t>(readU64(p + 16, 4), size - 20);
    info.stage.assign(p + 20, stage);
    info.detail.assign(p + 20 + stage, size - 20 - stage);
    return info;
}

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

// The child's Progress: reports go up the pipe, at most every 50 ms unless the stage changes or
// the work is complete (a per-face report on a 100,000-face model must not flood the pipe).
Progress childProgress(int fd) {
    struct State {
        std::chrono::steady_clock::time_point last{};
        std::string stage;
    };
    auto state = std::make_shared<State>();
    Progress p;
    p.report = [fd, state](const ProgressInfo& info) {
        const auto now = std::chrono::steady_clock::now();
        const bool complete = info.total > 0 && info.done >= info.total;
        if (info.stage == state->stage && !complete &&
            now - state->last < std::chrono::milliseconds(50))
            return;
        state->last = now;
        state->stage = info.stage;
        const std::string f = progressFrame(info);
        writeAll(fd, f.data(), f.size());
    };
    return p;
}

[[noreturn]] void childMain(int fd, const std::function<Scene(const Progress&)>& import,
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
        msg = frame('S', writeSceneBinary(import(childProgress(fd))));
    } catch (const Error& e) {
        msg = frame('E', static_cast<char>(e.code()) + e.problem());
    } catch (const std::bad_alloc&) {
        msg = frame('E', static_cast<char>(ErrorCode::TooLarge) +
                             std::string("reading it needs more memory than the import limit "
                                         "allows"));
    } catch (const std::exception& e) {
        msg = frame('E', static_cast<char>(ErrorCode::Malformed) + std::string(e.what()));
    }
    const bool ok = writeAll(fd, msg.data(), msg.size());
    ::close(fd);
    _exit(ok ? 0 : 3);
}

// Kills the child and rethrows the exception being handled (a throwing progress callback).
[[noreturn]] void stopChildAndRethrow(int fd, pid_t pid) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    ::close(fd);
    throw;
}

// Reads frames until the child closes the pipe: progress is re-emitted as it comes, the
// returned string is the last frame's type and payload ('S'/'E' + payload; empty when none).
std::string readFrames(int fd, pid_t pid, const std::filesystem::path& file,
                       unsigned timeoutSeconds, const Progress& progress) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
    std::string buffer, result;
    char chunk[1 << 16];
    const auto fail = [&](ErrorCode code, const std::string& problem) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, nullptr, 0);
        ::close(fd);
        throw Error(code, file, problem);
    };
    while (true) {
        if (progress.cancelled()) fail(ErrorCode::Cancelled, "import cancelled");
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            fail(ErrorCode::Malformed, "reading did not finish within " +
                                           std::to_string(timeoutSeconds) +
                                           " s (the reader hangs on this file)");
        }
        pollfd p{fd, POLLIN, 0};
        // Short waits: a raised cancel flag is seen within 100 ms.
        const int r = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 100)));
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) continue;
        const ssize_t n = ::read(fd, chunk, sizeof chunk);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        buffer.append(chunk, static_cast<std::size_t>(n));
        std::size_t pos = 0;
        while (buffer.size() - pos >= kFrameHeader) {
            const std::uint64_t size = readU64(buffer.data() + pos + 1);
            if (buffer.size() - pos - kFrameHeader < size) break;
            const char type = buffer[pos];
            if (type == 'P') {
                try {
                    progress.emit(parseProgress(buffer.data() + pos + kFrameHeader, size));
                } catch (...) {
                    stopChildAndRethrow(fd, pid);
                }
            } else {
                result.assign(1, type);
                result.append(buffer, pos + kFrameHeader, size);
            }
            pos += kFrameHeader + size;
        }
        if (pos > 0) buffer.erase(0, pos);
    }
    ::close(fd);
    return result;
}

} // namespace

Scene runIsolated(const std::filesystem::path& file,
                  const std::function<Scene(const Progress&)>& import,
                  const IsolationLimits& limits, const Progress& progress) {
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
    const std::string data = readFrames(fds[0], pid, file, limits.timeoutSeconds, progress);
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
