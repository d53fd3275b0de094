// Configurations of the comparison view (see CompareConfig.h).
#include "widgets/compare/CompareConfig.h"

#include <QCoreApplication>
#include <QLocale>
#include <QRegularExpression>

#include "pipeline/graph/Parameters.h"

namespace hlod::widgets {

namespace {

// k and S as the user typed them: no trailing zeros ("2", "0.5", "412.5").
QString number(double value) { return QString::number(value, 'g', 10); }

bool fail(QString* error, const QString& message) {
    if (error) *error = message;
    return false;
}

} // namespace

CompareConfig configOf(const PipelineGraph& graph, NodeId bake) {
    ParamValues cluster = defaultValues(NodeKind::Cluster);
    ParamValues baking = defaultValues(NodeKind::Bake);
    if (graph.hasNode(bake)) {
        baking = graph.node(bake).params;
        if (const NodeId c = graph.upstreamOfKind(bake, NodeKind::Cluster); c != kNoNode)
            cluster = graph.node(c).params;
    }
    CompareConfig c;
    c.volume = volumeTypeFromString(paramText(cluster, "volume"));
    c.k = paramNumber(cluster, "k");
    c.screenSize = paramNumber(baking, "screen_size");
    return c;
}

void applyConfig(PipelineGraph& graph, NodeId cluster, NodeId bake, const CompareConfig& config) {
    graph.setParam(cluster, "volume", std::string(toString(config.volume)));
    graph.setParam(cluster, "k", config.k);
    graph.setParam(bake, "screen_size", config.screenSize);
}

QString configLabel(const CompareConfig& config, bool withScreenSize) {
    QString label;
    switch (config.volume) {
    case VolumeType::Sphere:
        label = QCoreApplication::translate("CompareConfig", "Sphere");
        break;
    case VolumeType::Aabb:
        label = QCoreApplication::translate("CompareConfig", "AABB k=%1")
                    .arg(QLocale().toString(config.k, 'g', 10));
        break;
    case VolumeType::Octree:
        label = QCoreApplication::translate("CompareConfig", "Octree");
        break;
    case VolumeType::Original:
        label = QCoreApplication::translate("CompareConfig", "Original hierarchy");
        break;
    }
    if (withScreenSize)
        label = QCoreApplication::translate("CompareConfig", "%1, S = %2 px")
                    .arg(label, QLocale().toString(config.screenSize, 'g', 10));
    return label;
}

QString configSpec(const CompareConfig& config) {
    QString spec = QString::fromLatin1(toString(config.volume));
    if (config.volume == VolumeType::Aabb) spec += QStringLiteral("-k") + number(config.k);
    return spec + QLatin1Char('@') + number(config.screenSize);
}

bool parseSide(const QString& text, const CompareConfig& base, CompareSide& out, QString* error) {
    static const QRegularExpression node(QStringLiteral(R"(^#([0-9]{1,9})$)"));
    if (const QRegularExpressionMatch m = node.match(text.trimmed()); m.hasMatch()) {
        out = {static_cast<NodeId>(m.captured(1).toUInt()), base};
        return true;
    }
    // volume, then optionally "-k" and a number, then optionally "@" and a number.
    static const QRegularExpression pattern(
        QStringLiteral(R"(^(current|sphere|octree|original|aabb))"
                       R"((?:-k([0-9]+(?:\.[0-9]*)?))?)"
                       R"((?:@([0-9]+(?:\.[0-9]*)?))?$)"));
    const QString t = text.trimmed().toLower();
    const QRegularExpressionMatch m = pattern.match(t);
    if (!m.hasMatch())
        return fail(error, QCoreApplication::translate(
                               "CompareConfig",
                               "\"%1\" is not a configuration: use #N (Bake node N), sphere, "
                               "aabb, aabb-kK, octree, original or current, optionally followed "
                               "by @S (screen size in pixels)")
                               .arg(text));
    CompareConfig c = base;
    const QString volume = m.captured(1);
    if (volume != QLatin1String("current")) c.volume = volumeTypeFromString(volume.toStdString());
    if (m.hasCaptured(2)) {
        if (c.volume != VolumeType::Aabb)
            return fail(error, QCoreApplication::translate("CompareConfig",
                                                           "\"%1\": k applies to aabb only")
                                   .arg(text));
        const ParamDecl& k = parameterDeclaration("k");
        c.k = m.captured(2).toDouble();
        if (c.k < k.min || c.k > k.max)
            return fail(error, QCoreApplication::translate("CompareConfig",
                                                           "\"%1\": k must be within [%2, %3]")
                                   .arg(text)
                                   .arg(k.min)
                                   .arg(k.max));
    }
    if (m.hasCaptured(3)) {
        const ParamDecl& s = parameterDeclaration("screen_size");
        c.screenSize = m.captured(3).toDouble();
        if (c.screenSize < s.min || c.screenSize > s.max)
            return fail(error,
                        QCoreApplication::translate(
                            "CompareConfig", "\"%1\": the screen size must be within [%2, %3] px")
                            .arg(text)
                            .arg(s.min)
                            .arg(s.max));
    }
    out = {kNoNode, c};
    return true;
}

bool parseSidePair(const QString& text, const CompareConfig& base,
                   std::pair<CompareSide, CompareSide>& out, QString* error) {
    const QStringList parts = text.split(QLatin1Char(':'));
    if (parts.size() != 2)
        return fail(error,
                    QCoreApplication::translate(
                        "CompareConfig", "\"%1\" is not a pair of configurations LEFT:RIGHT, e.g. "
                                         "sphere:aabb-k2")
                        .arg(text));
    std::pair<CompareSide, CompareSide> pair;
    if (!parseSide(parts[0], base, pair.first, error) ||
        !parseSide(parts[1], base, pair.second, error))
        return false;
    out = pair;
    return true;
}

std::pair<CompareSide, CompareSide> defaultSides(const PipelineGraph& graph, NodeId shown,
                                                 const std::vector<NodeId>& bakes) {
    const CompareConfig base = configOf(graph, shown);
    const CompareSide left{shown, base};
    for (NodeId other : bakes)
        if (other != shown) return {left, {other, configOf(graph, other)}};
    CompareConfig right = base;
    if (base.volume == VolumeType::Aabb) {
        right.volume = VolumeType::Sphere;
    } else {
        right.volume = VolumeType::Aabb;
        right.k = 2.0; // the thesis' most compact AABB variant
    }
    return {left, {kNoNode, right}};
}

} // namespace hlod::widgets
