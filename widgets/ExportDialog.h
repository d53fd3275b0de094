// File ▸ Export Package…: writes the package of one branch by running its Export node through
// the pipeline graph (the runner `hlod build` uses, StudioModel::runExports), with a progress
// bar and Cancel. The folder and the DLOD choice are the Export node's parameters: Export sets
// them on the node as one undoable step (saved with the project; `hlod build PROJECT` writes the
// same folder), then runs the node; only what is not up to date upstream of it runs.
// The dialog stays open when the export fails (message shown in it) and closes itself with
// accept() when it finished. Cancel stops a running export first (the package is written
// atomically: nothing is left behind).
// Object names for tests: "exportFolder" (line edit), "exportDlod" (check box), "exportButton",
// "exportProgress", "exportStatus".
#pragma once

#include <QDialog>

#include "pipeline/graph/PipelineGraph.h"

class QCheckBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;

namespace hlod::widgets {

class StudioModel;
class UndoAdapter;

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    // Exports Export node `exportNode` of `undo`'s document; `folder` is proposed when the node
    // has no output folder yet.
    ExportDialog(UndoAdapter& undo, StudioModel* model, NodeId exportNode, const QString& folder,
                 QWidget* parent = nullptr);

    NodeId exportNode() const { return node_; }
    QString folder() const;
    void setFolder(const QString& folder);
    // Sets the node's folder and DLOD choice, then starts its run; false when the folder is
    // empty, a run is going on, or the parameters were refused.
    bool startExport();
    bool running() const { return running_; }
    void reject() override; // Cancel: stops a running export first

Q_SIGNALS:
    // The package was written to `folder`.
    void exported(const QString& folder, qint64 files, qint64 bytes);

private:
    void browse();
    void onFinished();
    void setRunning(bool running);

    UndoAdapter& undo_;
    StudioModel* model_;
    NodeId node_;
    bool running_ = false;
    QLineEdit* folder_ = nullptr;
    QPushButton* browse_ = nullptr;
    QCheckBox* dlod_ = nullptr;
    QProgressBar* bar_ = nullptr;
    QLabel* status_ = nullptr;
    QPushButton* export_ = nullptr;
    QPushButton* cancel_ = nullptr;
};

} // namespace hlod::widgets
