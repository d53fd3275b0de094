// The editor's open project (see ProjectSession.h).
#include "widgets/doc/ProjectSession.h"

#include <QFileInfo>
#include <QTimer>

#include "pipeline/doc/ProjectFile.h"

namespace hlod::widgets {

ProjectSession::ProjectSession(QObject* parent)
    : QObject(parent), doc_(std::make_unique<Document>()),
      undo_(std::make_unique<UndoAdapter>(*doc_)), timer_(new QTimer(this)) {
    connect(undo_.get(), &UndoAdapter::documentChanged, this, [this] {
        updateDirty();
        Q_EMIT documentChanged();
    });
    connect(undo_->stack(), &QUndoStack::cleanChanged, this, [this] { updateDirty(); });
    timer_->setInterval(kAutosaveMs);
    connect(timer_, &QTimer::timeout, this, [this] { autosave(); });
    timer_->start();
}

ProjectSession::~ProjectSession() = default;

QString ProjectSession::displayName() const {
    return path_.isEmpty() ? tr("Untitled") : QFileInfo(path_).fileName();
}

bool ProjectSession::isDirty() const { return recovered_ || !undo_->stack()->isClean(); }

void ProjectSession::updateDirty() {
    const bool dirty = isDirty();
    if (dirty == lastDirty_) return;
    lastDirty_ = dirty;
    Q_EMIT dirtyChanged(dirty);
}

void ProjectSession::replace(Document doc, const QString& path, bool recovered) {
    *doc_ = std::move(doc);
    path_ = path;
    recovered_ = recovered;
    replacing_ = true;
    undo_->reset(); // clears both histories, emits documentChanged
    replacing_ = false;
    updateDirty();
    Q_EMIT projectChanged();
}

void ProjectSession::newDocument(std::vector<std::filesystem::path> sources, NodeId keepFrom) {
    Document doc(std::move(sources));
    const PipelineGraph& old = doc_->graph();
    if (keepFrom != kNoNode && old.hasNode(keepFrom)) {
        const std::pair<NodeKind, NodeId> kept[] = {{NodeKind::Cluster, kDefaultCluster},
                                                    {NodeKind::Bake, kDefaultBake}};
        for (const auto& [kind, target] : kept) {
            const NodeId from = old.upstreamOfKind(keepFrom, kind);
            if (from == kNoNode) continue;
            for (const auto& [key, value] : old.node(from).params)
                doc.graph().setParam(target, key, value);
        }
    }
    replace(std::move(doc), {}, false);
}

void ProjectSession::save(const QString& path) {
    const std::filesystem::path file = path.toStdString();
    saveProject(*doc_, file);
    removeAutosave(file);
    const bool renamed = path != path_;
    path_ = path;
    recovered_ = false;
    undo_->setClean();
    updateDirty();
    if (renamed) Q_EMIT projectChanged();
}

void ProjectSession::open(const QString& path, bool fromAutosave) {
    adopt(read(path, fromAutosave), path, fromAutosave);
}

Document ProjectSession::read(const QString& path, bool fromAutosave) {
    const std::filesystem::path file = path.toStdString();
    return fromAutosave ? openAutosave(file) : openProject(file);
}

void ProjectSession::adopt(Document doc, const QString& path, bool recovered) {
    if (!recovered) removeAutosave(path.toStdString());
    replace(std::move(doc), path, recovered);
}

bool ProjectSession::hasNewerAutosave(const QString& path) {
    return autosaveIsNewer(path.toStdString());
}

bool ProjectSession::autosave() {
    if (path_.isEmpty() || !isDirty()) return false;
    writeAutosave(*doc_, path_.toStdString());
    return true;
}

} // namespace hlod::widgets
