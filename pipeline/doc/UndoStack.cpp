// The document's undo history (contract in UndoStack.h).
#include "pipeline/doc/UndoStack.h"

namespace hlod {

void UndoStack::push(std::unique_ptr<Command> command, Document& doc) {
    command->apply(doc); // throws: nothing changed
    if (index_ < commands_.size()) {
        commands_.erase(commands_.begin() + static_cast<std::ptrdiff_t>(index_), commands_.end());
        if (clean_ > static_cast<std::ptrdiff_t>(index_)) clean_ = -1;
    }
    Command* top = index_ > 0 ? commands_[index_ - 1].get() : nullptr;
    const bool mergeable =
        top && command->mergeId() != 0 && top->mergeId() == command->mergeId() && !isClean();
    if (!(mergeable && top->mergeWith(*command))) {
        commands_.push_back(std::move(command));
        ++index_;
    }
    changed();
}

void UndoStack::undo(Document& doc) {
    if (!canUndo()) return;
    commands_[index_ - 1]->revert(doc);
    --index_;
    changed();
}

void UndoStack::redo(Document& doc) {
    if (!canRedo()) return;
    commands_[index_]->apply(doc);
    ++index_;
    changed();
}

std::string UndoStack::undoText() const {
    return canUndo() ? commands_[index_ - 1]->text() : std::string();
}

std::string UndoStack::redoText() const {
    return canRedo() ? commands_[index_]->text() : std::string();
}

void UndoStack::setClean() {
    clean_ = static_cast<std::ptrdiff_t>(index_);
    changed();
}

void UndoStack::clear() {
    commands_.clear();
    index_ = 0;
    clean_ = 0;
    changed();
}

} // namespace hlod
