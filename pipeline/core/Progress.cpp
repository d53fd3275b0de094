#include "pipeline/core/Progress.h"

#include "pipeline/core/Error.h"

namespace hlod {

void Progress::throwIfCancelled() const {
    if (cancelled()) throw Error(ErrorCode::Cancelled, "operation cancelled");
}

} // namespace hlod
