// The "Build" dock: a plain form over hlod::HlodSettings (volume type, k, maximum children,
// proxy method, screen size S, pixel error) with Build and Cancel buttons.
//
// The form edits the StudioModel's settings (every change is written back at once) and follows
// them when they change elsewhere; the full parameter node graph will replace this form, the
// settings struct stays. Ranges follow the pipeline's validation (ErrorBudget.h, Cluster.h).
#pragma once

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QPushButton;
class QSpinBox;

namespace hlod::widgets {

class StudioModel;

class BuildPanel : public QWidget {
    Q_OBJECT
public:
    explicit BuildPanel(StudioModel* model, QWidget* parent = nullptr);

    QComboBox* volume() const { return volume_; }
    QDoubleSpinBox* k() const { return k_; }
    QSpinBox* maxChildren() const { return maxChildren_; }
    QComboBox* proxy() const { return proxy_; }
    QDoubleSpinBox* screenSize() const { return screenSize_; }
    QDoubleSpinBox* pixelError() const { return pixelError_; }
    QPushButton* buildButton() const { return build_; }
    QPushButton* cancelButton() const { return cancel_; }

private:
    void load();  // model -> form
    void store(); // form -> model
    void updateButtons();

    StudioModel* model_;
    QComboBox* volume_ = nullptr;
    QDoubleSpinBox* k_ = nullptr;
    QSpinBox* maxChildren_ = nullptr;
    QComboBox* proxy_ = nullptr;
    QDoubleSpinBox* screenSize_ = nullptr;
    QDoubleSpinBox* pixelError_ = nullptr;
    QPushButton* build_ = nullptr;
    QPushButton* cancel_ = nullptr;
    bool loading_ = false;
};

} // namespace hlod::widgets
