// The comparison's statistics table (see CompareTable.h).
#include "widgets/compare/CompareTable.h"

#include <QHeaderView>
#include <QLocale>

#include "widgets/DisplayController.h"
#include "widgets/GraphRunner.h"
#include "widgets/NumberFormat.h"

namespace hlod::widgets {

namespace {

const QColor kBetterBackground(198, 236, 198);
const QColor kBetterText(20, 80, 20);

} // namespace

CompareTable::CompareTable(QWidget* parent) : QTableWidget(RowCount, 2, parent) {
    setHorizontalHeaderLabels({tr("Left"), tr("Right")});
    const QStringList rows = {tr("Draw calls (now)"), tr("Triangles (now)"), tr("Tree nodes"),
                              tr("Proxy triangles"), tr("Package on disk")};
    const QStringList tips = {
        tr("Draw calls of the current frame for the linked camera (HLOD preview)"),
        tr("Triangles drawn in the current frame for the linked camera"),
        tr("Nodes of the cluster tree: leaves (one per mesh instance) and clusters"),
        tr("Triangles of all proxies of the inner nodes together"),
        tr("Bytes on disk of the package hlod build writes for this side (compressed, the "
           "allocated blocks of all its files): the figure hlod build prints; MB = 10⁶ bytes, "
           "as in Statistics")};
    for (int r = 0; r < RowCount; ++r) {
        auto* header = new QTableWidgetItem(rows[r]);
        header->setToolTip(tips[r] + QLatin1Char('\n') + tr("Lower is better."));
        setVerticalHeaderItem(r, header);
        for (int c = 0; c < 2; ++c) {
            auto* item = new QTableWidgetItem(QStringLiteral("–"));
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            setItem(r, c, item);
        }
    }
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setSelectionMode(QAbstractItemView::NoSelection);
    setFocusPolicy(Qt::NoFocus);
    horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);
}

void CompareTable::setSideTitle(Side side, const QString& title) {
    horizontalHeaderItem(side)->setText(title);
}

void CompareTable::setBuilt(Side side, const BuiltHlod* built) {
    auto& v = values_;
    if (built && built->build) {
        v[NodesRow][side] = built->build->tree->nodes.size();
        v[ProxyTrianglesRow][side] = built->build->bake->proxyTriangles;
        v[PackageRow][side] = built->package.bytesOnDisk;
    } else {
        for (Row row : {DrawCallsRow, TrianglesRow, NodesRow, ProxyTrianglesRow, PackageRow})
            v[row][side].reset();
    }
    for (int r = 0; r < RowCount; ++r)
        refreshRow(static_cast<Row>(r));
}

void CompareTable::setFrame(Side side, const FrameStats& frame) {
    if (!values_[NodesRow][side]) return; // a frame without a build draws nothing to compare
    const auto drawCalls = values_[DrawCallsRow][side];
    const auto triangles = values_[TrianglesRow][side];
    if (drawCalls == frame.drawCalls && triangles == frame.triangles) return;
    values_[DrawCallsRow][side] = frame.drawCalls;
    values_[TrianglesRow][side] = frame.triangles;
    refreshRow(DrawCallsRow);
    refreshRow(TrianglesRow);
}

std::optional<std::uint64_t> CompareTable::value(Row row, Side side) const {
    return values_[row][side];
}

std::optional<CompareTable::Side> CompareTable::better(Row row) const {
    const auto& l = values_[row][Left];
    const auto& r = values_[row][Right];
    if (!l || !r || *l == *r) return std::nullopt;
    return *l < *r ? Left : Right;
}

void CompareTable::refreshRow(Row row) {
    const QLocale locale;
    const std::optional<Side> best = better(row);
    for (Side side : {Left, Right}) {
        QTableWidgetItem* cell = item(row, side);
        const auto& v = values_[row][side];
        QString text = QStringLiteral("–");
        if (v)
            text = row == PackageRow ? formatMegabytes(*v)
                                     : locale.toString(static_cast<qulonglong>(*v));
        cell->setText(text);
        cell->setToolTip(v && row == PackageRow
                             ? tr("%1 bytes").arg(locale.toString(static_cast<qulonglong>(*v)))
                             : QString());
        cell->setData(Qt::UserRole,
                      v ? QVariant::fromValue(static_cast<qulonglong>(*v)) : QVariant());
        QFont font = cell->font();
        font.setBold(best == side);
        cell->setFont(font);
        cell->setBackground(best == side ? QBrush(kBetterBackground) : QBrush());
        cell->setForeground(best == side ? QBrush(kBetterText) : QBrush());
    }
}

} // namespace hlod::widgets
