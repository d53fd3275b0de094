// Runs the HLOD pipeline (hlod::buildHlod: cluster, dissolve split clusters, bake) off the GUI
// thread, so the editor stays responsive while proxies bake. The hand edits travel in the
// settings (locked groups, exclusions, split clusters), so a build here gives the same tree as
// `hlod build PROJECT.hlodproj` for the same project.
// Incremental: the builder keeps its last finished build; the next build of the same scene with
// the same clustering settings reuses its tree and only bakes (unchanged proxies come from the
// disk cache), so a bake parameter change reruns only what is downstream of it.
//
// Threading: each start() runs on its own std::thread (like SceneLoader); progress and results
// come back as queued calls on this object's thread. Starting again cancels the running build,
// whose result is dropped without a signal. cancel() raises the pipeline's cancel flag: the run
// ends with Error(Cancelled) within about one node's bake and cancelled() follows, never
// finished() (not even when the run had ended and its result was waiting in the event queue
// when cancel() came). The destructor cancels and joins every worker.
// Failure: hlod::Error, any other exception or out-of-memory end in failed(message); nothing
// escapes the worker. The statistics of a finished build are computed on the worker too.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include <QObject>
#include <QString>

#include "pipeline/doc/HlodBuild.h"
#include "pipeline/export/Package.h"
#include "pipeline/proxy/BakeStats.h"
#include "pipeline/scene/Scene.h"

namespace hlod::widgets {

// A finished build and what the editor shows about it.
struct BuiltHlod {
    std::shared_ptr<const Scene> scene; // the scene it was built from
    std::shared_ptr<const HlodBuild> build;
    GeometryStats original;       // BakeStats originalStats
    GeometryStats hlod;           // BakeStats hlodStats: originals plus every proxy
    ProxyShare share;             // BakeStats proxyShare
    std::vector<LevelRow> levels; // BakeStats levelTable
    // The package `hlod build` writes at the default compression, measured in memory: files and
    // bytes on disk (Package.h measurePackage, blocks of the temporary folder's file system).
    PackageSummary package;
    double seconds = 0.0;
};

// `build` of `scene` with its statistics (what a finished background build delivers).
BuiltHlod withStatistics(std::shared_ptr<const Scene> scene,
                         std::shared_ptr<const HlodBuild> build);

class HlodBuilder : public QObject {
    Q_OBJECT
public:
    explicit HlodBuilder(QObject* parent = nullptr);
    ~HlodBuilder() override;

    void start(std::shared_ptr<const Scene> scene, const HlodSettings& settings);
    // Raises the cancel flag of the running build; cancelled() follows once it has stopped.
    void cancel();
    // Drops the running build without any further signal and forgets the last build (a new
    // scene replaces the old one).
    void abandon();
    bool busy() const { return current_ != 0; }

Q_SIGNALS:
    void started();
    // `total` is 0 when unknown. Throttled to about ten updates per second.
    void progressed(const QString& stage, qint64 done, qint64 total, const QString& detail);
    void finished(const hlod::widgets::BuiltHlod& result);
    void failed(const QString& message);
    void cancelled();

private:
    struct Job {
        std::uint64_t id = 0;
        std::atomic<bool> cancel{false};
        std::thread thread;
    };

    void run(Job* job, std::shared_ptr<const Scene> scene, HlodSettings settings,
             std::shared_ptr<const HlodBuild> previous);
    // Whether cancel() has raised the flag of job `id` (false once the job is gone).
    bool cancelRaised(std::uint64_t id) const;
    void finish(std::uint64_t id);

    std::vector<std::unique_ptr<Job>> jobs_;
    std::uint64_t nextId_ = 1;
    std::uint64_t current_ = 0; // id whose outcome is wanted; 0 = none
    BuiltHlod last_;            // the last finished build (its tree may be reused)
};

} // namespace hlod::widgets

Q_DECLARE_METATYPE(hlod::widgets::BuiltHlod)
