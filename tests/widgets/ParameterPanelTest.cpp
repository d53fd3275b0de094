// widgets/params/ParameterPanel: editors generated from the declarations, every edit an undo
// step, a slider drag a single step.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSlider>
#include <QSpinBox>

#include "widgets/params/ParameterPanel.h"

namespace hlod::widgets {
namespace {

TEST(ParameterPanel, EditorsFollowTheDeclarations) {
    Document doc;
    UndoAdapter undo(doc);
    ParameterPanel panel(undo);
    panel.setNode(doc.bakeNode());
    auto* proxy = panel.findChild<QComboBox*>(QStringLiteral("param_proxy"));
    ASSERT_NE(proxy, nullptr);
    EXPECT_EQ(proxy->count(), 3); // decimate, remesh, sloppy
    EXPECT_EQ(proxy->currentText(), QStringLiteral("decimate"));
    auto* size = panel.findChild<QDoubleSpinBox*>(QStringLiteral("param_screen_size"));
    ASSERT_NE(size, nullptr);
    EXPECT_EQ(size->value(), 300.0); // DESIGN.md default S
    EXPECT_EQ(size->minimum(), 1.0);
    EXPECT_EQ(size->maximum(), 100000.0);
    EXPECT_EQ(size->suffix(), QStringLiteral(" px"));
    EXPECT_FALSE(size->toolTip().isEmpty());
    EXPECT_NE(panel.findChild<QSlider*>(QStringLiteral("param_screen_size_slider")), nullptr);
    EXPECT_NE(panel.findChild<QSpinBox*>(QStringLiteral("param_threads")), nullptr);
    EXPECT_NE(panel.findChild<QCheckBox*>(QStringLiteral("param_cache")), nullptr);
    panel.setNode(doc.clusterNode());
    EXPECT_EQ(panel.findChild<QComboBox*>(QStringLiteral("param_proxy")), nullptr);
    EXPECT_NE(panel.findChild<QComboBox*>(QStringLiteral("param_volume")), nullptr);
}

TEST(ParameterPanel, EachEditIsAnUndoStepAndUndoUpdatesTheEditor) {
    Document doc;
    UndoAdapter undo(doc);
    ParameterPanel panel(undo);
    panel.setNode(doc.clusterNode());
    auto* volume = panel.findChild<QComboBox*>(QStringLiteral("param_volume"));
    auto* k = panel.findChild<QDoubleSpinBox*>(QStringLiteral("param_k"));
    volume->setCurrentText(QStringLiteral("aabb"));
    k->setValue(2.0);
    EXPECT_EQ(doc.history().count(), 2u);
    EXPECT_EQ(paramText(doc.graph().node(doc.clusterNode()).params, "volume"), "aabb");
    undo.stack()->undo();
    EXPECT_EQ(k->value(), 1.0); // the editor shows the restored value
    undo.stack()->undo();
    EXPECT_EQ(volume->currentText(), QStringLiteral("sphere"));
}

TEST(ParameterPanel, ASliderDragIsOneUndoStep) {
    Document doc;
    UndoAdapter undo(doc);
    ParameterPanel panel(undo);
    panel.setNode(doc.clusterNode());
    auto* slider = panel.findChild<QSlider*>(QStringLiteral("param_k_slider"));
    ASSERT_NE(slider, nullptr);
    slider->setSliderDown(true);    // as a mouse press does: sliderPressed
    for (int pos : {100, 200, 250}) // k in [0, 16]: 1.6, 3.2, 4.0
        slider->setValue(pos);
    slider->setSliderDown(false);
    EXPECT_EQ(doc.history().count(), 1u);
    EXPECT_EQ(undo.stack()->count(), 1);
    EXPECT_DOUBLE_EQ(paramNumber(doc.graph().node(doc.clusterNode()).params, "k"), 4.0);
    undo.stack()->undo();
    EXPECT_DOUBLE_EQ(paramNumber(doc.graph().node(doc.clusterNode()).params, "k"), 1.0);
}

} // namespace
} // namespace hlod::widgets
