// "Use these settings" as one document command (see UseConfiguration.h).
#include "widgets/compare/UseConfiguration.h"

#include "pipeline/doc/Document.h"
#include "pipeline/graph/Parameters.h"

namespace hlod::widgets {

SetParameters::SetParameters(std::string text, std::vector<std::unique_ptr<SetParameter>> parts)
    : text_(std::move(text)), parts_(std::move(parts)) {}

void SetParameters::apply(Document& doc) {
    std::size_t applied = 0;
    try {
        for (; applied < parts_.size(); ++applied)
            parts_[applied]->apply(doc);
    } catch (...) {
        while (applied > 0)
            parts_[--applied]->revert(doc);
        throw;
    }
}

void SetParameters::revert(Document& doc) {
    for (auto it = parts_.rbegin(); it != parts_.rend(); ++it)
        (*it)->revert(doc);
}

nlohmann::json SetParameters::toJson() const {
    nlohmann::json parts = nlohmann::json::array();
    for (const auto& part : parts_)
        parts.push_back(part->toJson());
    return {{"command", "set_parameters"}, {"text", text_}, {"parts", parts}};
}

std::unique_ptr<SetParameters> useConfigurationCommand(const Document& doc, NodeId bakeNode,
                                                       const CompareConfig& config) {
    std::vector<std::unique_ptr<SetParameter>> parts;
    if (!doc.graph().hasNode(bakeNode)) return nullptr;
    const NodeId clusterNode = doc.graph().upstreamOfKind(bakeNode, NodeKind::Cluster);
    if (clusterNode == kNoNode) return nullptr;
    const ParamValues& cluster = doc.graph().node(clusterNode).params;
    const ParamValues& bake = doc.graph().node(bakeNode).params;
    const std::string volume = toString(config.volume);
    if (paramText(cluster, "volume") != volume)
        parts.push_back(std::make_unique<SetParameter>(clusterNode, "volume", volume));
    if (config.volume == VolumeType::Aabb && paramNumber(cluster, "k") != config.k)
        parts.push_back(std::make_unique<SetParameter>(clusterNode, "k", config.k));
    if (paramNumber(bake, "screen_size") != config.screenSize)
        parts.push_back(std::make_unique<SetParameter>(bakeNode, "screen_size", config.screenSize));
    if (parts.empty()) return nullptr;
    const std::string text = "Use " + configLabel(config, true).toStdString() + " for " +
                             nodeLabel(doc.graph().node(bakeNode)) + " from the comparison";
    return std::make_unique<SetParameters>(text, std::move(parts));
}

} // namespace hlod::widgets
