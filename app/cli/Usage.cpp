// Help text of `hlod` from the command table and the parameter declarations (see Usage.h).
#include "Usage.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>
#include <sstream>

namespace hlod::cli {

namespace {

constexpr std::size_t kWidth = 79;
constexpr std::size_t kIndent = 24; // where descriptions start

std::string number(double x) {
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%g", x);
    return buf;
}

std::string withUnit(const std::string& value, const std::string& unit) {
    if (unit.empty()) return value;
    if (unit == "°") return value + unit;
    return value + " " + unit;
}

// Words of `text` wrapped to kWidth, every line indented by `indent`; the first line starts
// after `first` (a flag column) or on its own line when the flag is too long.
std::string wrap(const std::string& first, const std::string& text, std::size_t indent) {
    std::string out = first;
    std::size_t column = first.size();
    if (!first.empty() && column + 1 >= indent) {
        out += "\n";
        column = 0;
    }
    std::istringstream words(text);
    std::string word;
    bool lineStart = true;
    while (words >> word) {
        if (!lineStart && column + 1 + word.size() > kWidth) {
            out += "\n";
            column = 0;
            lineStart = true;
        }
        if (lineStart) {
            out.append(indent - std::min(indent, column), ' ');
            column = std::max(column, indent);
        } else {
            out += ' ';
            ++column;
        }
        out += word;
        column += word.size();
        lineStart = false;
    }
    return out + "\n";
}

std::string optionLine(const std::string& flag, const std::string& text) {
    return wrap("  " + flag, text, kIndent);
}

const char* kindTitle(NodeKind kind) {
    switch (kind) {
    case NodeKind::Import:
        return "Import options (reading the scene)";
    case NodeKind::Cluster:
        return "Cluster options (the HLOD tree)";
    case NodeKind::Bake:
        return "Bake options (proxies of inner nodes)";
    case NodeKind::Export:
        return "Export options (the package)";
    }
    return "Options";
}

// Placeholder for a parameter's value: its choices, or what the unit suggests.
std::string valueName(const ParamDecl& d) {
    static const std::map<std::string, std::string> named{
        {"k", "K"}, {"geo", "LAT,LON,H"}, {"deflection", "R"}, {"proxy_ratio", "R"}};
    if (auto it = named.find(d.key); it != named.end()) return it->second;
    switch (d.type) {
    case ParamType::Enum: {
        std::string s;
        for (const std::string& c : d.choices)
            s += (s.empty() ? "" : "|") + c;
        return s;
    }
    case ParamType::Int:
        return "N";
    case ParamType::Double:
        return d.unit == "px" ? "PX" : d.unit == "°" ? "DEG" : d.unit == "m" ? "M" : "X";
    case ParamType::Path:
        return "DIR";
    case ParamType::Text:
        return "TEXT";
    case ParamType::Bool:
        return "";
    }
    return "X";
}

} // namespace

std::string flagOf(const ParamDecl& d) {
    std::string flag = d.cliFlag;
    if (!d.cliAlias.empty()) flag += ", " + d.cliAlias;
    if (d.type != ParamType::Bool) flag += " " + valueName(d);
    return flag;
}

std::string describe(const ParamDecl& d) {
    std::string text = d.tooltip;
    if (!text.empty() && text.back() != '.') text += '.';
    switch (d.type) {
    case ParamType::Bool: {
        std::string what = d.tooltip;
        if (!what.empty()) what[0] = static_cast<char>(std::tolower(what[0]));
        text = std::string(d.cliNegated ? "Turn off " : "Turn on ") + d.label + " (" +
               (d.cliNegated ? "on" : "off") + " by default): " + what + ".";
        break;
    }
    case ParamType::Enum:
        text += " Default " + formatParamValue(d.defaultValue) + ".";
        break;
    case ParamType::Int:
    case ParamType::Double:
        text += " Default " + withUnit(formatParamValue(d.defaultValue), d.unit) + "; " +
                number(d.min) + " to " + withUnit(number(d.max), d.unit) + ".";
        break;
    case ParamType::Path:
    case ParamType::Text: {
        const std::string def = formatParamValue(d.defaultValue);
        if (!def.empty()) text += " Default " + def + ".";
        break;
    }
    }
    return text;
}

std::string commandHelp(const CommandSpec& c) {
    std::string out = "Usage: " + c.synopsis.front() + "\n";
    for (std::size_t i = 1; i < c.synopsis.size(); ++i)
        out += "       " + c.synopsis[i] + "\n";
    out += "\n" + wrap("", c.summary, 0) + "\n";
    if (!c.operands.empty()) {
        out += "Arguments:\n";
        for (const auto& [name, meaning] : c.operands)
            out += optionLine(name, meaning);
        out += "\n";
    }
    for (NodeKind kind : {NodeKind::Import, NodeKind::Cluster, NodeKind::Bake, NodeKind::Export}) {
        const bool whole = std::find(c.kinds.begin(), c.kinds.end(), kind) != c.kinds.end();
        std::string lines;
        for (const ParamDecl* d : parametersOf(kind)) {
            const bool taken =
                whole || std::find(c.params.begin(), c.params.end(), d->key) != c.params.end();
            if (taken && !d->cliFlag.empty()) lines += optionLine(flagOf(*d), describe(*d));
        }
        if (!lines.empty()) out += std::string(kindTitle(kind)) + ":\n" + lines + "\n";
    }
    if (!c.options.empty()) {
        out += "Options of hlod " + c.name + ":\n";
        for (const OptionSpec& o : c.options) {
            std::string flag = o.flag;
            if (!o.alias.empty()) flag += ", " + o.alias;
            if (!o.value.empty()) flag += " " + o.value;
            std::string text = o.help;
            if (!o.defaultText.empty()) text += " Default " + o.defaultText + ".";
            out += optionLine(flag, text);
        }
        out += "\n";
    }
    out += optionLine("-h, --help", "Print this help and exit.");
    return out;
}

namespace {

// "Usage: ..." and "  or:  ..." lines (the form help2man turns into the man page's synopsis).
std::string synopses() {
    std::vector<std::string> lines;
    for (const CommandSpec& c : commands())
        lines.insert(lines.end(), c.synopsis.begin(), c.synopsis.end());
    lines.push_back("hlod help [COMMAND]");
    lines.push_back("hlod --version");
    std::string out;
    for (std::size_t i = 0; i < lines.size(); ++i)
        out += (i == 0 ? "Usage: " : "  or:  ") + lines[i] + "\n";
    return out;
}

} // namespace

std::string shortUsage() {
    return synopses() + "\n" +
           wrap("",
                "Run 'hlod help COMMAND' (or 'hlod COMMAND --help') for every flag of a "
                "command, 'hlod --help' for all of them.",
                0);
}

std::string fullHelp() {
    std::string out = synopses() + "\n";
    out += wrap("",
                "hlod " HLOD_VERSION
                ", the HLOD Studio command-line tool, builds Hierarchical Level-of-Detail "
                "for 3D scenes (clusters of meshes with simplified proxies) and writes "
                "engine-ready 3D Tiles packages. Run 'hlod help COMMAND' for one command.",
                0);
    out += "\nCommands:\n";
    for (const CommandSpec& c : commands()) {
        const std::size_t stop = c.summary.find(". ");
        const std::string first =
            stop == std::string::npos ? c.summary : c.summary.substr(0, stop + 1);
        out += optionLine(c.name, first);
    }
    out += "\nGeneral options:\n";
    out += optionLine("-h, --help", "Print this help and exit.");
    out += optionLine("--version", "Print the version and exit.");
    out += "\n" + wrap("",
                       "Exit status: 0 on success; 1 when the work fails (one line on "
                       "stderr names the file and the problem); 2 for a usage error.",
                       0);
    for (const CommandSpec& c : commands())
        out += "\n" + commandHelp(c);
    return out;
}

std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates) {
    // Edit distance with transpositions (optimal string alignment): "biuld" is one step from
    // "build".
    auto distance = [](const std::string& a, const std::string& b) {
        std::vector<std::vector<std::size_t>> d(a.size() + 1,
                                                std::vector<std::size_t>(b.size() + 1));
        for (std::size_t i = 0; i <= a.size(); ++i)
            d[i][0] = i;
        for (std::size_t j = 0; j <= b.size(); ++j)
            d[0][j] = j;
        for (std::size_t i = 1; i <= a.size(); ++i)
            for (std::size_t j = 1; j <= b.size(); ++j) {
                d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1,
                                    d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
                if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                    d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        return d[a.size()][b.size()];
    };
    const std::size_t limit = std::clamp<std::size_t>(word.size() / 3, 1, 3);
    std::string best;
    std::size_t bestDistance = limit + 1;
    for (const std::string& c : candidates) {
        const std::size_t d = distance(word, c);
        if (d < bestDistance) {
            best = c;
            bestDistance = d;
        }
    }
    if (!best.empty() || word.size() < 4) return best;
    // A flag cut short ("--screen"): the one candidate it begins.
    for (const std::string& c : candidates) {
        if (c.rfind(word, 0) != 0) continue;
        if (!best.empty()) return {};
        best = c;
    }
    return best;
}

} // namespace hlod::cli
