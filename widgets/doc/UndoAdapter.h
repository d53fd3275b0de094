// Qt's undo machinery over the document's own history (docs/architecture.md, "Undo": undo
// belongs to the document; widgets wrap pipeline commands in QUndoCommands).
//
// The Document's UndoStack (pipeline/doc/UndoStack.h) is the authority; the QUndoStack mirrors
// it one-to-one so the editor gets QUndoStack::createUndoAction/createRedoAction (Edit menu,
// Ctrl+Z / Ctrl+Shift+Z), QUndoView (history) and cleanChanged (the title's dirty mark) for
// free. Every change goes through execute(): the pipeline command is applied to the document
// first (a command that does not apply throws inside the pipeline and is reported through
// commandFailed, nothing is pushed), then a QUndoCommand that forwards undo()/redo() to
// Document::undo()/redo() is pushed. When the document merged the command into its top one (a
// slider drag with one merge id), nothing is pushed: the top entry already stands for it.
//
// Lifetime: the adapter references the Document; it must not outlive it. Call reset() after
// replacing the document's content (new, open) and setClean() after saving.
// Usage (lead's integration):
//   auto* undo = new UndoAdapter(document, this);
//   editMenu->addAction(undo->stack()->createUndoAction(this));  // Ctrl+Z via setShortcuts
//   connect(undo, &UndoAdapter::documentChanged, ...);          // refresh panels, rerun graph
#pragma once

#include <memory>

#include <QObject>
#include <QString>
#include <QUndoStack>

#include "pipeline/doc/Command.h"
#include "pipeline/doc/Document.h"

namespace hlod::widgets {

class UndoAdapter : public QObject {
    Q_OBJECT
public:
    explicit UndoAdapter(Document& doc, QObject* parent = nullptr);

    Document& document() { return doc_; }
    QUndoStack* stack() { return &stack_; }

    // Applies and records `command`; false (and commandFailed) when it does not apply.
    bool execute(std::unique_ptr<Command> command);
    void setClean(); // the document was saved
    void reset();    // forget both histories (after new/open)

Q_SIGNALS:
    void documentChanged(); // after execute, undo or redo
    void commandFailed(const QString& message);

private:
    friend class ForwardingCommand;
    void forwardUndo();
    void forwardRedo();

    Document& doc_;
    QUndoStack stack_;
};

} // namespace hlod::widgets
