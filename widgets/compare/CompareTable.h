// The statistics table of the comparison view: one column per side, one row per measure, and
// the better value of each row highlighted (bold on green; lower is better in every row:
// fewer draw calls and triangles draw faster, fewer nodes and proxy triangles and a smaller
// package load faster and take less memory). Equal values highlight neither side.
//
// Rows: the frame's draw calls and triangles (the pane's DisplayController, for the linked
// camera), the cluster tree's node count, the proxy triangles (BakeResult::proxyTriangles),
// and the package's bytes on disk: BuiltHlod::package, the package `hlod build` writes
// (measured in memory, the same figure the CLI prints).
// A cell without a value (no build yet, no frame yet) shows "–". The table holds the numbers
// it shows and nothing else; value() returns them for tests and tools.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include <QTableWidget>

namespace hlod::widgets {

struct BuiltHlod;
struct FrameStats;

class CompareTable : public QTableWidget {
    Q_OBJECT
public:
    enum Row { DrawCallsRow = 0, TrianglesRow, NodesRow, ProxyTrianglesRow, PackageRow, RowCount };
    enum Side { Left = 0, Right = 1 };

    explicit CompareTable(QWidget* parent = nullptr);

    void setSideTitle(Side side, const QString& title);
    // The build's rows of `side`; null clears them (and the frame rows: nothing is drawn).
    void setBuilt(Side side, const BuiltHlod* built);
    void setFrame(Side side, const FrameStats& frame);

    std::optional<std::uint64_t> value(Row row, Side side) const;
    // The side whose value is highlighted in `row`; empty when equal or a value is missing.
    std::optional<Side> better(Row row) const;

private:
    void refreshRow(Row row);

    std::array<std::array<std::optional<std::uint64_t>, 2>, RowCount> values_;
};

} // namespace hlod::widgets
