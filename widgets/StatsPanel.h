// The statistics dock: the thesis table (triangles, vertices, meshes, size; thesis tables
// 6.2-6.6) for the original scene and the current HLOD, as BakeStats computes them, plus the
// live plot of draw calls and triangles per frame.
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

    explicit StatsPanel(StudioModel* model, QWidget* parent = nullptr);

    QTableWidget* table() const { return table_; }
    StatsPlot* plot() const { return plot_; }

    void showFrame(const hlod::widgets::FrameStats& stats);

private:
    void refresh();

    StudioModel* model_;
    QTableWidget* table_ = nullptr;
    QLabel* summary_ = nullptr;
    StatsPlot* plot_ = nullptr;
};

} // namespace hlod::widgets
