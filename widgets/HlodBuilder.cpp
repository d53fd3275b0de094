// Background HLOD builds (see HlodBuilder.h).
#include "widgets/HlodBuilder.h"

#include <chrono>
#include <exception>
#include <filesystem>
#include <new>

#include <QMetaObject>

#include "pipeline/core/Error.h"
#include "pipeline/export/DiskUsage.h"

namespace hlod::widgets {

BuiltHlod withStatistics(std::shared_ptr<const Scene> scene,
                         std::shared_ptr<const HlodBuild> build) {
    BuiltHlod out;
    out.original = originalStats(*scene);
    out.hlod = hlodStats(*scene, build->tree, build->bake, hlodVersionName(build->tree));
    out.share = proxyShare(*scene, build->tree, build->bake);
    out.levels = levelTable(*scene, build->tree, build->bake);
    out.build = std::move(build);
    out.scene = std::move(scene);
    return out;
}

namespace {

using Clock = std::chrono::steady_clock;

} // namespace

HlodBuilder::HlodBuilder(QObject* parent) : QObject(parent) {
    qRegisterMetaType<hlod::widgets::BuiltHlod>();
}

HlodBuilder::~HlodBuilder() {
    for (auto& job : jobs_) {
        job->cancel = true;
        if (job->thread.joinable()) job->thread.join();
    }
}

void HlodBuilder::cancel() {
    for (auto& job : jobs_)
        if (job->id == current_) job->cancel = true;
}

void HlodBuilder::abandon() {
    for (auto& job : jobs_)
        job->cancel = true;
    current_ = 0;
    last_ = {}; // a new scene replaces the old one: do not keep it alive
}

void HlodBuilder::start(std::shared_ptr<const Scene> scene, const HlodSettings& settings) {
    std::shared_ptr<const HlodBuild> previous = last_.scene == scene ? last_.build : nullptr;
    abandon();
    auto job = std::make_unique<Job>();
    job->id = nextId_++;
    current_ = job->id;
    Job* raw = job.get();
    jobs_.push_back(std::move(job));
    Q_EMIT started();
    raw->thread =
        std::thread([this, raw, scene = std::move(scene), settings,
                     previous = std::move(previous)] { run(raw, scene, settings, previous); });
}

void HlodBuilder::run(Job* job, std::shared_ptr<const Scene> scene, HlodSettings settings,
                      std::shared_ptr<const HlodBuild> previous) {
    const std::uint64_t id = job->id;
    auto post = [this](auto&& fn) {
        QMetaObject::invokeMethod(this, std::forward<decltype(fn)>(fn), Qt::QueuedConnection);
    };
    // The baker reports from several worker threads: a shared, locked timestamp throttles.
    struct Throttle {
        std::mutex mutex;
        Clock::time_point last;
    };
    auto throttle = std::make_shared<Throttle>();
    Progress progress;
    progress.cancel = &job->cancel;
    progress.report = [this, id, post, throttle](const ProgressInfo& info) {
        {
            const std::lock_guard lock(throttle->mutex);
            const auto now = Clock::now();
            const bool last = info.total > 0 && info.done == info.total;
            if (!last && now - throttle->last < std::chrono::milliseconds(100)) return;
            throttle->last = now;
        }
        const QString stage = QString::fromStdString(info.stage);
        const QString detail = QString::fromStdString(info.detail);
        const auto done = static_cast<qint64>(info.done);
        const auto total = static_cast<qint64>(info.total);
        post([this, id, stage, done, total, detail] {
            if (id == current_) Q_EMIT progressed(stage, done, total, detail);
        });
    };

    BuiltHlod result;
    QString error;
    bool wasCancelled = false;
    try {
        const auto start = Clock::now();
        auto build =
            std::make_shared<HlodBuild>(buildHlod(*scene, settings, progress, previous.get()));
        Progress quiet; // the package is measured silently, but a cancel stops it
        quiet.cancel = &job->cancel;
        result = withStatistics(std::move(scene), std::move(build));
        result.package = measurePackage(*result.scene, result.build->tree, result.build->bake,
                                        result.build->settings.bake, {},
                                        blockSizeAt(std::filesystem::temp_directory_path()), quiet);
        result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    } catch (const Error& e) {
        wasCancelled = e.code() == ErrorCode::Cancelled;
        error = QString::fromStdString(e.what());
    } catch (const std::bad_alloc&) {
        error = tr("Not enough memory to build the HLOD of this scene");
    } catch (const std::exception& e) {
        error = QString::fromStdString(e.what());
    } catch (...) {
        error = tr("Unexpected error while building the HLOD");
    }
    // A cancel that arrives after the last node baked still means "no result".
    wasCancelled = wasCancelled || job->cancel.load();
    post([this, id, result = std::move(result), error, wasCancelled] {
        // A cancel raised while this call waited in the queue, after the worker's last look at
        // the flag, means "no result" too: cancel() is never followed by finished().
        const bool stopped = wasCancelled || cancelRaised(id);
        finish(id);
        if (id != current_) return;
        current_ = 0;
        if (stopped)
            Q_EMIT cancelled();
        else if (!error.isEmpty())
            Q_EMIT failed(error);
        else {
            last_ = result;
            Q_EMIT finished(result);
        }
    });
}

bool HlodBuilder::cancelRaised(std::uint64_t id) const {
    for (const auto& job : jobs_)
        if (job->id == id) return job->cancel.load();
    return false;
}

void HlodBuilder::finish(std::uint64_t id) {
    // The worker's last act was posting this call, so joining it here waits for nothing.
    for (auto it = jobs_.begin(); it != jobs_.end(); ++it) {
        if ((*it)->id != id) continue;
        if ((*it)->thread.joinable()) (*it)->thread.join();
        jobs_.erase(it);
        return;
    }
}

} // namespace hlod::widgets
