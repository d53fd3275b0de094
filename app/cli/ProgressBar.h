// Progress on stderr: a redrawn bar on a terminal, plain lines (at most one per second and
// per stage change) otherwise, so logs of build machines stay readable.
#pragma once

#include <chrono>
#include <mutex>
#include <string>

#include "pipeline/core/Progress.h"

namespace hlod::cli {

class ProgressBar {
public:
    ProgressBar();
    ~ProgressBar();
    Progress progress(); // a Progress whose callback draws into this bar
    void finish();

private:
    void draw(const ProgressInfo& info);
    std::mutex mutex_;
    bool tty_ = false;
    bool dirty_ = false;
    std::string lastStage_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point lastDraw_{};
};

} // namespace hlod::cli
