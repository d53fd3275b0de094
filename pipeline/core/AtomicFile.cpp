#include "pipeline/core/AtomicFile.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include "pipeline/core/Error.h"

namespace hlod {

std::string systemReason(int error) {
    char buffer[256];
    // GNU strerror_r returns the message (possibly a static string, not `buffer`).
    return ::strerror_r(error, buffer, sizeof buffer);
}

void writeFileBytes(const std::filesystem::path& file, std::string_view bytes) {
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw Error(ErrorCode::Io, file, "cannot write: " + systemReason(errno));
    const auto fail = [&](int error) {
        ::close(fd);
        ::unlink(file.c_str());
        throw Error(ErrorCode::Io, file, "cannot write: " + systemReason(error));
    };
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail(n < 0 ? errno : ENOSPC);
        done += static_cast<std::size_t>(n);
    }
    // Network and some local file systems report a full disk only when the data is flushed.
    if (::close(fd) != 0) {
        const int error = errno;
        ::unlink(file.c_str());
        throw Error(ErrorCode::Io, file, "cannot write: " + systemReason(error));
    }
}

void writeFileAtomic(const std::filesystem::path& file, std::string_view bytes) {
    // pid + counter: concurrent writers (threads or processes) never share a temporary file.
    static std::atomic<unsigned> counter{0};
    std::filesystem::path tmp = file;
    tmp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
    try {
        writeFileBytes(tmp, bytes);
    } catch (const Error& e) {
        // Name the target, not the temporary file the user never asked for.
        const std::string& problem = e.problem();
        throw Error(ErrorCode::Io, file, problem);
    }
    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw Error(ErrorCode::Io, file, "cannot move the file into place: " + ec.message());
    }
}

std::string readFileBytes(const std::filesystem::path& file, const std::string& hint) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec))
        throw Error(ErrorCode::FileNotFound, file, "no such file" + hint);
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(ErrorCode::FileUnreadable, file, "cannot be read");
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw Error(ErrorCode::FileUnreadable, file, "cannot be read");
    return bytes;
}

bool fileHoldsBytes(const std::filesystem::path& file, std::span<const std::uint8_t> bytes) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec) ||
        std::filesystem::file_size(file, ec) != bytes.size() || ec)
        return false;
    std::ifstream in(file, std::ios::binary);
    std::vector<char> have(bytes.size());
    in.read(have.data(), static_cast<std::streamsize>(have.size()));
    return in && std::equal(have.begin(), have.end(), bytes.begin(), [](char a, std::uint8_t b) {
               return static_cast<std::uint8_t>(a) == b;
           });
}

} // namespace hlod
