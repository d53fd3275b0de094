// The parameter panel of the selected pipeline node, generated from the parameter declarations
// (pipeline/graph/Parameters.h; docs/architecture.md, "The path of a parameter": the GUI panel,
// the CLI flags and the project file are all driven by that declaration): one editor per parameter
// of the node's kind, in declaration order, labelled with ParamDecl::label, the unit as suffix and
// the tooltip.
//   Enum -> QComboBox, Double -> QDoubleSpinBox (+ QSlider when ParamDecl::slider),
//   Int -> QSpinBox, Bool -> QCheckBox, Path/Text -> QLineEdit (committed on Return/focus out).
// The panel holds no pipeline state: it shows the values of the document's graph and turns
// every user edit into a SetParameter command through the UndoAdapter, so each edit is
// undoable. A slider drag takes one merge id when pressed (UndoStack::newMergeId) and uses it
// until released: the whole drag is one undo step. Spin boxes commit on Return, focus out and
// arrow steps (no keyboard tracking). Call refresh() when the document changed from elsewhere
// (the UndoAdapter's documentChanged does it when connected with connectTo()).
//
// Sliders: see kSliderSteps.
// Object names for tests and style sheets: each editor is named "param_<key>" (the slider
// "param_<key>_slider").
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include <QWidget>

#include "pipeline/graph/PipelineGraph.h"
#include "widgets/doc/UndoAdapter.h"

class QFormLayout;
class QSlider;

namespace hlod::widgets {

class ParameterPanel : public QWidget {
    Q_OBJECT
public:
    explicit ParameterPanel(UndoAdapter& undo, QWidget* parent = nullptr);

    // Shows the parameters of `node` (kNoNode: empty panel).
    void setNode(NodeId node);
    NodeId node() const { return node_; }
    // Re-reads every value from the document (editors keep their focus; no commands).
    void refresh();

    // A slider has kSliderSteps steps over [min, max]: linear, or logarithmic when the range
    // spans kLogRatio or more (min > 0; the screen size S, 1 to 100000 px, and the pixel error):
    // then every decade gets the same length and values are rounded to three significant digits
    // (S = 300 px sits at 50 % of the slider, not at 0.3 %).
    static constexpr int kSliderSteps = 1000;
    static constexpr double kLogRatio = 1000.0;
    static bool logarithmicSlider(const ParamDecl& decl);
    static int sliderPosition(const ParamDecl& decl, double value);
    static double sliderValue(const ParamDecl& decl, int position);

private:
    void rebuild();
    QWidget* makeEditor(const ParamDecl& decl);
    QWidget* makeNumberEditor(const ParamDecl& decl);
    void commit(const ParamDecl& decl, const ParamValue& value, std::uint64_t mergeId = 0);

    UndoAdapter& undo_;
    NodeId node_ = kNoNode;
    QFormLayout* form_ = nullptr;
    std::map<std::string, QWidget*> editors_; // key -> editor (for refresh)
    std::map<std::string, QSlider*> sliders_;
    std::uint64_t dragMergeId_ = 0; // non-zero while a slider is pressed
    bool refreshing_ = false;
};

} // namespace hlod::widgets
