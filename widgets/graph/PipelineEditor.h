// The "Pipeline" dock of the editor (issue #7, issue 29): the node graph of the open document
// (NodeGraphView over Document::graph()) with an "Add Node" button, "Fit" (key F in the view)
// and a line of help.
//
// Edits: every gesture of the view becomes a document command through the UndoAdapter, so it
// is undoable and saved with the project: add (AddNode: from the button, placed to the right of
// the selected node and connected to it when it can take its output, else on a free spot; from
// the background's context menu at the click, moved to a free spot), remove (RemoveNode: Delete
// or the node's context menu), connect (ConnectNodes: drag from an output port to an input
// port), disconnect (DisconnectNodes: a connection's context menu; DisconnectNode: a node's),
// duplicate (DuplicateNodes: the node alone, or "Duplicate Branch": the node and everything
// downstream, placed below the originals where no node is), rename (RenameNode, asked in a
// dialog), move (MoveNode: drag a box). Refused edits (a cycle, a port type mismatch, an input
// already connected) are reported by the UndoAdapter's commandFailed. The view is redrawn after
// every document change; it is fitted only when a document is opened or on request.
// Selection: clicking a node emits nodeSelected(id) (the main window shows that node's
// parameters in the Parameters dock); clicking a Bake node also makes it the shown one
// (StudioModel::setShownBake), which the view outlines.
// Statuses: the graph's, as the editor's runs bring them in node by node (GraphRunner), with
// the running step's progress in its header; nothing here derives a status.
#pragma once

#include <QPointF>
#include <QString>
#include <QWidget>

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
    QToolButton* fitButton() const { return fit_; }

    // The requests of the view, as commands (public for tests and menus). addNode places the
    // node on a free spot near (x, y); addAfter adds a node of `kind` to the right of `input`,
    // connected to it.
    bool addNode(NodeKind kind, double x, double y);
    bool addAfter(NodeKind kind, NodeId input);
    bool removeNode(NodeId node);
    bool connectNodes(const Connection& c);
    bool disconnectNodes(const Connection& c);
    bool disconnectNode(NodeId node);
    bool duplicate(NodeId node, bool branch);
    bool renameNode(NodeId node, const QString& name);
    bool moveNode(NodeId node, double x, double y);
    // Asks for a node's name in a dialog, then renames it.
    void askRename(NodeId node);

    // The top-left corner nearest to `wanted` (searching down, then right) where a box of
    // `kind` overlaps no node of the graph.
    QPointF freeSpot(NodeKind kind, QPointF wanted) const;

Q_SIGNALS:
    void nodeSelected(quint32 node);

private:
    void onDocumentChanged();
    void onNodeSelected(quint32 node);
    // Adds the kind chosen in the Add Node menu: after the selected node when it fits.
    void addFromButton(NodeKind kind);

    ProjectSession* session_;
    StudioModel* model_;
    NodeGraphView* view_ = nullptr;
    QToolButton* add_ = nullptr;
    QToolButton* fit_ = nullptr;
};

} // namespace hlod::widgets
