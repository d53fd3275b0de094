// Writes the engine-ready package of a build (pipeline/graph/ExportStep.h: statistics, then
// Package.h writePackage) off the GUI thread, with progress and cancel, for the export dialog.
//
// Threading: start() runs the export on its own std::thread; progress and the outcome come back
// as queued signals on this object's thread. cancel() raises the pipeline's cancel flag: the
// export ends with Error(Cancelled) and cancelled() follows (the package is written atomically,
// so nothing is left behind). Only one export runs at a time: start() while busy() is refused.
// The destructor cancels and joins the worker.
// Failure: any exception ends in failed(message); nothing escapes the worker.
#pragma once

#include <atomic>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <QObject>
#include <QString>

#include "pipeline/graph/HandEdits.h"
#include "widgets/HlodBuilder.h"

namespace hlod::widgets {

struct ExportRequest {
    BuiltHlod built;                 // scene and build to export
    HandEdits edits;                 // the hand edits the build was made with
    std::vector<std::string> inputs; // source scene paths as given
    std::filesystem::path output;    // the package folder
    bool dlod = true;                // include the DLOD chain statistics row
};

class PackageExporter : public QObject {
    Q_OBJECT
public:
    explicit PackageExporter(QObject* parent = nullptr);
    ~PackageExporter() override;

    // False when an export is running or the request has no build or no output folder.
    bool start(ExportRequest request);
    void cancel();
    bool busy() const { return busy_; }

Q_SIGNALS:
    void progressed(const QString& stage, qint64 done, qint64 total);
    // Files and bytes written.
    void finished(const QString& folder, qint64 files, qint64 bytes);
    void failed(const QString& message);
    void cancelled();

private:
    void run(ExportRequest request);
    void join();

    std::thread thread_;
    std::atomic<bool> cancel_{false};
    bool busy_ = false;
};

} // namespace hlod::widgets
