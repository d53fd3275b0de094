// Loads scenes off the GUI thread (see SceneLoader.h).
#include "widgets/SceneLoader.h"

#include <chrono>
#include <exception>
#include <filesystem>
#include <new>

#include <QFile>
#include <QMetaObject>

#include "pipeline/core/Error.h"
#include "pipeline/io/Import.h"
#include "pipeline/io/SampleScene.h"
#include "widgets/SceneActors.h"

namespace hlod::widgets {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

std::filesystem::path toPath(const QString& file) {
    return std::filesystem::path(QFile::encodeName(file).toStdString());
}

} // namespace

SceneLoader::SceneLoader(QObject* parent) : QObject(parent) {
    qRegisterMetaType<hlod::widgets::LoadedScene>();
}

SceneLoader::~SceneLoader() {
    for (auto& job : jobs_) {
        job->cancel = true;
        if (job->thread.joinable()) job->thread.join();
    }
}

void SceneLoader::cancel() {
    for (auto& job : jobs_)
        job->cancel = true;
    current_ = 0;
}

void SceneLoader::load(const QStringList& files, const ImportOptions& options) {
    cancel();
    auto job = std::make_unique<Job>();
    job->id = nextId_++;
    current_ = job->id;
    Job* raw = job.get();
    jobs_.push_back(std::move(job));
    ++running_;
    Q_EMIT started(files);
    raw->thread = std::thread([this, raw, files, options] { run(raw, files, options); });
}

void SceneLoader::run(Job* job, QStringList files, ImportOptions options) {
    const std::uint64_t id = job->id;
    auto post = [this](auto&& fn) {
        QMetaObject::invokeMethod(this, std::forward<decltype(fn)>(fn), Qt::QueuedConnection);
    };
    // Progress from the importer: forwarded at most every 100 ms so the event queue stays small.
    auto lastReport = std::make_shared<Clock::time_point>();
    Progress progress;
    progress.cancel = &job->cancel;
    progress.report = [this, id, post, lastReport](const ProgressInfo& info) {
        const auto now = Clock::now();
        if (now - *lastReport < std::chrono::milliseconds(100)) return;
        *lastReport = now;
        const QString stage = QString::fromStdString(info.stage);
        const auto done = static_cast<qint64>(info.done);
        const auto total = static_cast<qint64>(info.total);
        post([this, id, stage, done, total] {
            if (id == current_) Q_EMIT progressed(stage, done, total);
        });
    };

    LoadedScene result;
    result.files = files;
    QString error;
    try {
        const auto start = Clock::now();
        std::vector<std::filesystem::path> paths;
        for (const QString& file : files)
            paths.push_back(toPath(file));
        auto scene = std::make_shared<Scene>(paths.empty() ? makeSampleScene()
                                                           : importScene(paths, options, progress));
        result.importSeconds = secondsSince(start);
        progress.throwIfCancelled();
        const auto buildStart = Clock::now();
        result.actors = SceneActors::build(*scene);
        result.buildSeconds = secondsSince(buildStart);
        result.scene = std::move(scene);
    } catch (const Error& e) {
        error = QString::fromStdString(e.what());
    } catch (const std::bad_alloc&) {
        error =
            tr("%1: not enough memory to load this scene").arg(files.join(QStringLiteral(", ")));
    } catch (const std::exception& e) {
        error = QStringLiteral("%1: %2").arg(files.join(QStringLiteral(", ")),
                                             QString::fromStdString(e.what()));
    } catch (...) {
        error = tr("%1: unexpected error while loading").arg(files.join(QStringLiteral(", ")));
    }
    const bool cancelled = job->cancel.load();
    post([this, id, result = std::move(result), error, cancelled, files] {
        finish(id);
        if (id != current_ || cancelled) return;
        current_ = 0;
        if (error.isEmpty())
            Q_EMIT loaded(result);
        else
            Q_EMIT failed(files, error);
    });
}

void SceneLoader::finish(std::uint64_t id) {
    // The worker's last act was posting this call, so joining it here waits for nothing.
    for (auto it = jobs_.begin(); it != jobs_.end(); ++it) {
        if ((*it)->id != id) continue;
        if ((*it)->thread.joinable()) (*it)->thread.join();
        jobs_.erase(it);
        --running_;
        return;
    }
}

} // namespace hlod::widgets
