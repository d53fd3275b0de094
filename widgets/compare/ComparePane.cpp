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

// Ids of the temporary branch in a Custom side's copy of the graph: fixed (and far above any id
// a document hands out), so its definition does not change when the document gains a node.
constexpr NodeId kTempCluster = 0xfffffff0u;
constexpr NodeId kTempBake = 0xfffffff1u;

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
    source_ = new QComboBox;
    // One width whatever it lists, so both panes lay out alike (equal views, one frustum).
    source_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    source_->setMinimumContentsLength(14);
    source_->setToolTip(tr("A Bake node of the document, or Custom: the values on the right over "
                           "the shown branch (built as a temporary branch, the document is not "
                           "changed)"));
    volume_ = new QComboBox;
    volume_->addItem(tr("Sphere"), QStringLiteral("sphere"));
    volume_->addItem(tr("AABB"), QStringLiteral("aabb"));
    volume_->addItem(tr("Octree"), QStringLiteral("octree"));
    volume_->addItem(tr("Original hierarchy"), QStringLiteral("original"));
    volume_->setToolTip(QString::fromStdString(parameterDeclaration("volume").tooltip));
    k_ = spinFor("k", 2, 0.5, {});
    screen_ = spinFor("screen_size", 1, 10.0, tr(" px"));
    use_ = new QPushButton(tr("Use These Settings"));
    use_->setToolTip(tr("Set the volume, k and screen size of the branch this side is laid over "
                        "to this side's values (one step in Edit ▸ Undo)"));
    use_->hide();

    auto* selector = new QHBoxLayout;
    // Two rows: what the side shows, then its values; one row would be wider than half a
    // window and make the two views unequal.
    auto* source = new QHBoxLayout;
    source->addWidget(title_);
    source->addSpacing(8);
    source->addWidget(source_);
    source->addStretch(1);
    source->addWidget(use_);
    selector->addWidget(new QLabel(tr("Volume")));
    selector->addWidget(volume_);
    selector->addWidget(new QLabel(tr("k")));
    selector->addWidget(k_);
    selector->addWidget(new QLabel(tr("Screen size")));
    selector->addWidget(screen_);
    selector->addStretch(1);

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
    layout->addLayout(source);
    layout->addLayout(selector);
    layout->addLayout(status);
    layout->addWidget(viewport_, 1);

    connect(source_, &QComboBox::currentIndexChanged, this, &ComparePane::readSource);
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

void ComparePane::setUseVisible(bool visible) {
    useWanted_ = visible;
    updateUse();
}

void ComparePane::updateUse() { use_->setVisible(useWanted_ && side_.bake == kNoNode); }

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

void ComparePane::setDocument(PipelineGraph* document, NodeId baseBake) {
    if (document != document_) {
        writing_ = true;
        model_->setGraph(nullptr); // the old graph may be gone
        writing_ = false;
    }
    document_ = document;
    base_ = baseBake;
    fillSources();
}

void ComparePane::fillSources() {
    writing_ = true;
    source_->clear();
    if (document_) {
        const std::vector<NodeId> imports = document_->nodesOf(NodeKind::Import);
        for (NodeId bake : document_->nodesOf(NodeKind::Bake)) {
            if (imports.empty() || document_->upstreamOfKind(bake, NodeKind::Import) != imports[0])
                continue;
            source_->addItem(QString::fromStdString(describeNode(document_->node(bake))),
                             QVariant::fromValue<quint32>(bake));
        }
    }
    source_->addItem(tr("Custom"), QVariant::fromValue<quint32>(kNoNode));
    source_->setCurrentIndex(
        std::max(0, source_->findData(QVariant::fromValue<quint32>(side_.bake))));
    writing_ = false;
}

void ComparePane::setSide(const CompareSide& side, bool rebuildIfChanged) {
    const bool changed = !(side == side_);
    side_ = side;
    if (side_.bake != kNoNode && document_ && document_->hasNode(side_.bake))
        side_.config = configOf(*document_, side_.bake);
    fillSources();
    writeSelector();
    updateUse();
    if (changed && rebuildIfChanged) rebuild();
}

CompareConfig ComparePane::config() const {
    if (side_.bake != kNoNode && document_ && document_->hasNode(side_.bake))
        return configOf(*document_, side_.bake);
    return side_.config;
}

QString ComparePane::label(bool withScreenSize) const {
    const QString config = configLabel(this->config(), withScreenSize);
    if (side_.bake != kNoNode && document_ && document_->hasNode(side_.bake))
        return tr("%1: %2").arg(QString::fromStdString(describeNode(document_->node(side_.bake))),
                                config);
    if (document_ && document_->hasNode(base_))
        return tr("%1 (over %2)")
            .arg(config, QString::fromStdString(nodeLabel(document_->node(base_))));
    return config;
}

