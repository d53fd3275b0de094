// Test support for the main window (see StudioWindow.h).
#include "StudioWindow.h"

#include <QAbstractButton>
#include <QApplication>
#include <QElapsedTimer>
#include <QMessageBox>
#include <QSettings>
#include <QTest>
#include <QTimer>

#include "pipeline/doc/Commands.h"
#include "pipeline/doc/ProjectFile.h"
#include "widgets/StudioModel.h"
#include "widgets/doc/ProjectSession.h"

namespace hlod::studio::test {

std::unique_ptr<MainWindow> openWindow() {
    QSettings().clear();
    auto window = std::make_unique<MainWindow>();
    window->resize(1280, 800);
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get())) return nullptr;
    // Keyboard shortcuts go to the active window.
    window->activateWindow();
    if (!QTest::qWaitForWindowActive(window.get())) return nullptr;
    return window;
}

bool waitUntil(const std::function<bool()>& done, int ms) {
    QElapsedTimer timer;
    timer.start();
    while (!done() && timer.elapsed() < ms)
        QTest::qWait(20);
    return done();
}

struct DialogAnswerer::Impl {
    QTimer timer;
};

DialogAnswerer::DialogAnswerer(std::function<bool(QDialog*)> answer)
    : impl_(std::make_unique<Impl>()), messages_(std::make_shared<QStringList>()) {
    impl_->timer.setInterval(30);
    QObject::connect(&impl_->timer, &QTimer::timeout, [answer, messages = messages_] {
        auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
        if (!dialog || !dialog->isVisible()) return;
        if (auto* box = qobject_cast<QMessageBox*>(dialog)) *messages << box->text();
        answer(dialog);
    });
    impl_->timer.start();
}

DialogAnswerer::~DialogAnswerer() = default;

std::function<bool(QDialog*)> clickButton(int standardButton) {
    return [standardButton](QDialog* dialog) {
        auto* box = qobject_cast<QMessageBox*>(dialog);
        if (!box) return false;
        if (QAbstractButton* b =
                box->button(static_cast<QMessageBox::StandardButton>(standardButton)))
            b->click();
        else
            box->reject();
        return true;
    };
}

bool openSampleWithoutCache(MainWindow& window) {
    window.openFiles({});
    if (!waitUntil([&] { return window.model()->scene() != nullptr; })) return false;
    auto* undo = window.session()->undo();
    return undo->execute(std::make_unique<SetParameter>(kDefaultBake, "cache", false)) &&
           undo->execute(std::make_unique<SetParameter>(kDefaultBake, "threads", 2));
}

bool settled(const MainWindow& window) {
    const widgets::StudioModel* model = window.model();
    const PipelineGraph& g = window.session()->document().graph();
    const NodeId shown = model->shownBake();
    return !model->building() && model->hasBuild() && shown != kNoNode && g.hasNode(shown) &&
           g.status(shown) == NodeStatus::UpToDate && model->built().build == g.sharedOutput(shown);
}

bool waitSettled(const MainWindow& window) {
    return waitUntil([&window] { return settled(window); });
}

void writeSampleProject(const QString& path) {
    Document doc; // no sources: the embedded sample scene
    const NodeId cluster = kDefaultCluster;
    const NodeId bake = kDefaultBake;
    doc.execute(std::make_unique<SetParameter>(cluster, "volume", std::string("aabb")));
    doc.execute(std::make_unique<SetParameter>(cluster, "k", 2.0));
    doc.execute(std::make_unique<SetParameter>(bake, "cache", false));
    doc.execute(std::make_unique<SetParameter>(bake, "threads", 2));
    doc.execute(std::make_unique<ExcludeInstance>(cluster, InstanceSet{3}));
    saveProject(doc, path.toStdString());
}

} // namespace hlod::studio::test
