// The export dialog (see ExportDialog.h).
#include "widgets/ExportDialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace hlod::widgets {

ExportDialog::ExportDialog(ExportRequest request, const QString& folder, QWidget* parent)
    : QDialog(parent), request_(std::move(request)), exporter_(new PackageExporter(this)) {
    setWindowTitle(tr("Export Package"));
    folder_ = new QLineEdit(folder);
    folder_->setObjectName(QStringLiteral("exportFolder"));
    folder_->setToolTip(tr("The package folder: tileset.json, tiles/*.glb and hlod.json"));
    browse_ = new QPushButton(tr("Browse…"));
    connect(browse_, &QPushButton::clicked, this, &ExportDialog::browse);
    auto* row = new QHBoxLayout;
    row->addWidget(folder_, 1);
    row->addWidget(browse_);
    dlod_ = new QCheckBox(tr("Include the DLOD chain statistics (slower)"));
    dlod_->setObjectName(QStringLiteral("exportDlod"));
    dlod_->setChecked(request_.dlod);
    bar_ = new QProgressBar;
    bar_->setObjectName(QStringLiteral("exportProgress"));
    bar_->setRange(0, 1000);
    bar_->setValue(0);
    status_ = new QLabel;
    status_->setObjectName(QStringLiteral("exportStatus"));
    status_->setWordWrap(true);

    auto* buttons = new QDialogButtonBox;
    export_ = buttons->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
    export_->setObjectName(QStringLiteral("exportButton"));
    cancel_ = buttons->addButton(QDialogButtonBox::Cancel);
    connect(export_, &QPushButton::clicked, this, &ExportDialog::startExport);
    connect(cancel_, &QPushButton::clicked, this, &ExportDialog::reject);

    auto* form = new QFormLayout;
    form->addRow(tr("Folder:"), row);
    form->addRow(QString(), dlod_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(bar_);
    layout->addWidget(status_);
    layout->addWidget(buttons);
    resize(560, sizeHint().height());

    connect(exporter_, &PackageExporter::progressed, this, &ExportDialog::onProgress);
    connect(exporter_, &PackageExporter::finished, this, &ExportDialog::onFinished);
    connect(exporter_, &PackageExporter::failed, this, &ExportDialog::onFailed);
    connect(exporter_, &PackageExporter::cancelled, this, [this] {
        setRunning(false);
        status_->setText(tr("Export cancelled; nothing was written"));
    });
    setRunning(false);
}

QString ExportDialog::folder() const { return folder_->text().trimmed(); }
void ExportDialog::setFolder(const QString& folder) { folder_->setText(folder); }

void ExportDialog::browse() {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Export Package To"), folder());
    if (!dir.isEmpty()) folder_->setText(dir);
}

bool ExportDialog::startExport() {
    if (folder().isEmpty()) {
        status_->setText(tr("Choose a folder for the package"));
        return false;
    }
    ExportRequest request = request_;
    request.output = folder().toStdString();
    request.dlod = dlod_->isChecked();
    if (!exporter_->start(std::move(request))) return false;
    Q_EMIT exportStarted(folder());
    status_->setText(tr("Exporting…"));
    bar_->setRange(0, 0);
    setRunning(true);
    return true;
}

void ExportDialog::reject() {
    if (exporter_->busy()) {
        exporter_->cancel(); // cancelled() follows; the dialog stays to say so
        return;
    }
    QDialog::reject();
}

void ExportDialog::onProgress(const QString& stage, qint64 done, qint64 total) {
    status_->setText(total > 0 ? tr("%1 %2/%3").arg(stage).arg(done).arg(total) : stage);
    if (total > 0) {
        bar_->setRange(0, 1000);
        bar_->setValue(static_cast<int>(1000.0 * double(done) / double(total)));
    } else {
        bar_->setRange(0, 0);
    }
}

void ExportDialog::onFinished(const QString& folder, qint64 files, qint64 bytes) {
    setRunning(false);
    bar_->setRange(0, 1000);
    bar_->setValue(1000);
    status_->setText(
        tr("Wrote %1 files (%2) to %3").arg(files).arg(QLocale().formattedDataSize(bytes), folder));
    accept();
}

void ExportDialog::onFailed(const QString& message) {
    setRunning(false);
    bar_->setRange(0, 1000);
    bar_->setValue(0);
    status_->setText(message);
}

void ExportDialog::setRunning(bool running) {
    folder_->setEnabled(!running);
    browse_->setEnabled(!running);
    dlod_->setEnabled(!running);
    export_->setEnabled(!running);
}

} // namespace hlod::widgets