std::pair<PipelineGraph*, NodeId> ComparePane::target() {
    if (!document_) return {nullptr, kNoNode};
    if (side_.bake != kNoNode && document_->hasNode(side_.bake)) return {document_, side_.bake};
    // The temporary branch: the base branch's Cluster and Bake nodes copied, fed by its Import.
    temp_ = *document_;
    temp_.setStatusListener({});
    temp_.setProgressListener({});
    NodeId base = document_->hasNode(base_) ? base_ : kNoNode;
    if (base == kNoNode && !document_->nodesOf(NodeKind::Bake).empty())
        base = document_->nodesOf(NodeKind::Bake).front();
    const NodeId import = base != kNoNode ? document_->upstreamOfKind(base, NodeKind::Import)
                          : document_->nodesOf(NodeKind::Import).empty()
                              ? kNoNode
                              : document_->nodesOf(NodeKind::Import).front();
    if (import == kNoNode) return {nullptr, kNoNode};
    GraphNode cluster{kTempCluster, NodeKind::Cluster, defaultValues(NodeKind::Cluster)};
    GraphNode bake{kTempBake, NodeKind::Bake, defaultValues(NodeKind::Bake)};
    if (base != kNoNode) {
        bake.params = document_->node(base).params;
        if (const NodeId c = document_->upstreamOfKind(base, NodeKind::Cluster); c != kNoNode) {
            cluster.params = document_->node(c).params;
            cluster.edits = document_->node(c).edits;
        }
    }
    temp_.insertNode(cluster);
    temp_.insertNode(bake);
    temp_.connect({import, 0, kTempCluster, 0});
    temp_.connect({kTempCluster, 0, kTempBake, 0});
    applyConfig(temp_, kTempCluster, kTempBake, side_.config);
    return {&temp_, kTempBake};
}

void ComparePane::rebuild() {
    if (!model_->scene()) return;
    // The previous result is of another configuration: drop it before building. The model's
    // signals while it is set up are not this side's outcome.
    writing_ = true;
    model_->setScene(model_->scene());
    const auto [graph, node] = target();
    model_->setGraph(graph);
    model_->setShownBake(node);
    model_->setScene(model_->scene()); // shows nothing until the run below delivers
    writing_ = false;
    model_->setMode(DisplayMode::Hlod);
    if (!graph || node == kNoNode) {
        setState(State::Failed, tr("The document has no Import node to build from"));
        return;
    }
    builtDefinition_ = graph->definition(node);
    setState(State::Building, tr("Building %1…").arg(label()));
    model_->build();
}

void ComparePane::documentChanged() {
    fillSources();
    if (side_.bake != kNoNode && document_ && !document_->hasNode(side_.bake)) {
        // Its node was removed: the same values as a Custom side.
        setSide({kNoNode, side_.config});
        return;
    }
    if (side_.bake != kNoNode) side_.config = configOf(*document_, side_.bake);
    writeSelector();
    Q_EMIT configChanged(); // the labels of a Bake-node side follow its parameters
    if (!model_->scene()) return;
    std::string now;
    if (side_.bake != kNoNode && document_) {
        now = document_->definition(side_.bake);
    } else {
        const auto [graph, node] = target();
        // target() remakes the copy the model runs: the same nodes, the document's new state.
        if (graph && node != kNoNode) now = graph->definition(node);
    }
    if (now != builtDefinition_) rebuild();
}

void ComparePane::cancel() {
    if (!building()) return;
    // The worker stops at its next check of the flag, within about one node's bake, and its
    // cancelled() comes later still: the pane is cancelled from now on, so that a window closed
    // and shown again at once rebuilds it (MainWindow::showCompare) instead of waiting for a
    // build that will never finish. The model never delivers a result after the cancel
    // (GraphRunner).
    model_->cancelBuild();
    setState(State::Cancelled, tr("Cancelled"));
}

void ComparePane::readSource() {
    if (writing_) return;
    const NodeId bake = source_->currentData().value<quint32>();
    CompareSide side = side_;
    if (bake != kNoNode) {
        side.bake = bake;
    } else {
        // Custom, over the node this side showed (or the base), with its values.
        if (side_.bake != kNoNode) base_ = side_.bake;
        side = {kNoNode, config()};
    }
    setSide(side);
    Q_EMIT configChanged();
}

void ComparePane::readSelector() {
    if (writing_) return;
    CompareConfig c = config();
    c.volume = volumeTypeFromString(volume_->currentData().toString().toStdString());
    c.k = k_->value();
    c.screenSize = screen_->value();
    k_->setEnabled(c.volume == VolumeType::Aabb);
    if (c == config()) return;
    // Values of their own: a Custom side over the node shown so far.
    if (side_.bake != kNoNode) base_ = side_.bake;
    setSide({kNoNode, c});
    Q_EMIT configChanged();
}

void ComparePane::writeSelector() {
    writing_ = true;
    const CompareConfig c = config();
    volume_->setCurrentIndex(volume_->findData(QString::fromLatin1(hlod::toString(c.volume))));
    k_->setValue(c.k);
    k_->setEnabled(c.volume == VolumeType::Aabb);
    screen_->setValue(c.screenSize);
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
    status_->setText(total > 0 ? tr("%1: %2 %3/%4").arg(label(), what).arg(done).arg(total)
                               : tr("%1: %2").arg(label(), what));
    if (total > 0) {
        progress_->setRange(0, 1000);
        progress_->setValue(static_cast<int>(1000.0 * double(done) / double(total)));
    }
}

void ComparePane::onFinished() {
    if (writing_ || !model_->hasBuild()) return;
    // The selector above names the configuration: the status says what came out.
    const BuiltHlod& b = model_->built();
    const QLocale locale;
    setState(State::Built, tr("%1 nodes, height %2; built in %3 s (%4 proxies baked, %5 from "
                              "the cache)")
                               .arg(locale.toString(qulonglong(b.build->tree->nodes.size())))
                               .arg(b.build->tree->height())
                               .arg(locale.toString(b.seconds, 'f', 2))
                               .arg(b.build->bake->baked)
                               .arg(b.build->bake->reused));
    viewport_->update();
}

} // namespace hlod::widgets
