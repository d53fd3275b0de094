// One side of the comparison view (see ComparePane.h).
#include "widgets/compare/ComparePane.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

#include "pipeline/graph/Parameters.h"
#include "widgets/DisplayController.h"
#include "widgets/StudioModel.h"
#include "widgets/Viewport.h"

namespace hlod::widgets {

namespace {

QDoubleSpinBox* spinFor(const char* key, int decimals, double step, const QString& suffix) {
    const ParamDecl& decl = parameterDeclaration(key);
    auto* spin = new QDoubleSpinBox;
    spin->setRange(decl.min, decl.max);
    spin->setDecimals(decimals);
    spin->setSingleStep(step);
    spin->setSuffix(suffix);
    spin->setToolTip(QString::fromStdString(decl.tooltip));
    // Only a finished value (Enter, focus out, arrows) rebuilds, not every typed digit.
    spin->setKeyboardTracking(false);
    return spin;
}

} // namespace

ComparePane::ComparePane(const QString& title, QWidget* parent)
    : QWidget(parent), model_(std::make_unique<StudioModel>()) {
    title_ = new QLabel(QStringLiteral("<b>%1</b>").arg(title.toHtmlEscaped()));
    volume_ = new QComboBox;
    volume_->addItem(tr("Sphere"), QStringLiteral("sphere"));
    volume_->addItem(tr("AABB"), QStringLiteral("aabb"));
    volume_->addItem(tr("Octree"), QStringLiteral("octree"));
    volume_->addItem(tr("Original hierarchy"), QStringLiteral("original"));
    volume_->setToolTip(QString::fromStdString(parameterDeclaration("volume").tooltip));
    k_ = spinFor("k", 2, 0.5, {});
    screen_ = spinFor("screen_size", 1, 10.0, tr(" px"));
    use_ = new QPushButton(tr("Use These Settings"));
    use_->setToolTip(tr("Set the document's volume, k and screen size to this side's values "
                        "(one step in Edit ▸ Undo)"));
    use_->hide();

    auto* selector = new QHBoxLayout;
    selector->addWidget(title_);
    selector->addSpacing(8);
    selector->addWidget(new QLabel(tr("Volume")));
    selector->addWidget(volume_);
    selector->addWidget(new QLabel(tr("k")));
    selector->addWidget(k_);
    selector->addWidget(new QLabel(tr("Screen size")));
    selector->addWidget(screen_);
    selector->addStretch(1);
    selector->addWidget(use_);

    status_ = new QLabel;
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // A long status must not widen the pane: both views keep the same size while text changes.
    status_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    progress_ = new QProgressBar;
    progress_->setMaximumWidth(160);
    progress_->setMaximumHeight(16);
    progress_->setTextVisible(false);
    cancel_ = new QPushButton(tr("Cancel"));
    cancel_->setToolTip(tr("Stop this side's build"));
    // The row keeps its height while the progress and Cancel come and go: no view jumps.
    status_->setMinimumHeight(cancel_->sizeHint().height());
    auto* status = new QHBoxLayout;
    status->addWidget(status_, 1);
    status->addWidget(progress_);
    status->addWidget(cancel_);

    viewport_ = new Viewport;
    viewport_->setMinimumSize(240, 180);
    display_ = std::make_unique<DisplayController>(model_.get(), viewport_);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(3);
    layout->addLayout(selector);
    layout->addLayout(status);
    layout->addWidget(viewport_, 1);

    connect(volume_, &QComboBox::currentIndexChanged, this, &ComparePane::readSelector);
    connect(k_, &QDoubleSpinBox::valueChanged, this, &ComparePane::readSelector);
    connect(screen_, &QDoubleSpinBox::valueChanged, this, &ComparePane::readSelector);
    connect(cancel_, &QPushButton::clicked, this, &ComparePane::cancel);
    connect(use_, &QPushButton::clicked, this, &ComparePane::useRequested);
    connect(display_.get(), &DisplayController::frameStats, this, &ComparePane::frameStats);
    connect(model_.get(), &StudioModel::buildProgress, this,
            [this](const QString& stage, qint64 done, qint64 total, const QString&) {
                onProgress(stage, done, total);
            });
    connect(model_.get(), &StudioModel::buildFinished, this, &ComparePane::onFinished);
    connect(model_.get(), &StudioModel::buildFailed, this, [this](const QString& message) {
        setState(State::Failed, tr("Build failed: %1").arg(message));
    });
    // After cancel() the pane says so already; this covers a cancel of its model from elsewhere.
    connect(model_.get(), &StudioModel::buildCancelled, this, [this] {
        if (building()) setState(State::Cancelled, tr("Cancelled"));
    });
    writeSelector();
    setState(State::Empty, tr("No scene"));
}

ComparePane::~ComparePane() {
    // The controller goes before the model it listens to; the model joins its build.
    display_.reset();
    model_.reset();
}

const std::shared_ptr<const Scene>& ComparePane::scene() const { return model_->scene(); }

const BuiltHlod* ComparePane::built() const {
    return model_->hasBuild() ? &model_->built() : nullptr;
}

void ComparePane::setUseVisible(bool visible) { use_->setVisible(visible); }

void ComparePane::setScene(std::shared_ptr<const Scene> scene, int upAxis) {
    const bool had = model_->scene() != nullptr;
    writing_ = true; // a running build ends here: that is not a user's cancel
    model_->setScene(std::move(scene));
    writing_ = false;
    model_->setMode(DisplayMode::Hlod);
    viewport_->setSceneActors(nullptr, upAxis, false);
    setState(State::Empty, model_->scene() ? tr("Not built") : tr("No scene"));
    if (had) viewport_->update();
}

void ComparePane::setConfig(const CompareConfig& config, bool rebuildIfChanged) {
    const bool changed = !(config == config_);
    config_ = config;
    writeSelector();
    if (changed && rebuildIfChanged) rebuild();
}

void ComparePane::rebuild() {
    if (!model_->scene()) return;
    // The previous result is of another configuration (or base): drop it before building.
    writing_ = true;
    model_->setScene(model_->scene());
    writing_ = false;
    model_->setMode(DisplayMode::Hlod);
    model_->setSettings(settings());
    setState(State::Building, tr("Building %1…").arg(configLabel(config_)));
    model_->build();
}

void ComparePane::cancel() {
    if (!building()) return;
    // The worker stops at its next check of the flag, within about one node's bake, and its
    // cancelled() comes later still: the pane is cancelled from now on, so that a window closed
    // and shown again at once rebuilds it (MainWindow::showCompare) instead of waiting for a
    // build that will never finish. The model never delivers a result after the cancel
    // (HlodBuilder).
    model_->cancelBuild();
    setState(State::Cancelled, tr("Cancelled"));
}

void ComparePane::readSelector() {
    if (writing_) return;
    CompareConfig c = config_;
    c.volume = volumeTypeFromString(volume_->currentData().toString().toStdString());
    c.k = k_->value();
    c.screenSize = screen_->value();
    k_->setEnabled(c.volume == VolumeType::Aabb);
    if (c == config_) return;
    config_ = c;
    rebuild();
    Q_EMIT configChanged();
}

void ComparePane::writeSelector() {
    writing_ = true;
    volume_->setCurrentIndex(
        volume_->findData(QString::fromLatin1(hlod::toString(config_.volume))));
    k_->setValue(config_.k);
    k_->setEnabled(config_.volume == VolumeType::Aabb);
    screen_->setValue(config_.screenSize);
    writing_ = false;
}

void ComparePane::setState(State state, const QString& text) {
    if (writing_ && state == State::Cancelled) return;
    state_ = state;
    status_->setText(text);
    status_->setToolTip(text);
    const bool busy = state == State::Building;
    progress_->setVisible(busy);
    cancel_->setVisible(busy);
    if (busy) progress_->setRange(0, 0);
    Q_EMIT stateChanged();
}

void ComparePane::onProgress(const QString& stage, qint64 done, qint64 total) {
    if (!building()) return;
    const QString what = stage == QLatin1String("cluster") ? tr("Clustering")
                         : stage == QLatin1String("bake")  ? tr("Baking proxies")
                                                           : stage;
    status_->setText(total > 0
                         ? tr("%1: %2 %3/%4").arg(configLabel(config_), what).arg(done).arg(total)
                         : tr("%1: %2").arg(configLabel(config_), what));
    if (total > 0) {
        progress_->setRange(0, 1000);
        progress_->setValue(static_cast<int>(1000.0 * double(done) / double(total)));
    }
}

void ComparePane::onFinished() {
    // The selector above names the configuration: the status says what came out.
    const BuiltHlod& b = model_->built();
    const QLocale locale;
    setState(State::Built, tr("%1 nodes, height %2; built in %3 s (%4 proxies baked, %5 from "
                              "the cache)")
                               .arg(locale.toString(qulonglong(b.build->tree.nodes.size())))
                               .arg(b.build->tree.height())
                               .arg(locale.toString(b.seconds, 'f', 2))
                               .arg(b.build->bake.baked)
                               .arg(b.build->bake.reused));
    viewport_->update();
}

} // namespace hlod::widgets
