// Background package export (see PackageExporter.h).
#include "widgets/PackageExporter.h"

#include <chrono>
#include <exception>
#include <mutex>

#include <QMetaObject>

#include "pipeline/core/Error.h"
#include "pipeline/graph/ExportStep.h"

namespace hlod::widgets {

PackageExporter::PackageExporter(QObject* parent) : QObject(parent) {}

PackageExporter::~PackageExporter() {
    cancel_ = true;
    join();
}

void PackageExporter::join() {
    if (thread_.joinable()) thread_.join();
}

bool PackageExporter::start(ExportRequest request) {
    if (busy_ || !request.built.build || !request.built.scene || request.output.empty())
        return false;
    join();
    cancel_ = false;
    busy_ = true;
    thread_ =
        std::thread([this, request = std::move(request)]() mutable { run(std::move(request)); });
    return true;
}

void PackageExporter::cancel() {
    if (busy_) cancel_ = true;
}

void PackageExporter::run(ExportRequest request) {
    auto post = [this](auto&& fn) {
        QMetaObject::invokeMethod(this, std::forward<decltype(fn)>(fn), Qt::QueuedConnection);
    };
    using Clock = std::chrono::steady_clock;
    std::mutex mutex;
    Clock::time_point last{};
    Progress progress;
    progress.cancel = &cancel_;
    progress.report = [&](const ProgressInfo& info) {
        const std::lock_guard<std::mutex> lock(mutex);
        const Clock::time_point now = Clock::now();
        if (now - last < std::chrono::milliseconds(100) && info.done != info.total) return;
        last = now;
        const QString stage = QString::fromStdString(info.stage);
        const auto done = static_cast<qint64>(info.done);
        const auto total = static_cast<qint64>(info.total);
        post([this, stage, done, total] { Q_EMIT progressed(stage, done, total); });
    };
    try {
        const HlodBuild& build = *request.built.build;
        const BuildInputs in{*request.built.scene,   build.tree,    build.bake,
                             build.settings.cluster, request.edits, build.settings.bake,
                             request.inputs};
        ExportOptions options;
        options.output = request.output;
        options.dlod = request.dlod;
        const ExportResult result = exportPackage(in, options, progress);
        const QString folder = QString::fromStdString(result.output.string());
        const auto files = static_cast<qint64>(result.written.files);
        const auto bytes = static_cast<qint64>(result.written.bytes);
        post([this, folder, files, bytes] {
            busy_ = false;
            Q_EMIT finished(folder, files, bytes);
        });
    } catch (const Error& e) {
        const bool wasCancelled = e.code() == ErrorCode::Cancelled;
        const QString message = QString::fromStdString(e.what());
        post([this, wasCancelled, message] {
            busy_ = false;
            if (wasCancelled)
                Q_EMIT cancelled();
            else
                Q_EMIT failed(message);
        });
    } catch (const std::exception& e) {
        const QString message = QString::fromStdString(e.what());
        post([this, message] {
            busy_ = false;
            Q_EMIT failed(message);
        });
    }
}

} // namespace hlod::widgets
