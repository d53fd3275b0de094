// Parameter editors generated from the declarations (contract in ParameterPanel.h).
#include "widgets/params/ParameterPanel.h"

#include <algorithm>
#include <cmath>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>

#include "pipeline/doc/Commands.h"

namespace hlod::widgets {

namespace {

QString qs(const std::string& s) { return QString::fromStdString(s); }

// Rounds to three significant digits: a logarithmic slider gives 302 px, not 301.995 px.
double roundSignificant(double v) {
    if (v <= 0.0) return v;
    const double scale = std::pow(10.0, std::floor(std::log10(v)) - 2.0);
    return std::round(v / scale) * scale;
}

} // namespace

bool ParameterPanel::logarithmicSlider(const ParamDecl& d) {
    return d.min > 0.0 && d.max / d.min >= kLogRatio;
}

int ParameterPanel::sliderPosition(const ParamDecl& d, double value) {
    if (d.max <= d.min) return 0;
    const double t = logarithmicSlider(d)
                         ? std::log(std::max(value, d.min) / d.min) / std::log(d.max / d.min)
                         : (value - d.min) / (d.max - d.min);
    return static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * kSliderSteps));
}

double ParameterPanel::sliderValue(const ParamDecl& d, int position) {
    const double t = position / static_cast<double>(kSliderSteps);
    if (!logarithmicSlider(d)) return d.min + (d.max - d.min) * t;
    return std::clamp(roundSignificant(d.min * std::pow(d.max / d.min, t)), d.min, d.max);
}

namespace {

int decimalsFor(const ParamDecl& d) {
    // Enough digits for the smallest meaningful value of the range (0.01 px, 1e-6 x diagonal).
    const double lo = std::max(std::abs(d.min), 1e-9);
    return d.min > 0.0 && lo < 1.0 ? std::min(9, static_cast<int>(-std::floor(std::log10(lo))) + 1)
                                   : 3;
}

} // namespace

ParameterPanel::ParameterPanel(UndoAdapter& undo, QWidget* parent) : QWidget(parent), undo_(undo) {
    form_ = new QFormLayout(this);
    connect(&undo_, &UndoAdapter::documentChanged, this, &ParameterPanel::refresh);
}

void ParameterPanel::setNode(NodeId node) {
    node_ = node;
    rebuild();
}

void ParameterPanel::rebuild() {
    while (form_->rowCount() > 0)
        form_->removeRow(0);
    editors_.clear();
    sliders_.clear();
    const PipelineGraph& g = undo_.document().graph();
    if (node_ == kNoNode || !g.hasNode(node_)) return;
    for (const ParamDecl* d : parametersOf(g.node(node_).kind)) {
        QWidget* editor = makeEditor(*d);
        auto* label = new QLabel(qs(d->label), this);
        label->setToolTip(qs(d->tooltip));
        form_->addRow(label, editor);
    }
    refresh();
}

QWidget* ParameterPanel::makeNumberEditor(const ParamDecl& d) {
    QWidget* spin = nullptr;
    if (d.type == ParamType::Int) {
        auto* s = new QSpinBox(this);
        s->setRange(static_cast<int>(d.min), static_cast<int>(d.max));
        s->setKeyboardTracking(false);
        connect(s, &QSpinBox::valueChanged, this, [this, &d](int v) { commit(d, v); });
        spin = s;
    } else {
        auto* s = new QDoubleSpinBox(this);
        s->setDecimals(decimalsFor(d));
        s->setRange(d.min, d.max);
        s->setKeyboardTracking(false);
        connect(s, &QDoubleSpinBox::valueChanged, this, [this, &d](double v) { commit(d, v); });
        spin = s;
    }
    if (!d.unit.empty()) {
        const QString suffix = QStringLiteral(" ") + qs(d.unit);
        if (auto* i = qobject_cast<QSpinBox*>(spin)) i->setSuffix(suffix);
        if (auto* f = qobject_cast<QDoubleSpinBox*>(spin)) f->setSuffix(suffix);
    }
    spin->setObjectName(qs("param_" + d.key));
    spin->setToolTip(qs(d.tooltip));
    editors_[d.key] = spin;
    if (!d.slider) return spin;

    auto* box = new QWidget(this);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(0, 0, 0, 0);
    auto* slider = new QSlider(Qt::Horizontal, box);
    slider->setObjectName(qs("param_" + d.key + "_slider"));
    slider->setRange(0, kSliderSteps);
    slider->setToolTip(qs(d.tooltip));
    connect(slider, &QSlider::sliderPressed, this,
            [this] { dragMergeId_ = undo_.document().history().newMergeId(); });
    connect(slider, &QSlider::sliderReleased, this, [this] { dragMergeId_ = 0; });
    connect(slider, &QSlider::valueChanged, this,
            [this, &d](int pos) { commit(d, sliderValue(d, pos), dragMergeId_); });
    row->addWidget(slider, 1);
    row->addWidget(spin);
    sliders_[d.key] = slider;
    return box;
}

