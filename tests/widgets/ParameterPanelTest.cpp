// widgets/params/ParameterPanel: editors generated from the declarations, every edit an undo
// step, a slider drag a single step.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSlider>
#include <QSpinBox>

#include "pipeline/graph/Parameters.h"
#include "widgets/params/ParameterPanel.h"

namespace hlod::widgets {
namespace {

TEST(ParameterPanel, EditorsFollowTheDeclarations) {
    Document doc;
    UndoAdapter undo(doc);
    ParameterPanel panel(undo);
    panel.setNode(kDefaultBake);
    auto* proxy = panel.findChild<QComboBox*>(QStringLiteral("param_proxy"));
    ASSERT_NE(proxy, nullptr);
    EXPECT_EQ(proxy->count(), 3); // decimate, remesh, sloppy
    EXPECT_EQ(proxy->currentText(), QStringLiteral("decimate"));
    auto* size = panel.findChild<QDoubleSpinBox*>(QStringLiteral("param_screen_size"));
    ASSERT_NE(size, nullptr);
    EXPECT_EQ(size->value(), 300.0); // the thesis' S, the declared default
    EXPECT_EQ(size->minimum(), 1.0);
    EXPECT_EQ(size->maximum(), 100000.0);
    EXPECT_EQ(size->suffix(), QStringLiteral(" px"));
    EXPECT_FALSE(size->toolTip().isEmpty());
    EXPECT_NE(panel.findChild<QSlider*>(QStringLiteral("param_screen_size_slider")), nullptr);
    EXPECT_NE(panel.findChild<QSpinBox*>(QStringLiteral("param_threads")), nullptr);
    EXPECT_NE(panel.findChild<QCheckBox*>(QStringLiteral("param_cache")), nullptr);
    panel.setNode(kDefaultCluster);
    EXPECT_EQ(panel.findChild<QComboBox*>(QStringLiteral("param_proxy")), nullptr);
    EXPECT_NE(panel.findChild<QComboBox*>(QStringLiteral("param_volume")), nullptr);
}

TEST(ParameterPanel, EachEditIsAnUndoStepAndUndoUpdatesTheEditor) {
    Document doc;
    UndoAdapter undo(doc);
    ParameterPanel panel(undo);
    panel.setNode(kDefaultCluster);
    auto* volume = panel.findChild<QComboBox*>(QStringLiteral("param_volume"));
    auto* k = panel.findChild<QDoubleSpinBox*>(QStringLiteral("param_k"));
    volume->setCurrentText(QStringLiteral("aabb"));
    k->setValue(2.0);
    EXPECT_EQ(doc.history().count(), 2u);
    EXPECT_EQ(paramText(doc.graph().node(kDefaultCluster).params, "volume"), "aabb");
    undo.stack()->undo();
    EXPECT_EQ(k->value(), 1.0); // the editor shows the restored value
    undo.stack()->undo();
    EXPECT_EQ(volume->currentText(), QStringLiteral("sphere"));
}

TEST(ParameterPanel, ASliderDragIsOneUndoStep) {
    Document doc;
    UndoAdapter undo(doc);
    ParameterPanel panel(undo);
    panel.setNode(kDefaultCluster);
    auto* slider = panel.findChild<QSlider*>(QStringLiteral("param_k_slider"));
    ASSERT_NE(slider, nullptr);
    slider->setSliderDown(true);    // as a mouse press does: sliderPressed
    for (int pos : {100, 200, 250}) // k in [0, 16]: 1.6, 3.2, 4.0
        slider->setValue(pos);
    slider->setSliderDown(false);
    EXPECT_EQ(doc.history().count(), 1u);
    EXPECT_EQ(undo.stack()->count(), 1);
    EXPECT_DOUBLE_EQ(paramNumber(doc.graph().node(kDefaultCluster).params, "k"), 4.0);
    undo.stack()->undo();
    EXPECT_DOUBLE_EQ(paramNumber(doc.graph().node(kDefaultCluster).params, "k"), 1.0);
}

TEST(ParameterPanel, WideRangesGetALogarithmicSlider) {
    // S spans 1 to 100000 px (five decades): each decade is a fifth of the slider, so the
    // default 300 px sits near the middle (log10(300) / 5 = 0.495) instead of at 0.3 %.
    const ParamDecl& size = parameterDeclaration("screen_size");
    ASSERT_TRUE(ParameterPanel::logarithmicSlider(size));
    EXPECT_FALSE(ParameterPanel::logarithmicSlider(parameterDeclaration("k"))); // 0..16
    EXPECT_EQ(ParameterPanel::sliderPosition(size, 300.0), 495);
    EXPECT_EQ(ParameterPanel::sliderValue(size, 0), 1.0);
    EXPECT_EQ(ParameterPanel::sliderValue(size, 1000), 100000.0);
    EXPECT_EQ(ParameterPanel::sliderValue(size, 600), 1000.0);       // 10^(0.6 * 5)
    EXPECT_DOUBLE_EQ(ParameterPanel::sliderValue(size, 495), 299.0); // 298.5: 3 digits
    EXPECT_EQ(ParameterPanel::sliderPosition(size, 1000.0), 600);

    Document doc;
    UndoAdapter undo(doc);
    ParameterPanel panel(undo);
    panel.setNode(kDefaultBake);
    auto* slider = panel.findChild<QSlider*>(QStringLiteral("param_screen_size_slider"));
    auto* spin = panel.findChild<QDoubleSpinBox*>(QStringLiteral("param_screen_size"));
    ASSERT_NE(slider, nullptr);
    EXPECT_EQ(slider->value(), 495);
    slider->setValue(600);
    EXPECT_EQ(paramNumber(doc.graph().node(kDefaultBake).params, "screen_size"), 1000.0);
    EXPECT_EQ(spin->value(), 1000.0);
    spin->setValue(50.0); // typing a value moves the slider to its decade
    EXPECT_EQ(slider->value(), ParameterPanel::sliderPosition(size, 50.0));
    EXPECT_EQ(doc.history().count(), 2u);
}

} // namespace
} // namespace hlod::widgets
