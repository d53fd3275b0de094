// File ▸ Export Package…: choose a folder, then the package of the current build is written in
// the background (PackageExporter) with a progress bar and Cancel. The dialog stays open when
// the export fails (message shown in it) and closes itself with accept() when it finished.
// Object names for tests: "exportFolder" (line edit), "exportDlod" (check box), "exportButton",
// "exportProgress", "exportStatus".
#pragma once

#include <QDialog>

#include "widgets/PackageExporter.h"

class QCheckBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;

namespace hlod::widgets {

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    // `request` holds everything but the folder (and the DLOD choice), taken from the dialog.
    ExportDialog(ExportRequest request, const QString& folder, QWidget* parent = nullptr);

    QString folder() const;
    void setFolder(const QString& folder);
    // Starts the export with the dialog's choices; false when the folder is empty or an export
    // already runs.
    bool startExport();
    PackageExporter* exporter() const { return exporter_; }

Q_SIGNALS:
    // An export to `folder` started (the exporter's finished, failed or cancelled follows).
    void exportStarted(const QString& folder);

protected:
    void reject() override; // Cancel: stops a running export first

private:
    void browse();
    void onProgress(const QString& stage, qint64 done, qint64 total);
    void onFinished(const QString& folder, qint64 files, qint64 bytes);
    void onFailed(const QString& message);
    void setRunning(bool running);

    ExportRequest request_;
    PackageExporter* exporter_ = nullptr;
    QLineEdit* folder_ = nullptr;
    QPushButton* browse_ = nullptr;
    QCheckBox* dlod_ = nullptr;
    QProgressBar* bar_ = nullptr;
    QLabel* status_ = nullptr;
    QPushButton* export_ = nullptr;
    QPushButton* cancel_ = nullptr;
};

} // namespace hlod::widgets
