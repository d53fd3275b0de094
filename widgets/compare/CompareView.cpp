// The comparison view (see CompareView.h).
#include "widgets/compare/CompareView.h"

#include <QCheckBox>
#include <QCloseEvent>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QPushButton>
#include <QShortcut>
#include <QSplitter>
#include <QVBoxLayout>

#include "widgets/CameraController.h"
#include "widgets/SceneActors.h"
#include "widgets/StudioModel.h"
#include "widgets/Viewport.h"
#include "widgets/compare/CameraLink.h"
#include "widgets/compare/ComparePane.h"
#include "widgets/compare/CompareTable.h"
#include "widgets/compare/UseConfiguration.h"
#include "widgets/doc/UndoAdapter.h"

namespace hlod::widgets {

namespace {

// The corners of every instance's world box: a tight fit for sparse layouts (SceneActors does
// the same for the editor's viewport).
std::vector<glm::dvec3> fitPoints(const Scene& scene) {
    std::vector<glm::dvec3> points;
    points.reserve(scene.instances.size() * 8);
    for (Id i = 0; i < scene.instances.size(); ++i) {
        const Aabb b = scene.instanceBounds(i);
        if (b.empty()) continue;
        for (int c = 0; c < 8; ++c)
            points.emplace_back((c & 1) ? b.max.x : b.min.x, (c & 2) ? b.max.y : b.min.y,
                                (c & 4) ? b.max.z : b.min.z);
    }
    return points;
}

} // namespace

CompareView::CompareView(QWidget* parent) : QWidget(parent) {
    left_ = new ComparePane(tr("Left"));
    right_ = new ComparePane(tr("Right"));
    table_ = new CompareTable;
    link_ = new CameraLink(left_->viewport(), right_->viewport(), this);

    linkBox_ = new QCheckBox(tr("Link cameras"));
    linkBox_->setChecked(true);
    linkBox_->setToolTip(tr("Orbiting, panning or zooming one side moves the other the same "
                            "way"));
    fit_ = new QPushButton(tr("Fit View"));
    fit_->setToolTip(tr("Show the whole scene in both views (F)"));
    rebuild_ = new QPushButton(tr("Rebuild Both"));
    rebuild_->setToolTip(tr("Build both sides again from the document's current graph"));
    close_ = new QPushButton(tr("Close"));
    close_->setToolTip(tr("Close the comparison (Esc); its builds stop"));
    message_ = new QLabel;
    auto* bar = new QHBoxLayout;
    bar->addWidget(linkBox_);
    bar->addWidget(fit_);
    bar->addWidget(rebuild_);
    bar->addSpacing(12);
    bar->addWidget(message_, 1);
    bar->addWidget(close_);

    auto* panes = new QSplitter(Qt::Horizontal);
    panes->addWidget(left_);
    panes->addWidget(right_);
    panes->setChildrenCollapsible(false);
    panes->setStretchFactor(0, 1);
    panes->setStretchFactor(1, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->addLayout(bar);
    layout->addWidget(panes, 1);
    layout->addWidget(table_);

    connect(linkBox_, &QCheckBox::toggled, link_, &CameraLink::setEnabled);
    connect(fit_, &QPushButton::clicked, this, &CompareView::fitView);
    connect(rebuild_, &QPushButton::clicked, this, &CompareView::rebuildAll);
    connect(close_, &QPushButton::clicked, this, &QWidget::close);
    auto* escape = new QShortcut(QKeySequence(Qt::Key_Escape), this);
    escape->setContext(Qt::WindowShortcut);
    connect(escape, &QShortcut::activated, this, &QWidget::close);
    for (ComparePane* pane : {left_, right_}) {
        const auto side = pane == left_ ? CompareTable::Left : CompareTable::Right;
        connect(pane, &ComparePane::stateChanged, this, [this, pane] { onStateChanged(pane); });
        connect(pane, &ComparePane::configChanged, this, &CompareView::updateTitles);
        connect(pane, &ComparePane::frameStats, this,
                [this, side](const FrameStats& stats) { table_->setFrame(side, stats); });
        connect(pane, &ComparePane::useRequested, this, [this, pane] { useSettings(pane); });
        pane->viewport()->installEventFilter(this);
    }
    setWindowTitle(tr("Compare Configurations"));
    resize(1400, 900);
    updateTitles();
}

CompareView::~CompareView() {
    // The link observes both viewports' cameras: remove it before the panes go.
    delete link_;
    link_ = nullptr;
}

void CompareView::open(std::shared_ptr<const Scene> scene, PipelineGraph* document, NodeId baseBake,
                       const std::pair<CompareSide, CompareSide>& sides) {
    upAxis_ = scene ? suggestedUpAxis(*scene) : 1;
    for (ComparePane* pane : {left_, right_}) {
        pane->setScene(scene, upAxis_);
        pane->setDocument(document, baseBake);
    }
    left_->setSide(sides.first, false);
    right_->setSide(sides.second, false);
    message_->clear();
    updateTitles();
    // From the front, right and above (the editor's default view) until copyCamera() gives
    // the editor's own view; the link takes the right side along.
    CameraController controller(left_->viewport()->camera());
    controller.setUpAxis(upAxis_);
    controller.setDefaultDirection();
    fitView();
    rebuildAll();
}

const std::shared_ptr<const Scene>& CompareView::scene() const { return left_->scene(); }

void CompareView::detach() {
    for (ComparePane* pane : {left_, right_}) {
        pane->setDocument(nullptr, kNoNode);
        pane->setScene(nullptr, upAxis_);
    }
}

void CompareView::documentChanged() {
    for (ComparePane* pane : {left_, right_})
        pane->documentChanged();
}

void CompareView::setUndo(UndoAdapter* undo) {
    undo_ = undo;
    left_->setUseVisible(undo_ != nullptr);
    right_->setUseVisible(undo_ != nullptr);
}

void CompareView::rebuildAll() {
    left_->rebuild();
    right_->rebuild();
}

void CompareView::cancelAll() {
    left_->cancel();
    right_->cancel();
}

bool CompareView::building() const { return left_->building() || right_->building(); }

bool CompareView::allBuilt() const {
    return left_->state() == ComparePane::State::Built &&
           right_->state() == ComparePane::State::Built;
}

void CompareView::copyCamera(const vtkCamera* camera) {
    link_->copyFrom(camera);
    if (!link_->enabled()) {
        // Unlinked, the right side would keep its own pose: give it the editor's view too.
        link_->setEnabled(true);
        link_->setEnabled(linkBox_->isChecked());
    }
}

void CompareView::fitView() {
    if (!scene()) return;
    const std::vector<glm::dvec3> points = fitPoints(*scene());
    for (ComparePane* pane : {left_, right_}) {
        Viewport* view = pane->viewport();
        CameraController controller(view->camera());
        controller.setUpAxis(upAxis_);
        const double aspect = view->height() > 0 ? double(view->width()) / view->height() : 1.0;
        controller.fit(points, aspect);
        view->update();
    }
}

void CompareView::closeEvent(QCloseEvent* event) {
    cancelAll(); // nobody is looking: give the cores back to the editor
    QWidget::closeEvent(event);
}

bool CompareView::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::KeyPress && static_cast<QKeyEvent*>(event)->key() == Qt::Key_F &&
        (watched == left_->viewport() || watched == right_->viewport())) {
        fitView();
        return true;
    }
    return QWidget::eventFilter(watched, event);
}

