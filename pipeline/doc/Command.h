// One undoable change of a Document (docs/architecture.md, "Undo": undo belongs to the document,
// every change, parameter edits included, is a command). Modelled on Qt's QUndoCommand (text,
// id/mergeWith) but without Qt, so the CLI and tests use the same commands; widgets/doc/UndoAdapter
// wraps them in QUndoCommands.
//
// Contract: apply() makes the change and records what it needs to undo it (the first apply
// computes the result from the document as it is then; a redo repeats exactly that result);
// revert() restores the document exactly as it was before apply() (the serialized document is
// identical). apply() that cannot be done throws hlod::Error(InvalidArgument) and leaves the
// document unchanged. Commands are data: toJson() describes one for a history view or a log.
// Merging: a command with a non-zero mergeId() may absorb the next command with the same
// mergeId (mergeWith returns true), so a slider drag is one undo step.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace hlod {

class Document;

class Command {
public:
    virtual ~Command() = default;
    virtual std::string text() const = 0; // for Edit ▸ Undo <text> and the history view
    virtual void apply(Document& doc) = 0;
    virtual void revert(Document& doc) = 0;
    virtual std::uint64_t mergeId() const { return 0; } // 0 = never merges
    // Takes over `next` (already applied to the document) when both belong to one gesture.
    virtual bool mergeWith(const Command& /*next*/) { return false; }
    virtual nlohmann::json toJson() const = 0;
};

} // namespace hlod
