// The statistics dock: the branch it is about (the shown Bake node's, "Branch: Cluster #5 →
// Bake #6 (up to date)"), the thesis table (triangles, vertices, meshes, size; thesis tables
// 6.2-6.6) for the original scene and the current HLOD, as BakeStats computes them, what the
// HLOD row counts (the original meshes plus every proxy: what the package stores, not what is
// drawn at once) next to the proxies' share of the original, the per-level table (level,
// nodes, mean children, error budget, proxy triangles, share; BakeStats levelTable, as
// `hlod build` prints it), how many clusters the proxy economy dissolved, and the live plot of
// draw calls and triangles per frame.
// The panel shows the StudioModel's build and DisplayController's frames; it stores nothing.
#pragma once

#include <QWidget>

class QLabel;
class QTableWidget;

namespace hlod::widgets {

struct FrameStats;
class StatsPlot;
class StudioModel;

class StatsPanel : public QWidget {
    Q_OBJECT
public:
    enum Column { TrianglesColumn = 0, VerticesColumn, MeshesColumn, SizeColumn, ColumnCount };
    enum Row { OriginalRow = 0, HlodRow, RowCount };
    enum LevelColumn {
        LevelLevelColumn = 0,
        LevelNodesColumn,
        LevelChildrenColumn,
        LevelBudgetColumn,
        LevelTrianglesColumn,
        LevelShareColumn,
        LevelColumnCount
    };

    explicit StatsPanel(StudioModel* model, QWidget* parent = nullptr);

    QTableWidget* table() const { return table_; }
    QTableWidget* levelTable() const { return levels_; }
    // What the HLOD row counts and the proxies' share ("HLOD = the original meshes + ...").
    QLabel* countsNote() const { return note_; }
    // The proxy economy's dissolved clusters.
    QLabel* economyLabel() const { return economy_; }
    QLabel* summaryLabel() const { return summary_; }
    // "Branch: Cluster #5 → Bake #6 (up to date)".
    QLabel* branchLabel() const { return branch_; }
    // At the top, shown only when the build surprises (BuildWarnings.h dissolveWarning).
    QLabel* warningLabel() const { return warning_; }
    StatsPlot* plot() const { return plot_; }

    void showFrame(const hlod::widgets::FrameStats& stats);

private:
    void refresh();
    void refreshLevels();
    void refreshBranch();

    StudioModel* model_;
    QTableWidget* table_ = nullptr;
    QLabel* note_ = nullptr;
    QTableWidget* levels_ = nullptr;
    QLabel* economy_ = nullptr;
    QLabel* summary_ = nullptr;
    QLabel* branch_ = nullptr;
    QLabel* warning_ = nullptr;
    StatsPlot* plot_ = nullptr;
};

} // namespace hlod::widgets
