// The "Parameters" dock of the editor: the parameter panels (ParameterPanel) of the document's
// Cluster and Bake nodes (the ones the editor's builds use), one above the other, with Build and
// Cancel buttons; above them, the panel of the node selected in the node graph (showNode) when
// that is another node (Import, Export, or a node the user added). Selecting the Cluster or Bake
// node marks and reveals its own group instead. Every edit is a SetParameter command on the
// document (undoable), and StudioModel takes its build settings from the document, so nothing
// here holds parameters.
// The panels follow the document: after a change that removes or adds the first Cluster or Bake
// node, or removes the selected node, they show what the document has then. Call setNodes()
// after the document was replaced (a project opened): node ids may differ.
#pragma once

#include <QWidget>

#include "pipeline/graph/PipelineGraph.h"

class QGroupBox;
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

    void setNodes(NodeId clusterNode, NodeId bakeNode);
    // Shows the parameters of `node` (the node graph's selection; kNoNode: none).
    void showNode(NodeId node);
    NodeId shownNode() const { return shown_; }
    // The panel that shows `shownNode()` (nullptr when none is selected).
    ParameterPanel* selectedPanel() const;

    ParameterPanel* clusterPanel() const { return cluster_; }
    ParameterPanel* bakePanel() const { return bake_; }
    ParameterPanel* otherPanel() const { return other_; }
    QPushButton* buildButton() const { return build_; }
    QPushButton* cancelButton() const { return cancel_; }

private:
    void updateButtons();
    void followDocument();
    void updateGroups();

    UndoAdapter& undo_;
    StudioModel* model_;
    ParameterPanel* cluster_ = nullptr;
    ParameterPanel* bake_ = nullptr;
    ParameterPanel* other_ = nullptr;
    QGroupBox* clusterBox_ = nullptr;
    QGroupBox* bakeBox_ = nullptr;
    QGroupBox* otherBox_ = nullptr;
    QScrollArea* scroll_ = nullptr;
    QPushButton* build_ = nullptr;
    QPushButton* cancel_ = nullptr;
    NodeId shown_ = kNoNode;
};

} // namespace hlod::widgets
