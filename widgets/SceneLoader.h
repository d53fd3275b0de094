// Loads scenes off the GUI thread: import (or the embedded sample) plus the render data, so the
// window stays responsive while a 13 MB AC3D file or a STEP assembly is read.
//
// Threading: each load() runs on its own std::thread (QtConcurrent is not linked); results come
// back as queued calls on this object's thread and are emitted from there. A new load() cancels
// the one running (through hlod::Progress's cancel flag); its result is dropped. The destructor
// cancels and joins every worker, so no thread outlives the loader.
// Failure: an hlod::Error (its message already names the file), any other exception, or
// out-of-memory ends in failed(); nothing escapes the worker.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>
#include <vector>

#include <QObject>
#include <QStringList>

#include "pipeline/io/Import.h"
#include "pipeline/scene/Scene.h"

namespace hlod::widgets {

class SceneActors;

struct LoadedScene {
    std::shared_ptr<const Scene> scene;
    std::shared_ptr<SceneActors> actors;
    QStringList files;          // what load() was given; empty for the sample scene
    double importSeconds = 0.0; // reading and converting the files
    double buildSeconds = 0.0;  // building the render data
};

class SceneLoader : public QObject {
    Q_OBJECT
public:
    explicit SceneLoader(QObject* parent = nullptr);
    ~SceneLoader() override;

    // Starts loading `files` (files or folders, several form one scene) with `options` (a
    // project's Import parameters); an empty list loads the embedded sample scene.
    void load(const QStringList& files, const ImportOptions& options = {});
    // Cancels the running load, if any; neither loaded() nor failed() follows for it.
    void cancel();
    bool busy() const { return current_ != 0; }

Q_SIGNALS:
    void started(const QStringList& files);
    // `total` is 0 when unknown. Throttled to a few updates per second.
    void progressed(const QString& stage, qint64 done, qint64 total);
    void loaded(const hlod::widgets::LoadedScene& result);
    void failed(const QStringList& files, const QString& message);

private:
    struct Job {
        std::uint64_t id = 0;
        std::atomic<bool> cancel{false};
        std::thread thread;
    };

    void run(Job* job, QStringList files, ImportOptions options);
    void finish(std::uint64_t id);

    std::vector<std::unique_ptr<Job>> jobs_;
    std::uint64_t nextId_ = 1;
    std::uint64_t current_ = 0; // id whose result is wanted; 0 = none
    int running_ = 0;
};

} // namespace hlod::widgets

Q_DECLARE_METATYPE(hlod::widgets::LoadedScene)
