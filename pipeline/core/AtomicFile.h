// Reading and writing whole files. Writing so that readers never see half of it: the bytes go to a
// uniquely named temporary file next to the target (same file system), which is then renamed over
// it. Failure: Error(Io) naming the target and the system's reason (a full disk, a read-only file
// system, a missing permission); the temporary file is removed and an existing target is left as it
// was.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace hlod {

void writeFileAtomic(const std::filesystem::path& file, std::string_view bytes);

// Writes `bytes` to `file` (created or truncated) with POSIX calls, so that every failure,
// the one reported only when the file is closed included, is seen. Not atomic: callers write
// into a temporary file or folder. Failure: Error(Io, file, "cannot write: <reason>"); a
// partly written file is removed.
void writeFileBytes(const std::filesystem::path& file, std::string_view bytes);

// The whole of `file`. Failure: Error(FileNotFound, file, "no such file" + hint) when it does
// not exist, Error(FileUnreadable) when it cannot be read.
std::string readFileBytes(const std::filesystem::path& file, const std::string& hint = {});

// Whether `file` is a regular file holding exactly `bytes` (false when it cannot be read).
bool fileHoldsBytes(const std::filesystem::path& file, std::span<const std::uint8_t> bytes);

// The system's reason for the last failed call (strerror of errno), e.g. "No space left on
// device", for error messages.
std::string systemReason(int error);

} // namespace hlod
