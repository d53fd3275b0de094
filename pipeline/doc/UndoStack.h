// The document's undo history: a list of applied commands and an index (commands [0, index)
// are applied, [index, count) can be redone), with a clean index for the "unsaved changes"
// mark, as QUndoStack does.
//
// push(): applies the command (an exception leaves stack and document unchanged), drops the redo
// tail, then either merges it into the top command (same non-zero mergeId, the top is not the
// clean state) or appends it. undo()/redo() revert/apply one command; an exception from them
// propagates and leaves the index where it was.
// Listener: called after every change of index, count or clean state (single-threaded).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "pipeline/doc/Command.h"

namespace hlod {

class UndoStack {
public:
    void push(std::unique_ptr<Command> command, Document& doc);
    bool canUndo() const { return index_ > 0; }
    bool canRedo() const { return index_ < commands_.size(); }
    void undo(Document& doc); // no-op when !canUndo()
    void redo(Document& doc); // no-op when !canRedo()

    std::size_t count() const { return commands_.size(); }
    std::size_t index() const { return index_; }
    const Command& command(std::size_t i) const { return *commands_.at(i); }
    std::string undoText() const; // empty when nothing to undo
    std::string redoText() const;

    void setClean(); // the current index is the saved state
    bool isClean() const { return clean_ == static_cast<std::ptrdiff_t>(index_); }
    void clear(); // forgets the history (a new or reopened document); clean afterwards

    // A fresh non-zero merge id for one gesture (a slider drag, a node drag).
    std::uint64_t newMergeId() { return ++lastMergeId_; }

    void setChangedListener(std::function<void()> listener) { listener_ = std::move(listener); }

private:
    void changed() const {
        if (listener_) listener_();
    }
    std::vector<std::unique_ptr<Command>> commands_;
    std::size_t index_ = 0;
    std::ptrdiff_t clean_ = 0; // -1 when the saved state cannot be reached any more
    std::uint64_t lastMergeId_ = 0;
    std::function<void()> listener_;
};

} // namespace hlod
