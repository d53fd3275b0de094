// "Use these settings" of the comparison view: one undoable document command that sets the
// volume, k and screen size of a CompareConfig on a branch of the document (the Bake node the
// quick configuration was laid over, and its Cluster node).
//
// Why a command of its own: the three values are separate SetParameter commands
// (pipeline/doc/Commands.h), and the user chose one configuration, so Edit ▸ Undo must take
// all of them back in one step. SetParameters applies its parts in order and reverts them in
// reverse; when a part does not apply, the parts already applied are reverted before the error
// propagates, so the document is left unchanged (Command.h contract).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "pipeline/doc/Commands.h"
#include "widgets/compare/CompareConfig.h"

namespace hlod::widgets {

class SetParameters : public Command {
public:
    SetParameters(std::string text, std::vector<std::unique_ptr<SetParameter>> parts);
    std::string text() const override { return text_; }
    void apply(Document& doc) override;
    void revert(Document& doc) override;
    nlohmann::json toJson() const override;
    std::size_t size() const { return parts_.size(); }

private:
    std::string text_;
    std::vector<std::unique_ptr<SetParameter>> parts_;
};

// The command that gives the branch of `bake` the values of `config` (only those that differ: k
// is left alone unless the volume is AABB); null when it has them all (or `bake` has no Cluster
// node upstream). SetParameters is also what several parameter edits of one gesture use (the
// export dialog's folder and DLOD choice).
std::unique_ptr<SetParameters> useConfigurationCommand(const Document& doc, NodeId bake,
                                                       const CompareConfig& config);

} // namespace hlod::widgets
