// The statistics dock (see StatsPanel.h).
#include "widgets/StatsPanel.h"

#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QScrollArea>
#include <QScrollBar>
#include <QTableWidget>
#include <QVBoxLayout>

#include "pipeline/proxy/BakeStats.h"
#include "widgets/BuildWarnings.h"
#include "widgets/DisplayController.h"
#include "widgets/NumberFormat.h"
#include "widgets/StatsPlot.h"
#include "widgets/StudioModel.h"

namespace hlod::widgets {

namespace {

QTableWidgetItem* numberItem(const QString& text, const QString& tip = {}) {
    auto* item = new QTableWidgetItem(text);
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    if (!tip.isEmpty()) item->setToolTip(tip);
    return item;
}

QTableWidget* makeTable(int rows, int columns, QWidget* parent) {
    auto* table = new QTableWidget(rows, columns, parent);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setSelectionMode(QAbstractItemView::NoSelection);
    table->setFocusPolicy(Qt::NoFocus);
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->horizontalHeader()->setStretchLastSection(false);
    table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    table->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // As tall as its rows: the panel scrolls as a whole when the dock is short.
    table->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    return table;
}

QString percent(double share) {
    const double p = share * 100.0;
    return QLocale().toString(p, 'f', p < 9.95 ? 1 : 0) + QStringLiteral(" %");
}

// Exactly as tall and as wide as the header and the rows: the tables never scroll, the panel
// does (vertically when the dock is short, horizontally when it is narrow).
void fitSize(QTableWidget* table) {
    table->resizeColumnsToContents();
    table->resizeRowsToContents();
    int h =
        table->horizontalHeader()->isVisible() ? table->horizontalHeader()->sizeHint().height() : 0;
    for (int r = 0; r < table->rowCount(); ++r)
        h += table->rowHeight(r);
    int w = table->verticalHeader()->isVisible() ? table->verticalHeader()->sizeHint().width() : 0;
    for (int c = 0; c < table->columnCount(); ++c)
        w += table->columnWidth(c);
    table->setFixedHeight(h + 2 * table->frameWidth());
    table->setMinimumWidth(w + 2 * table->frameWidth());
}

// "0.12–1.12": both ends in scene units (the column header names them).
QString budgetRange(const LevelRow& row) {
    const QString hi = formatLength(row.budgetMax);
    const QString lo = formatLength(row.budgetMin);
    return lo == hi ? hi : lo + QStringLiteral("–") + hi;
}

QLabel* note(QWidget* parent) {
    auto* label = new QLabel(parent);
    label->setWordWrap(true);
    label->setTextFormat(Qt::PlainText);
    return label;
}

} // namespace

StatsPanel::StatsPanel(StudioModel* model, QWidget* parent) : QWidget(parent), model_(model) {
    auto* content = new QWidget;
    table_ = makeTable(RowCount, ColumnCount, content);
    table_->setHorizontalHeaderLabels(
        {tr("Triangles"), tr("Vertices"), tr("Meshes"), tr("Geometry")});
    table_->horizontalHeaderItem(SizeColumn)
        ->setToolTip(tr("Bytes of the geometry as the package's GLB files store it (MB = 10⁶ "
                        "bytes); the package on disk (below, and in Compare) adds textures, "
                        "tile files and file-system blocks"));
    table_->setVerticalHeaderLabels({tr("Original"), tr("HLOD")});
    table_->verticalHeaderItem(HlodRow)->setToolTip(
        tr("The original meshes plus every proxy: what the package stores (as in the thesis' "
           "tables), not what is drawn at once"));
    note_ = note(content);
    levels_ = makeTable(0, LevelColumnCount, content);
    levels_->verticalHeader()->hide();
    levels_->setHorizontalHeaderLabels({tr("Level"), tr("Nodes"), tr("Children"),
                                        tr("Budget\n(%1)").arg(lengthUnit()), tr("Triangles"),
                                        tr("Share")});
    const QStringList tips{tr("Level in the tree: 0 holds the original meshes"),
                           tr("Nodes whose level is exactly this one (level 0: meshes). The "
                              "viewport's Clusters mode counts the same, and says apart the "
                              "lower nodes no cluster of the level holds"),
                           tr("Mean number of children of this level's clusters"),
                           tr("Error budget: how far a proxy of this level may deviate from what "
                              "it replaces (pixel error × cluster diameter / screen size), in %1")
                               .arg(lengthUnit()),
                           tr("Triangles of all proxies of this level (level 0: of the original "
                              "meshes)"),
                           tr("Those triangles as a share of the original scene's")};
    for (int c = 0; c < LevelColumnCount; ++c)
        levels_->horizontalHeaderItem(c)->setToolTip(tips[c]);
    economy_ = note(content);
    summary_ = note(content);
    branch_ = new QLabel(content);
    branch_->setObjectName(QStringLiteral("StatsBranch"));
    branch_->setWordWrap(true);
    branch_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Above the scrolled part, as wide as the dock: always in sight, never cut (issue 31 #7).
    warning_ = note(this);
    warning_->setObjectName(QStringLiteral("StatsWarning"));
    warning_->setStyleSheet(QStringLiteral("QLabel { background: #fff1c2; color: #5a3d00; "
                                           "border: 1px solid #d9a400; padding: 4px; }"));
    warning_->hide();
    auto* column = new QVBoxLayout(content);
    column->setContentsMargins(0, 0, 0, 0);
    for (QWidget* w :
         std::initializer_list<QWidget*>{branch_, table_, note_, levels_, economy_, summary_})
        column->addWidget(w);
    column->addStretch(1);
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(content);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    plot_ = new StatsPlot(this);
    plot_->setMinimumHeight(90);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(warning_);
    layout->addWidget(scroll, 3);
    layout->addWidget(plot_, 1);
    connect(model_, &StudioModel::sceneChanged, this, &StatsPanel::refresh);
    connect(model_, &StudioModel::buildFinished, this, &StatsPanel::refresh);
    connect(model_, &StudioModel::shownBakeChanged, this, &StatsPanel::refresh);
    connect(model_, &StudioModel::nodeStatusChanged, this, &StatsPanel::refreshBranch);
    refresh();
}

void StatsPanel::refreshBranch() {
    const NodeId shown = model_->shownBake();
    const PipelineGraph* g = model_->graph();
    if (shown == kNoNode || !g || !g->hasNode(shown)) {
        branch_->setText(model_->scene() ? tr("No Bake node is shown: pick a branch in the "
                                              "toolbar or click a Bake node")
                                         : QString());
        return;
    }
    const NodeStatus status = g->status(shown);
    const QString state = !model_->hasBuild()              ? tr("not built yet")
                          : status == NodeStatus::UpToDate ? tr("up to date")
                          : status == NodeStatus::Running  ? tr("building; its last build shown")
                                                           : tr("changed since this build");
    branch_->setText(
        tr("<b>Branch:</b> %1 (%2)").arg(model_->branchLabel(shown).toHtmlEscaped(), state));
}

void StatsPanel::refresh() {
    refreshBranch();
    const QLocale locale;
    auto fill = [&](int row, const GeometryStats* s) {
        auto text = [&](std::size_t n) {
            return s ? locale.toString(static_cast<qulonglong>(n)) : QStringLiteral("–");
        };
        table_->setItem(row, TrianglesColumn, numberItem(text(s ? s->triangles : 0)));
        table_->setItem(row, VerticesColumn, numberItem(text(s ? s->vertices : 0)));
        table_->setItem(row, MeshesColumn, numberItem(text(s ? s->meshes : 0)));
        table_->setItem(
            row, SizeColumn,
            numberItem(s ? formatMegabytes(s->bytes) : QStringLiteral("–"),
                       tr("Geometry as the package's GLB files store it (MB = 10⁶ bytes)")));
    };
    const auto& scene = model_->scene();
    GeometryStats original;
    if (scene) original = model_->hasBuild() ? model_->built().original : originalStats(*scene);
    fill(OriginalRow, scene ? &original : nullptr);
    fill(HlodRow, model_->hasBuild() ? &model_->built().hlod : nullptr);
    refreshLevels();
    fitSize(table_);
    fitSize(levels_);
    plot_->clear();
    const QString warning =
        model_->hasBuild() ? dissolveWarning(model_->built(), model_->clusterLabels()) : QString();
    warning_->setText(warning);
    warning_->setVisible(!warning.isEmpty());
    if (!model_->hasBuild()) {
        note_->setText(scene ? tr("Build the HLOD (Build ▸ Build HLOD, Ctrl+B) to compare.")
                             : QString());
        economy_->clear();
        summary_->clear();
        return;
    }
    const BuiltHlod& b = model_->built();
    const BakeResult& bake = *b.build->bake;
    const std::size_t proxyTriangles =
        b.hlod.triangles - std::min(b.hlod.triangles, b.original.triangles);
    const QString root = b.share.rootProxy > 0.0
                             ? tr("the root's alone %1").arg(percent(b.share.rootProxy))
                             : tr("the root has none: it always draws its children");
    note_->setText(tr("HLOD: the original meshes plus all %1 proxies, as the thesis' tables "
                      "count it: what the package stores, not what is drawn at once. The "
                      "proxies hold %2 triangles, %3 of the original (%4).")
                       .arg(b.hlod.meshes - std::min(b.hlod.meshes, b.original.meshes))
                       .arg(locale.toString(static_cast<qulonglong>(proxyTriangles)))
                       .arg(percent(b.share.allProxies), root));
    const double ratio = b.build->bakeParams.proxyRatio;
    economy_->setText(
        (bake.dissolved == 1 ? tr("Proxy economy: 1 cluster dissolved")
                             : tr("Proxy economy: %1 clusters dissolved").arg(bake.dissolved)) +
        QLatin1Char(' ') +
        tr("(a proxy must hold at most %1 of the triangles it replaces; a dissolved cluster's "
           "children hang from its parent).")
            .arg(percent(ratio)));
    QString package;
    if (b.package.files > 0)
        package = QLatin1Char(' ') + tr("Package on disk: %1 in %2 files (what hlod build and "
                                        "Compare report; Geometry above is the GLB geometry "
                                        "alone).")
                                         .arg(formatMegabytes(b.package.bytesOnDisk))
                                         .arg(b.package.files);
    summary_->setText(tr("%1: %2 nodes, height %3; %4 proxies baked, %5 reused; built in %6 s.")
                          .arg(QString::fromStdString(b.hlod.version))
                          .arg(b.build->tree->nodes.size())
                          .arg(b.build->tree->height())
                          .arg(bake.baked)
                          .arg(bake.reused)
                          .arg(locale.toString(b.seconds, 'f', 2)) +
                      package);
}

void StatsPanel::refreshLevels() {
    const std::vector<LevelRow> rows =
        model_->hasBuild() ? model_->built().levels : std::vector<LevelRow>{};
    levels_->setRowCount(static_cast<int>(rows.size()));
    levels_->setVisible(!rows.empty());
    const QLocale locale;
    for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
        const LevelRow& row = rows[r];
        const bool meshes = row.level == 0;
        levels_->setItem(r, LevelLevelColumn,
                         numberItem(QString::number(row.level),
                                    meshes ? tr("Level 0: the original meshes") : QString()));
        levels_->setItem(r, LevelNodesColumn,
                         numberItem(locale.toString(static_cast<qulonglong>(row.nodes))));
        levels_->setItem(
            r, LevelChildrenColumn,
            numberItem(meshes ? QStringLiteral("–") : locale.toString(row.meanChildren, 'f', 1)));
        levels_->setItem(r, LevelBudgetColumn,
                         numberItem(meshes ? QStringLiteral("–") : budgetRange(row)));
        levels_->setItem(r, LevelTrianglesColumn,
                         numberItem(locale.toString(static_cast<qulonglong>(row.triangles))));
        levels_->setItem(r, LevelShareColumn, numberItem(percent(row.share)));
    }
}

void StatsPanel::showFrame(const FrameStats& stats) {
    plot_->setCurrent(stats.drawCalls, stats.triangles);
}

} // namespace hlod::widgets
