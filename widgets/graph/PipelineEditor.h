// The "Pipeline" dock of the editor (issue #7): the node graph of the open document
// (NodeGraphView over Document::graph()) with a line of help and an "Add Node" button.
//
// Edits: every gesture of the view becomes a document command through the UndoAdapter, so it
// is undoable: add (AddNode, from the button or the background's context menu), remove
// (RemoveNode: Delete or the node's context menu; the last node of a kind stays, since the
// editor builds and exports with the first node of each kind), connect (ConnectNodes: drag from an
// output port to an input port), disconnect (DisconnectNodes: a connection's context menu), move
// (MoveNode: drag a box). Refused edits (a cycle, a port type mismatch, an input already
// connected) are reported by the UndoAdapter's commandFailed. The view is redrawn after every
// document change.
// Selection: clicking a node emits nodeSelected(id) (the main window shows that node's
// parameters in the Parameters dock).
// Status colours: the editor does not run the document's graph, it builds in the background
// (StudioModel / HlodBuilder) with the first Import, Cluster and Bake nodes (Document's
// shortcuts). Their statuses are that build's: Import is up to date once the scene is open;
// during a build the stage that runs is "running" ("cluster", then "bake"), a failed stage
// "failed" (tooltip: the message) until the settings change; otherwise Cluster and Bake are up to
// date when the document's settings (HlodSettings: sameClustering, sameBaking) are the ones of
// the build shown, else pending. A bake parameter change leaves Cluster up to date: only the
// bake reruns. Export runs on File ▸ Export Package (issue 20 #3): running while the package is
// written, up to date once the package of exactly the shown build is written (tooltip: the
// folder), failed with the message, pending again when the build changes. Other nodes are not
// built by the editor: they show the graph's own run state (pending).
#pragma once

#include <optional>

#include <QString>
#include <QWidget>

#include "pipeline/doc/HlodBuild.h"
#include "pipeline/graph/PipelineGraph.h"

class QToolButton;

namespace hlod::widgets {

class NodeGraphView;
class ProjectSession;
class StudioModel;

class PipelineEditor : public QWidget {
    Q_OBJECT
public:
    PipelineEditor(ProjectSession* session, StudioModel* model, QWidget* parent = nullptr);

    NodeGraphView* view() const { return view_; }
    QToolButton* addButton() const { return add_; }
    // Recomputes the status colours (also done on every build and document change).
    void updateStatuses();

    // The requests of the view, as commands (public for tests and menus).
    bool addNode(NodeKind kind, double x, double y);
    bool removeNode(NodeId node);
    bool connectNodes(const Connection& c);
    bool disconnectNodes(const Connection& c);
    bool moveNode(NodeId node, double x, double y);

Q_SIGNALS:
    void nodeSelected(quint32 node);

private:
    void onDocumentChanged();
    // A free spot for a node added from the button: below the lowest node.
    QPointF freeSpot() const;

    ProjectSession* session_;
    StudioModel* model_;
    NodeGraphView* view_ = nullptr;
    QToolButton* add_ = nullptr;
    QString stage_;       // stage of the running build ("cluster", "bake"); empty when idle
    QString failedStage_; // stage of the last failed build; empty when none
    QString failedMessage_;
    std::optional<HlodSettings> failedSettings_; // what the failed build was given
};

} // namespace hlod::widgets