QWidget* ParameterPanel::makeEditor(const ParamDecl& d) {
    switch (d.type) {
    case ParamType::Enum: {
        auto* c = new QComboBox(this);
        for (const std::string& choice : d.choices)
            c->addItem(qs(choice));
        c->setObjectName(qs("param_" + d.key));
        c->setToolTip(qs(d.tooltip));
        connect(c, &QComboBox::currentTextChanged, this,
                [this, &d](const QString& t) { commit(d, t.toStdString()); });
        editors_[d.key] = c;
        return c;
    }
    case ParamType::Bool: {
        auto* c = new QCheckBox(this);
        c->setObjectName(qs("param_" + d.key));
        c->setToolTip(qs(d.tooltip));
        connect(c, &QCheckBox::toggled, this, [this, &d](bool on) { commit(d, on); });
        editors_[d.key] = c;
        return c;
    }
    case ParamType::Path:
    case ParamType::Text: {
        auto* e = new QLineEdit(this);
        e->setObjectName(qs("param_" + d.key));
        e->setToolTip(qs(d.tooltip));
        connect(e, &QLineEdit::editingFinished, this,
                [this, &d, e] { commit(d, e->text().toStdString()); });
        editors_[d.key] = e;
        return e;
    }
    case ParamType::Int:
    case ParamType::Double:
        return makeNumberEditor(d);
    }
    return new QWidget(this);
}

void ParameterPanel::commit(const ParamDecl& d, const ParamValue& value, std::uint64_t mergeId) {
    if (refreshing_ || node_ == kNoNode) return;
    const PipelineGraph& g = undo_.document().graph();
    if (!g.hasNode(node_)) return;
    try {
        if (normalizedValue(d, value) == g.node(node_).params.at(d.key)) return;
    } catch (const std::exception&) {
        // Out of range: let the command report it through commandFailed.
    }
    undo_.execute(std::make_unique<SetParameter>(node_, d.key, value, mergeId));
}

void ParameterPanel::refresh() {
    const PipelineGraph& g = undo_.document().graph();
    if (node_ == kNoNode || !g.hasNode(node_)) return;
    refreshing_ = true;
    const ParamValues& values = g.node(node_).params;
    for (const auto& [key, editor] : editors_) {
        const ParamDecl& d = parameterDeclaration(key);
        const ParamValue& v = values.at(key);
        const QSignalBlocker block(editor);
        if (auto* c = qobject_cast<QComboBox*>(editor)) {
            c->setCurrentText(qs(std::get<std::string>(v)));
        } else if (auto* b = qobject_cast<QCheckBox*>(editor)) {
            b->setChecked(std::get<bool>(v));
        } else if (auto* e = qobject_cast<QLineEdit*>(editor)) {
            e->setText(qs(std::get<std::string>(v)));
        } else if (auto* i = qobject_cast<QSpinBox*>(editor)) {
            i->setValue(std::get<int>(v));
        } else if (auto* f = qobject_cast<QDoubleSpinBox*>(editor)) {
            f->setValue(paramNumber(values, key));
        }
        if (auto it = sliders_.find(key); it != sliders_.end() && !it->second->isSliderDown()) {
            const QSignalBlocker blockSlider(it->second);
            it->second->setValue(sliderPosition(d, paramNumber(values, key)));
        }
    }
    refreshing_ = false;
}

} // namespace hlod::widgets
