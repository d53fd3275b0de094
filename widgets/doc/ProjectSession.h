// The editor's open project: one hlod::Document (parameters, sources, hand edits, view state;
// the single source of truth, docs/architecture.md, "Undo"), its UndoAdapter, the
// `.hlodproj` path it was opened from or saved to, and the autosave (ProjectFile.h).
//
// Dirty: the document differs from the saved file: the undo stack is not at its clean index, or
// the content was recovered from an autosave and not saved since. dirtyChanged() follows it.
// Autosave: every kAutosaveMs while dirty and the project has a path, the document is written
// to `<project>.autosave`; saving removes it. Untitled projects are not autosaved.
// Replacing the document (newDocument, open) keeps the same Document and UndoAdapter objects,
// so widgets bound to them (ParameterPanel) stay valid; both histories are cleared.
// Failure: save/open throw hlod::Error (the caller shows it); nothing changes on failure.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include <QObject>
#include <QString>

#include "pipeline/doc/Document.h"
#include "widgets/doc/UndoAdapter.h"

class QTimer;

namespace hlod::widgets {

class ProjectSession : public QObject {
    Q_OBJECT
public:
    static constexpr int kAutosaveMs = 2 * 60 * 1000;

    explicit ProjectSession(QObject* parent = nullptr);
    ~ProjectSession() override;

    Document& document() { return *doc_; }
    const Document& document() const { return *doc_; }
    UndoAdapter* undo() { return undo_.get(); }

    // Empty for an untitled project.
    const QString& projectPath() const { return path_; }
    // "name.hlodproj", or "Untitled" for an untitled project.
    QString displayName() const;
    bool isDirty() const;
    // Whether closing should ask "save changes?" (the same as isDirty()).
    bool shouldPromptOnClose() const { return isDirty(); }

    // A fresh untitled document over `sources` (empty = the sample scene). It keeps the Cluster
    // and Bake parameters of the branch of `keepFrom` (a Bake node of the current document; the
    // defaults when kNoNode), not its hand edits (they name instances of the previous scene).
    void newDocument(std::vector<std::filesystem::path> sources, NodeId keepFrom = kNoNode);
    // Saves to `path` (becomes the project path), marks clean, removes the autosave.
    void save(const QString& path);
    // Opens `path` (or its autosave when `fromAutosave`; the result is then dirty):
    // adopt(read(path, fromAutosave), path, fromAutosave).
    void open(const QString& path, bool fromAutosave = false);
    // The document in `path` (or its autosave); the session is not touched. Throws hlod::Error
    // naming the file.
    static Document read(const QString& path, bool fromAutosave = false);
    // Makes `doc`, read from `path`, the open project (dirty when `recovered` from the
    // autosave; otherwise the autosave, declined, is removed).
    void adopt(Document doc, const QString& path, bool recovered);
    // Whether `path` has an autosave newer than itself (an offer to recover).
    static bool hasNewerAutosave(const QString& path);
    // Writes the autosave now when dirty and titled; true when one was written.
    bool autosave();
    QTimer* autosaveTimer() const { return timer_; }

    // True while newDocument/open replace the content (documentChanged then does not come
    // from an edit of the open scene's project).
    bool replacing() const { return replacing_; }

Q_SIGNALS:
    void dirtyChanged(bool dirty);
    void projectChanged();  // new document, open, or a save under a new path
    void documentChanged(); // any content change (command, undo, redo, replace)

private:
    void replace(Document doc, const QString& path, bool recovered);
    void updateDirty();

    std::unique_ptr<Document> doc_;
    std::unique_ptr<UndoAdapter> undo_;
    QString path_;
    bool recovered_ = false;
    bool lastDirty_ = false;
    bool replacing_ = false;
    QTimer* timer_ = nullptr;
};

} // namespace hlod::widgets
