// Progress reporting and cancellation shared by every long pipeline operation.
//
// Contract: a long operation calls `report` from any thread (it must be thread-safe on the
// receiver's side) and checks `cancelled()` regularly; when it is raised the operation throws
// hlod::Error(ErrorCode::Cancelled) and leaves no partial output behind.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

namespace hlod {

struct ProgressInfo {
    std::string stage; // "import", "cluster", "bake", "export", ...
    std::uint64_t done = 0;
    std::uint64_t total = 0; // 0 when unknown
    std::string detail;      // short free text ("baked 12, reused 3")
};

struct Progress {
    std::function<void(const ProgressInfo&)> report; // may be empty
    const std::atomic<bool>* cancel = nullptr;       // may be null

    bool cancelled() const { return cancel && cancel->load(std::memory_order_relaxed); }
    void throwIfCancelled() const;
    void emit(const ProgressInfo& info) const {
        if (report) report(info);
    }
};

} // namespace hlod
