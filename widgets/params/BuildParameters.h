// The "Parameters" dock of the editor: the parameter panels (ParameterPanel) of the document's
// Cluster and Bake nodes, one above the other, with Build and Cancel buttons. It replaces the
// old BuildPanel form: every edit is a SetParameter command on the document (undoable), and
// StudioModel takes its build settings from the document, so nothing here holds parameters.
// Call setNodes() after the document was replaced (a project opened): node ids may differ.
#pragma once

#include <QWidget>

#include "pipeline/graph/PipelineGraph.h"

class QPushButton;

namespace hlod::widgets {

class ParameterPanel;
class StudioModel;
class UndoAdapter;

class BuildParameters : public QWidget {
    Q_OBJECT
public:
    BuildParameters(UndoAdapter& undo, StudioModel* model, QWidget* parent = nullptr);

    void setNodes(NodeId clusterNode, NodeId bakeNode);
    ParameterPanel* clusterPanel() const { return cluster_; }
    ParameterPanel* bakePanel() const { return bake_; }
    QPushButton* buildButton() const { return build_; }
    QPushButton* cancelButton() const { return cancel_; }

private:
    void updateButtons();

    StudioModel* model_;
    ParameterPanel* cluster_ = nullptr;
    ParameterPanel* bake_ = nullptr;
    QPushButton* build_ = nullptr;
    QPushButton* cancel_ = nullptr;
};

} // namespace hlod::widgets
