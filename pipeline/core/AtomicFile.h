// Writing a file so that readers never see half of it: the bytes go to a uniquely named
// temporary file next to the target (same file system), which is then renamed over it.
// Failure: Error(Io) naming the target; the temporary file is removed and an existing target
// is left as it was.
#pragma once

#include <filesystem>
#include <string_view>

namespace hlod {

void writeFileAtomic(const std::filesystem::path& file, std::string_view bytes);

} // namespace hlod
