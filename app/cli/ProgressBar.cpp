#include "ProgressBar.h"

#include <cstdio>
#include <unistd.h>

namespace hlod::cli {

ProgressBar::ProgressBar()
    : tty_(isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() { finish(); }

Progress ProgressBar::progress() {
    Progress p;
    p.report = [this](const ProgressInfo& info) { draw(info); };
    return p;
}

void ProgressBar::draw(const ProgressInfo& info) {
    std::lock_guard lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    const bool stageChanged = info.stage != lastStage_;
    const bool complete = info.total > 0 && info.done >= info.total;
    const auto minGap = tty_ ? std::chrono::milliseconds(50) : std::chrono::milliseconds(1000);
    // Plain lines only for work that lasts: a quick command (or a quick failure) keeps stderr
    // to its one result line.
    if (!tty_ && now - start_ < std::chrono::seconds(1)) return;
    if (!stageChanged && !complete && now - lastDraw_ < minGap) return;
    lastDraw_ = now;
    lastStage_ = info.stage;
    const double frac =
        info.total > 0 ? static_cast<double>(info.done) / static_cast<double>(info.total) : 0.0;
    if (tty_) {
        const int width = 30;
        const int filled = static_cast<int>(frac * width);
        std::string bar(static_cast<std::size_t>(filled), '#');
        bar.resize(width, '-');
        std::fprintf(stderr, "\r%-8s [%s] %5.1f%% %llu/%llu %s\033[K", info.stage.c_str(),
                     bar.c_str(), frac * 100.0, static_cast<unsigned long long>(info.done),
                     static_cast<unsigned long long>(info.total), info.detail.c_str());
        dirty_ = true;
    } else {
        std::fprintf(stderr, "%s: %llu/%llu %s\n", info.stage.c_str(),
                     static_cast<unsigned long long>(info.done),
                     static_cast<unsigned long long>(info.total), info.detail.c_str());
    }
    std::fflush(stderr);
}

void ProgressBar::finish() {
    std::lock_guard lock(mutex_);
    if (tty_ && dirty_) std::fputc('\n', stderr);
    dirty_ = false;
}

} // namespace hlod::cli
