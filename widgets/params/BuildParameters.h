// The "Parameters" dock of the editor: the parameter panel (ParameterPanel) of the node selected
// in the node graph, and only that node's (issue 29: two Cluster nodes never show two "Volume"
// fields at once), under a title naming it ("Cluster #5 'spheres'"), with Build and Cancel
// buttons for the shown branch. Without a selection it says how to get one. Every edit is a
// SetParameter command on the document (undoable), and runs take their parameters from the
// document's graph, so nothing here holds parameters.
// The panel follows the document: when the selected node is removed (or the document replaced),
// it shows nothing.
#pragma once

#include <QWidget>

#include "pipeline/graph/PipelineGraph.h"

class QGroupBox;
class QLabel;
class QPushButton;
class QScrollArea;

namespace hlod::widgets {

class ParameterPanel;
class StudioModel;
class UndoAdapter;

class BuildParameters : public QWidget {
    Q_OBJECT
public:
    BuildParameters(UndoAdapter& undo, StudioModel* model, QWidget* parent = nullptr);

    // Shows the parameters of `node` (the node graph's selection; kNoNode: none).
    void showNode(NodeId node);
    NodeId shownNode() const { return shown_; }
    // The panel, showing shownNode()'s parameters (it is empty when none is selected).
    ParameterPanel* panel() const { return panel_; }
    QGroupBox* group() const { return box_; }
    QLabel* hint() const { return hint_; }
    QPushButton* buildButton() const { return build_; }
    QPushButton* cancelButton() const { return cancel_; }

private:
    void updateButtons();
    void followDocument();
    void updateTitle();

    UndoAdapter& undo_;
    StudioModel* model_;
    ParameterPanel* panel_ = nullptr;
    QGroupBox* box_ = nullptr;
    QLabel* hint_ = nullptr;
    QScrollArea* scroll_ = nullptr;
    QPushButton* build_ = nullptr;
    QPushButton* cancel_ = nullptr;
    NodeId shown_ = kNoNode;
};

} // namespace hlod::widgets
