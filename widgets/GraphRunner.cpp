// The editor's graph runs (see GraphRunner.h).
#include "widgets/GraphRunner.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>
#include <map>
#include <mutex>
#include <new>

#include <QMetaObject>

#include "pipeline/core/Error.h"
#include "pipeline/export/DiskUsage.h"

namespace hlod::widgets {

namespace {

using Clock = std::chrono::steady_clock;

// Progress reports of one run, at most one per node every 100 ms (the last of a step always).
// The baker reports from several worker threads at once.
class Throttle {
public:
    bool pass(NodeId node, const ProgressInfo& info) {
        const std::lock_guard lock(mutex_);
        const auto now = Clock::now();
        const bool last = info.total > 0 && info.done == info.total;
        Clock::time_point& before = last_[node];
        if (!last && now - before < std::chrono::milliseconds(100)) return false;
        before = now;
        return true;
    }

private:
    std::mutex mutex_;
    std::map<NodeId, Clock::time_point> last_;
};

} // namespace

BuiltHlod withStatistics(NodeId bakeNode, std::shared_ptr<const NodeOutput> output) {
    BuiltHlod out;
    const Scene& scene = *output->scene;
    out.original = originalStats(scene);
    out.hlod = hlodStats(scene, *output->tree, *output->bake, hlodVersionName(*output->tree));
    out.share = proxyShare(scene, *output->tree, *output->bake);
    out.levels = levelTable(scene, *output->tree, *output->bake);
    out.scene = output->scene;
    out.bakeNode = bakeNode;
    out.build = std::move(output);
    return out;
}

GraphRunner::GraphRunner(QObject* parent) : QObject(parent) {
    qRegisterMetaType<hlod::widgets::BuiltHlod>();
    qRegisterMetaType<std::vector<hlod::widgets::BuiltHlod>>();
}

GraphRunner::~GraphRunner() {
    for (auto& job : jobs_) {
        job->cancel = true;
        if (job->thread.joinable()) job->thread.join();
    }
}

void GraphRunner::cancel() {
    for (auto& job : jobs_)
        if (job->id == current_) job->cancel = true;
}

void GraphRunner::abandon() {
    for (auto& job : jobs_)
        job->cancel = true;
    settleRunning();
    current_ = 0;
    graph_ = nullptr;
    targets_.clear();
    definitions_.clear();
}

void GraphRunner::settleRunning() {
    // A node the abandoned run was running is not being run any more.
    if (graph_) {
        for (NodeId n : running_)
            if (graph_->hasNode(n) && graph_->status(n) == NodeStatus::Running)
                graph_->adopt(n, graph_->definition(n), NodeStatus::Pending, nullptr);
    }
    running_.clear();
}

void GraphRunner::start(PipelineGraph* graph, std::vector<NodeId> targets) {
    abandon();
    graph_ = graph;
    targets_ = targets;
    for (NodeId id : graph->nodeIds())
        definitions_[id] = graph->definition(id);
    PipelineGraph copy = *graph; // outputs are shared: the copy is cheap
    copy.setStatusListener({});
    copy.setProgressListener({});
    auto job = std::make_unique<Job>();
    job->id = nextId_++;
    current_ = job->id;
    Job* raw = job.get();
    jobs_.push_back(std::move(job));
    Q_EMIT started();
    raw->thread = std::thread([this, raw, copy = std::move(copy), targets]() mutable {
        run(raw, std::move(copy), std::move(targets));
    });
}

void GraphRunner::run(Job* job, PipelineGraph copy, std::vector<NodeId> targets) {
    const std::uint64_t id = job->id;
    auto post = [this](auto&& fn) {
        QMetaObject::invokeMethod(this, std::forward<decltype(fn)>(fn), Qt::QueuedConnection);
    };
    copy.setStatusListener([&copy, id, post, this](NodeId node, NodeStatus status) {
        std::shared_ptr<const NodeOutput> output = copy.sharedOutput(node);
        std::string error = status == NodeStatus::Failed ? copy.error(node) : std::string();
        post([this, id, node, status, output = std::move(output), error = std::move(error)] {
            onStatus(id, node, status, output, error);
        });
    });
    auto throttle = std::make_shared<Throttle>();
    copy.setProgressListener([this, id, post, throttle](NodeId node, const ProgressInfo& info) {
        if (!throttle->pass(node, info)) return;
        const QString stage = QString::fromStdString(info.stage);
        const QString detail = QString::fromStdString(info.detail);
        const auto done = static_cast<qint64>(info.done);
        const auto total = static_cast<qint64>(info.total);
        post([this, id, node, stage, done, total, detail] {
            if (id == current_) Q_EMIT progressed(node, stage, done, total, detail);
        });
    });
    Progress progress;
    progress.cancel = &job->cancel;

    std::vector<BuiltHlod> bakes;
    QString error;
    bool wasCancelled = false;
    try {
        const auto start = Clock::now();
        copy.run(targets, progress);
        Progress quiet; // the package is measured silently, but a cancel stops it
        quiet.cancel = &job->cancel;
        for (NodeId n : targets) {
            if (copy.node(n).kind != NodeKind::Bake) continue;
            BuiltHlod b = withStatistics(n, copy.sharedOutput(n));
            b.package =
                measurePackage(*b.scene, *b.build->tree, *b.build->bake, b.build->bakeParams, {},
                               blockSizeAt(std::filesystem::temp_directory_path()), quiet);
            b.seconds = std::chrono::duration<double>(Clock::now() - start).count();
            bakes.push_back(std::move(b));
        }
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
    // A cancel that arrives after the last node ran still means "no result".
    wasCancelled = wasCancelled || job->cancel.load();
    copy.setStatusListener({});
    copy.setProgressListener({});
    post([this, id, bakes = std::move(bakes), error, wasCancelled] {
        // A cancel raised while this call waited in the queue, after the worker's last look at
        // the flag, means "no result" too: cancel() is never followed by finished().
        const bool stopped = wasCancelled || cancelRaised(id);
        finish(id);
        if (id != current_) return;
        settleRunning();
        current_ = 0;
        graph_ = nullptr;
        targets_.clear();
        definitions_.clear();
        if (stopped)
            Q_EMIT cancelled();
        else if (!error.isEmpty())
            Q_EMIT failed(error);
        else
            Q_EMIT finished(bakes);
    });
}

void GraphRunner::onStatus(std::uint64_t id, NodeId node, NodeStatus status,
                           std::shared_ptr<const NodeOutput> output, const std::string& error) {
    if (id != current_ || !graph_) return;
    const auto def = definitions_.find(node);
    if (def == definitions_.end()) return;
    if (!graph_->adopt(node, def->second, status, std::move(output), error)) return;
    if (status == NodeStatus::Running)
        running_.insert(node);
    else
        running_.erase(node);
    Q_EMIT nodeStatus(node, static_cast<int>(status));
}

bool GraphRunner::covers(NodeId node) const {
    if (!current_ || !graph_ || !graph_->hasNode(node)) return false;
    const auto def = definitions_.find(node);
    if (def == definitions_.end() || def->second != graph_->definition(node)) return false;
    std::vector<NodeId> reach = graph_->downstreamOf(node);
    reach.push_back(node);
    for (NodeId t : targets_)
        if (std::find(reach.begin(), reach.end(), t) != reach.end()) return true;
    return false;
}

bool GraphRunner::cancelRaised(std::uint64_t id) const {
    for (const auto& job : jobs_)
        if (job->id == id) return job->cancel.load();
    return false;
}

void GraphRunner::finish(std::uint64_t id) {
    // The worker's last act was posting this call, so joining it here waits for nothing.
    for (auto it = jobs_.begin(); it != jobs_.end(); ++it) {
        if ((*it)->id != id) continue;
        if ((*it)->thread.joinable()) (*it)->thread.join();
        jobs_.erase(it);
        return;
    }
}

} // namespace hlod::widgets
