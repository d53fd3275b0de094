// The statistics dock (see StatsPanel.h).
#include "widgets/StatsPanel.h"

#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QTableWidget>
#include <QVBoxLayout>

#include "pipeline/proxy/BakeStats.h"
#include "widgets/DisplayController.h"
#include "widgets/StatsPlot.h"
#include "widgets/StudioModel.h"

namespace hlod::widgets {

namespace {

QTableWidgetItem* numberItem(const QString& text) {
    auto* item = new QTableWidgetItem(text);
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    return item;
}

} // namespace

StatsPanel::StatsPanel(StudioModel* model, QWidget* parent) : QWidget(parent), model_(model) {
    table_ = new QTableWidget(RowCount, ColumnCount, this);
    table_->setHorizontalHeaderLabels({tr("Triangles"), tr("Vertices"), tr("Meshes"), tr("MB")});
    table_->setVerticalHeaderLabels({tr("Original"), tr("HLOD")});
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    table_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    table_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    summary_ = new QLabel(this);
    summary_->setWordWrap(true);
    plot_ = new StatsPlot(this);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(table_);
    layout->addWidget(summary_);
    layout->addWidget(plot_, 1);
    connect(model_, &StudioModel::sceneChanged, this, &StatsPanel::refresh);
    connect(model_, &StudioModel::buildFinished, this, &StatsPanel::refresh);
    refresh();
}

void StatsPanel::refresh() {
    const QLocale locale;
    auto fill = [&](int row, const GeometryStats* s) {
        auto text = [&](std::size_t n) {
            return s ? locale.toString(static_cast<qulonglong>(n)) : QStringLiteral("–");
        };
        table_->setItem(row, TrianglesColumn, numberItem(text(s ? s->triangles : 0)));
        table_->setItem(row, VerticesColumn, numberItem(text(s ? s->vertices : 0)));
        table_->setItem(row, MeshesColumn, numberItem(text(s ? s->meshes : 0)));
        table_->setItem(row, SizeColumn,
                        numberItem(s ? locale.toString(double(s->bytes) / 1.0e6, 'f', 2)
                                     : QStringLiteral("–")));
    };
    const auto& scene = model_->scene();
    GeometryStats original;
    if (scene) original = model_->hasBuild() ? model_->built().original : originalStats(*scene);
    fill(OriginalRow, scene ? &original : nullptr);
    fill(HlodRow, model_->hasBuild() ? &model_->built().hlod : nullptr);
    if (model_->hasBuild()) {
        const BuiltHlod& b = model_->built();
        table_->setVerticalHeaderItem(HlodRow,
                                      new QTableWidgetItem(QString::fromStdString(b.hlod.version)));
        summary_->setText(tr("%1 nodes, height %2; %3 proxies baked, %4 reused; built in %5 s")
                              .arg(b.build->tree.nodes.size())
                              .arg(b.build->tree.height())
                              .arg(b.build->bake.baked)
                              .arg(b.build->bake.reused)
                              .arg(locale.toString(b.seconds, 'f', 2)));
    } else {
        table_->setVerticalHeaderItem(HlodRow, new QTableWidgetItem(tr("HLOD")));
        summary_->setText(scene ? tr("Build the HLOD (Build ▸ Build HLOD, Ctrl+B) to compare.")
                                : QString());
    }
    plot_->clear();
}

void StatsPanel::showFrame(const FrameStats& stats) {
    plot_->setCurrent(stats.drawCalls, stats.triangles);
}

} // namespace hlod::widgets
