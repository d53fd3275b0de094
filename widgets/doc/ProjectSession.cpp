// The editor's open project (see ProjectSession.h).
#include "widgets/doc/ProjectSession.h"

#include <QFileInfo>
#include <QTimer>

#include "pipeline/doc/ProjectFile.h"

namespace hlod::widgets {

HlodSettings settingsOf(const Document& doc) {
    const PipelineGraph& g = doc.graph();
    // A graph edited down to no Cluster or Bake node builds with that stage's defaults.
    const NodeId clusterId = doc.clusterNode();
    const NodeId bakeId = doc.bakeNode();
    const ParamValues clusterParams =
        clusterId == kNoNode ? defaultValues(NodeKind::Cluster) : g.node(clusterId).params;
    const ParamValues bakeParams =
        bakeId == kNoNode ? defaultValues(NodeKind::Bake) : g.node(bakeId).params;
    HlodSettings s = hlodSettingsFrom(clusterParams, bakeParams);
    if (clusterId != kNoNode) {
        const HandEdits& edits = g.node(clusterId).edits;
        applyConstraints(edits, s.cluster);
        s.dissolved = edits.dissolved;
    }
    return s;
}

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

void ProjectSession::newDocument(std::vector<std::filesystem::path> sources) {
    Document doc(std::move(sources));
    // A new scene keeps the parameters the user chose (not the hand edits: they name instances
    // of the previous scene).
    for (NodeId id : {doc.clusterNode(), doc.bakeNode()}) {
        const GraphNode& before = doc_->graph().node(id);
        for (const auto& [key, value] : before.params)
            if (key != "output") doc.graph().setParam(id, key, value);
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

HlodSettings ProjectSession::settings() const { return settingsOf(*doc_); }

} // namespace hlod::widgets
