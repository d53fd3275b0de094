// The display toolbar: Original / Clusters / HLOD preview mode buttons (keys 1, 2, 3), the
// cluster level slider, the bounds drawn in Clusters mode (none, spheres, boxes; whole level or
// the selected cluster's subtree) and the HLOD preview's depth tint.
// It edits the StudioModel's ViewOptions and follows them; modes other than Original and the
// cluster controls are enabled only once a build exists.
#pragma once

#include <QToolBar>

class QAction;
class QActionGroup;
class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;

namespace hlod::widgets {

class StudioModel;

class DisplayToolBar : public QToolBar {
    Q_OBJECT
public:
    explicit DisplayToolBar(StudioModel* model, QWidget* parent = nullptr);

    QAction* originalAction() const { return original_; }
    QAction* clustersAction() const { return clusters_; }
    QAction* hlodAction() const { return hlod_; }
    QSlider* levelSlider() const { return level_; }
    QComboBox* boundsBox() const { return bounds_; }
    QCheckBox* selectionOnlyBox() const { return selectionOnly_; }
    QCheckBox* tintBox() const { return tint_; }

private:
    void load();

    StudioModel* model_;
    QActionGroup* modes_ = nullptr;
    QAction* original_ = nullptr;
    QAction* clusters_ = nullptr;
    QAction* hlod_ = nullptr;
    QSlider* level_ = nullptr;
    QLabel* levelLabel_ = nullptr;
    QComboBox* bounds_ = nullptr;
    QCheckBox* selectionOnly_ = nullptr;
    QCheckBox* tint_ = nullptr;
    bool loading_ = false;
    QString clustersTip_, hlodTip_; // what the Clusters and HLOD preview modes show
};

} // namespace hlod::widgets
