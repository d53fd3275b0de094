// The one wording of an import limit refusal (see ImportLimits.h).
#include "pipeline/io/ImportLimits.h"

#include "pipeline/core/Error.h"

namespace hlod {

void throwOverLimit(const std::filesystem::path& file, const std::string& what, std::uint64_t limit,
                    const char* flag) {
    std::string problem = what + ", over the import limit of " + std::to_string(limit);
    if (flag != nullptr) problem += std::string(" (") + flag + " raises it)";
    throw Error(ErrorCode::TooLarge, file, problem);
}

} // namespace hlod
