// Runs the pipeline graph off the GUI thread for the editor: the same runner as `hlod build`
// (PipelineGraph::run, docs/architecture.md "The graph runner"), on a copy of the graph made
// when the run starts, so the editor stays responsive and editable while proxies bake.
//
// What comes back: every status change of the copy (with the node's output or error) is brought
// into the graph the run was started from with PipelineGraph::adopt, on this object's thread, as
// it happens: the Pipeline dock shows the statuses of the run, node by node, and a node edited
// meanwhile keeps its own (adopt compares definitions). Progress comes per node. Once the run
// has ended, finished() delivers, for every Bake node among the targets, its output with the
// statistics the editor shows (computed on the worker).
// Incremental: the copy carries the outputs of the nodes that are up to date, so only Pending
// nodes upstream of the targets run; the Bake step takes unchanged proxies from the disk cache.
//
// Threading: each start() runs on its own std::thread; results come back as queued calls.
// Starting again abandons the running run (its cancel flag is raised, nothing more of it is
// delivered, and the nodes it had marked Running are put back to Pending). cancel() raises the
// flag of the running run: it ends with Error(Cancelled) within about one node's bake and
// cancelled() follows, never finished(). The destructor cancels and joins every worker.
// Failure: a refused graph (PipelineGraph::checkRunnable), hlod::Error, any other exception or
// out-of-memory end in failed(message); nothing escapes the worker.
// Lifetime: the graph given to start() must outlive the run or be let go first (abandon()).
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <QObject>
#include <QString>

#include "pipeline/export/Package.h"
#include "pipeline/graph/PipelineGraph.h"
#include "pipeline/proxy/BakeStats.h"

namespace hlod::widgets {

// The output of a Bake node and what the editor shows about it.
struct BuiltHlod {
    std::shared_ptr<const Scene> scene;      // the scene it was built from
    std::shared_ptr<const NodeOutput> build; // the Bake node's output: tree, proxies, parameters
    NodeId bakeNode = kNoNode;
    GeometryStats original;       // BakeStats originalStats
    GeometryStats hlod;           // BakeStats hlodStats: originals plus every proxy
    ProxyShare share;             // BakeStats proxyShare
    std::vector<LevelRow> levels; // BakeStats levelTable
    // The package `hlod build` writes at the default compression, measured in memory: files and
    // bytes on disk (Package.h measurePackage, blocks of the temporary folder's file system).
    PackageSummary package;
    double seconds = 0.0; // the run that made it
};

// The statistics of Bake node `bakeNode`'s `output` (without the package measure).
BuiltHlod withStatistics(NodeId bakeNode, std::shared_ptr<const NodeOutput> output);

class GraphRunner : public QObject {
    Q_OBJECT
public:
    explicit GraphRunner(QObject* parent = nullptr);
    ~GraphRunner() override;

    // Runs `targets` of `graph` (see above).
    void start(PipelineGraph* graph, std::vector<NodeId> targets);
    void cancel();
    // Drops the running run without any further signal (see above).
    void abandon();
    bool busy() const { return current_ != 0; }
    // The targets of the running run (empty when idle).
    const std::vector<NodeId>& targets() const { return targets_; }
    // Whether the running run will bring `node` up to date as the graph defines it now: it is a
    // target or upstream of one, and unchanged since the run started.
    bool covers(NodeId node) const;

Q_SIGNALS:
    void started();
    // A status of the run taken into the graph.
    void nodeStatus(quint32 node, int status);
    // Progress of the step of `node`; `total` is 0 when unknown. Throttled to about ten updates
    // per second.
    void progressed(quint32 node, const QString& stage, qint64 done, qint64 total,
                    const QString& detail);
    void finished(const std::vector<hlod::widgets::BuiltHlod>& bakes);
    void failed(const QString& message);
    void cancelled();

private:
    struct Job {
        std::uint64_t id = 0;
        std::atomic<bool> cancel{false};
        std::thread thread;
    };

    void run(Job* job, PipelineGraph copy, std::vector<NodeId> targets);
    void onStatus(std::uint64_t id, NodeId node, NodeStatus status,
                  std::shared_ptr<const NodeOutput> output, const std::string& error);
    void settleRunning();
    bool cancelRaised(std::uint64_t id) const;
    void finish(std::uint64_t id);

    std::vector<std::unique_ptr<Job>> jobs_;
    std::uint64_t nextId_ = 1;
    std::uint64_t current_ = 0; // id whose outcome is wanted; 0 = none
    PipelineGraph* graph_ = nullptr;
    std::vector<NodeId> targets_;
    std::map<NodeId, std::string> definitions_; // of every node when the run started
    std::set<NodeId> running_;                  // nodes this run marked Running in graph_
};

} // namespace hlod::widgets

Q_DECLARE_METATYPE(hlod::widgets::BuiltHlod)
Q_DECLARE_METATYPE(std::vector<hlod::widgets::BuiltHlod>)
