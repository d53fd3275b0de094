// QUndoStack mirror of the document's history (contract in UndoAdapter.h).
#include "widgets/doc/UndoAdapter.h"

#include "pipeline/core/Error.h"

namespace hlod::widgets {

// One entry of the QUndoStack: stands for the document command at the same index.
class ForwardingCommand : public QUndoCommand {
public:
    ForwardingCommand(UndoAdapter& adapter, const QString& text)
        : QUndoCommand(text), adapter_(adapter) {}
    void undo() override { adapter_.forwardUndo(); }
    void redo() override {
        // QUndoStack::push calls redo(); the document applied the command already.
        if (first_) {
            first_ = false;
            return;
        }
        adapter_.forwardRedo();
    }

private:
    UndoAdapter& adapter_;
    bool first_ = true;
};

UndoAdapter::UndoAdapter(Document& doc, QObject* parent) : QObject(parent), doc_(doc) {}

bool UndoAdapter::execute(std::unique_ptr<Command> command) {
    const std::size_t index = doc_.history().index();
    try {
        doc_.execute(std::move(command));
    } catch (const std::exception& e) {
        Q_EMIT commandFailed(QString::fromStdString(e.what()));
        return false;
    }
    // A merged command leaves the index where it was (the top entry stands for both).
    if (doc_.history().index() == index + 1) {
        const QString text = QString::fromStdString(doc_.history().undoText());
        stack_.push(new ForwardingCommand(*this, text));
    }
    Q_EMIT documentChanged();
    return true;
}

void UndoAdapter::forwardUndo() {
    try {
        doc_.undo();
    } catch (const std::exception& e) {
        Q_EMIT commandFailed(QString::fromStdString(e.what()));
    }
    Q_EMIT documentChanged();
}

void UndoAdapter::forwardRedo() {
    try {
        doc_.redo();
    } catch (const std::exception& e) {
        Q_EMIT commandFailed(QString::fromStdString(e.what()));
    }
    Q_EMIT documentChanged();
}

void UndoAdapter::setClean() {
    doc_.markSaved();
    stack_.setClean();
}

void UndoAdapter::reset() {
    doc_.history().clear();
    stack_.clear();
    Q_EMIT documentChanged();
}

} // namespace hlod::widgets
