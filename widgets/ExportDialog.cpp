// The export dialog (see ExportDialog.h).
#include "widgets/ExportDialog.h"
#include "widgets/NumberFormat.h"

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

#include "widgets/StudioModel.h"
#include "widgets/compare/UseConfiguration.h"
#include "widgets/doc/UndoAdapter.h"

namespace hlod::widgets {

ExportDialog::ExportDialog(UndoAdapter& undo, StudioModel* model, NodeId exportNode,
                           const QString& folder, QWidget* parent)
    : QDialog(parent), undo_(undo), model_(model), node_(exportNode) {
    const PipelineGraph& g = undo_.document().graph();
    const bool known = g.hasNode(node_);
    const QString label = known ? QString::fromStdString(describeNode(g.node(node_))) : QString();
    setWindowTitle(tr("Export Package — %1").arg(label));
    const QString output =
        known ? QString::fromStdString(paramText(g.node(node_).params, "output")) : QString();
    folder_ = new QLineEdit(output.isEmpty() ? folder : output);
    folder_->setObjectName(QStringLiteral("exportFolder"));
    folder_->setToolTip(tr("The package folder: tileset.json, tiles/*.glb and hlod.json"));
    browse_ = new QPushButton(tr("Browse…"));
    connect(browse_, &QPushButton::clicked, this, &ExportDialog::browse);
    auto* row = new QHBoxLayout;
    row->addWidget(folder_, 1);
    row->addWidget(browse_);
    dlod_ = new QCheckBox(tr("Include the DLOD chain statistics (slower)"));
    dlod_->setObjectName(QStringLiteral("exportDlod"));
    dlod_->setChecked(known ? paramBool(g.node(node_).params, "dlod") : true);
    bar_ = new QProgressBar;
    bar_->setObjectName(QStringLiteral("exportProgress"));
    bar_->setRange(0, 1000);
    bar_->setValue(0);
    status_ = new QLabel(
        known ? tr("Branch: %1").arg(model_->branchLabel(g.upstreamOfKind(node_, NodeKind::Bake)))
              : QString());
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

    connect(model_, &StudioModel::nodeProgress, this,
            [this](quint32, const QString& stage, qint64 done, qint64 total) {
                if (!running_) return;
                status_->setText(total > 0 ? tr("%1 %2/%3").arg(stage).arg(done).arg(total)
                                           : stage);
                if (total > 0) {
                    bar_->setRange(0, 1000);
                    bar_->setValue(static_cast<int>(1000.0 * double(done) / double(total)));
                } else {
                    bar_->setRange(0, 0);
                }
            });
    connect(model_, &StudioModel::runFinished, this, &ExportDialog::onFinished);
    connect(model_, &StudioModel::buildFailed, this, [this](const QString& message) {
        if (!running_) return;
        setRunning(false);
        bar_->setRange(0, 1000);
        bar_->setValue(0);
        status_->setText(message);
    });
    connect(model_, &StudioModel::buildCancelled, this, [this] {
        if (!running_) return;
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
    if (running_ || model_->building()) return false;
    const PipelineGraph& g = undo_.document().graph();
    if (!g.hasNode(node_)) return false;
    // The node's folder and DLOD choice, as one undoable step (nothing when they are its own).
    const ParamValues& params = g.node(node_).params;
    std::vector<std::unique_ptr<SetParameter>> parts;
    const std::string output = folder().toStdString();
    if (paramText(params, "output") != output)
        parts.push_back(std::make_unique<SetParameter>(node_, "output", output));
    if (paramBool(params, "dlod") != dlod_->isChecked())
        parts.push_back(std::make_unique<SetParameter>(node_, "dlod", dlod_->isChecked()));
    if (!parts.empty()) {
        const std::string text = "Export " + nodeLabel(g.node(node_)) + " to " + output;
        if (!undo_.execute(std::make_unique<SetParameters>(text, std::move(parts)))) return false;
    }
    status_->setText(tr("Exporting…"));
    bar_->setRange(0, 0);
    setRunning(true);
    model_->runExports({node_});
    if (!model_->building()) { // nothing could start (no scene)
        setRunning(false);
        status_->setText(tr("Nothing to export: open a scene first"));
        return false;
    }
    return true;
}

void ExportDialog::reject() {
    if (running_) {
        model_->cancelBuild(); // buildCancelled follows; the dialog stays to say so
        return;
    }
    QDialog::reject();
}

void ExportDialog::onFinished() {
    if (!running_) return;
    setRunning(false);
    const PipelineGraph& g = undo_.document().graph();
    const NodeOutput* out = g.hasNode(node_) ? g.output(node_) : nullptr;
    if (!out || !out->exported || g.status(node_) != NodeStatus::UpToDate) {
        status_->setText(tr("The export did not finish (the document changed meanwhile)"));
        return;
    }
    const PackageSummary& written = out->exported->written;
    const QString dir = QString::fromStdString(out->exported->output.string());
    bar_->setRange(0, 1000);
    bar_->setValue(1000);
    status_->setText(tr("Wrote %1 files (%2) to %3")
                         .arg(written.files)
                         .arg(formatMegabytes(written.bytes), dir));
    Q_EMIT exported(dir, static_cast<qint64>(written.files), static_cast<qint64>(written.bytes));
    accept();
}

void ExportDialog::setRunning(bool running) {
    running_ = running;
    folder_->setEnabled(!running);
    browse_->setEnabled(!running);
    dlod_->setEnabled(!running);
    export_->setEnabled(!running);
}

} // namespace hlod::widgets