void CompareView::onStateChanged(ComparePane* pane) {
    const auto side = pane == left_ ? CompareTable::Left : CompareTable::Right;
    table_->setBuilt(side, pane->built());
    if (pane->state() == ComparePane::State::Built) pane->viewport()->update();
    if (allBuilt()) Q_EMIT buildsFinished();
}

void CompareView::useSettings(ComparePane* pane) {
    if (!undo_) return;
    std::unique_ptr<SetParameters> command =
        useConfigurationCommand(undo_->document(), pane->baseBake(), pane->config());
    const QString label = configLabel(pane->config(), true);
    if (!command) {
        message_->setText(tr("The document already uses %1.").arg(label));
        return;
    }
    if (!undo_->execute(std::move(command))) return; // UndoAdapter reports why
    message_->setText(tr("The document now uses %1 (Edit ▸ Undo takes it back).").arg(label));
    Q_EMIT settingsUsed(label);
}

void CompareView::updateTitles() {
    // The screen size is named only when the sides differ in it.
    const bool withS = left_->config().screenSize != right_->config().screenSize;
    table_->setSideTitle(CompareTable::Left, tr("Left: %1").arg(left_->label(withS)));
    table_->setSideTitle(CompareTable::Right, tr("Right: %1").arg(right_->label(withS)));
}

} // namespace hlod::widgets
