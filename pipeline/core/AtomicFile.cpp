#include "pipeline/core/AtomicFile.h"

#include <atomic>
#include <fstream>
#include <string>

#include <unistd.h>

#include "pipeline/core/Error.h"

namespace hlod {

void writeFileAtomic(const std::filesystem::path& file, std::string_view bytes) {
    // pid + counter: concurrent writers (threads or processes) never share a temporary file.
    static std::atomic<unsigned> counter{0};
    std::filesystem::path tmp = file;
    tmp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.flush();
        if (!out) {
            out.close();
            std::error_code ec;
            std::filesystem::remove(tmp, ec);
            throw Error(ErrorCode::Io, file, "cannot write file");
        }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw Error(ErrorCode::Io, file, "cannot move the file into place: " + ec.message());
    }
}

} // namespace hlod
