#include "Args.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "Usage.h"
#include "pipeline/core/Error.h"

namespace hlod::cli {

Args::Args(const std::vector<std::string>& argv, const std::set<std::string>& valueOptions,
           const std::set<std::string>& switches) {
    for (std::size_t i = 0; i < argv.size(); ++i) {
        const std::string& a = argv[i];
        if (a.size() < 2 || a[0] != '-' || a == "-") {
            positionals_.push_back(a);
            continue;
        }
        std::string name = a;
        std::optional<std::string> inlineValue;
        if (auto eq = a.find('='); eq != std::string::npos) {
            name = a.substr(0, eq);
            inlineValue = a.substr(eq + 1);
        }
        if (switches.count(name) && !inlineValue) {
            switches_.insert(name);
        } else if (valueOptions.count(name)) {
            if (inlineValue) {
                values_[name] = *inlineValue;
            } else if (i + 1 < argv.size()) {
                values_[name] = argv[++i];
            } else {
                throw Error(ErrorCode::InvalidArgument, "option " + name + " needs a value");
            }
        } else {
            std::vector<std::string> known(valueOptions.begin(), valueOptions.end());
            known.insert(known.end(), switches.begin(), switches.end());
            const std::string hint = closestMatch(name, known);
            throw Error(ErrorCode::InvalidArgument,
                        "unknown option " + name +
                            (hint.empty() ? std::string() : " (did you mean " + hint + "?)"));
        }
    }
}

namespace {

std::set<std::string> valueFlagsOf(const CommandSpec& c) {
    std::set<std::string> out = paramValueFlags(c.kinds, c.params);
    for (const OptionSpec& o : c.options) {
        if (o.value.empty()) continue;
        out.insert(o.flag);
        if (!o.alias.empty()) out.insert(o.alias);
    }
    return out;
}

std::set<std::string> switchesOf(const CommandSpec& c) {
    std::set<std::string> out = paramSwitches(c.kinds, c.params);
    for (const OptionSpec& o : c.options)
        if (o.value.empty()) out.insert(o.flag);
    return out;
}

} // namespace

Args::Args(const std::vector<std::string>& argv, const CommandSpec& command)
    : Args(argv, valueFlagsOf(command), switchesOf(command)) {}

bool Args::has(const std::string& name) const {
    return switches_.count(name) || values_.count(name);
}

std::optional<std::string> Args::value(const std::string& name) const {
    auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    return it->second;
}

std::string Args::value(const std::string& name, const std::string& fallback) const {
    return value(name).value_or(fallback);
}

double Args::number(const std::string& name, double fallback, double lo, double hi) const {
    auto v = value(name);
    if (!v) return fallback;
    double out = 0.0;
    auto [ptr, ec] = std::from_chars(v->data(), v->data() + v->size(), out);
    if (ec != std::errc() || ptr != v->data() + v->size() || !std::isfinite(out)) {
        throw Error(ErrorCode::InvalidArgument, name + " expects a number, got '" + *v + "'");
    }
    if (out < lo || out > hi) {
        throw Error(ErrorCode::InvalidArgument, name + " must be within [" + std::to_string(lo) +
                                                    ", " + std::to_string(hi) + "], got " + *v);
    }
    return out;
}

int Args::integer(const std::string& name, int fallback, int lo, int hi) const {
    auto v = value(name);
    if (!v) return fallback;
    int out = 0;
    auto [ptr, ec] = std::from_chars(v->data(), v->data() + v->size(), out);
    if (ec != std::errc() || ptr != v->data() + v->size()) {
        throw Error(ErrorCode::InvalidArgument, name + " expects an integer, got '" + *v + "'");
    }
    if (out < lo || out > hi) {
        throw Error(ErrorCode::InvalidArgument, name + " must be within [" + std::to_string(lo) +
                                                    ", " + std::to_string(hi) + "], got " + *v);
    }
    return out;
}

namespace {

bool ofKinds(const ParamDecl& d, const std::vector<NodeKind>& kinds,
             const std::vector<std::string>& keys) {
    return !d.cliFlag.empty() && (std::find(kinds.begin(), kinds.end(), d.node) != kinds.end() ||
                                  std::find(keys.begin(), keys.end(), d.key) != keys.end());
}

} // namespace

std::set<std::string> paramValueFlags(const std::vector<NodeKind>& kinds,
                                      const std::vector<std::string>& keys) {
    std::set<std::string> out;
    for (const ParamDecl& d : parameterDeclarations()) {
        if (!ofKinds(d, kinds, keys) || d.type == ParamType::Bool) continue;
        out.insert(d.cliFlag);
        if (!d.cliAlias.empty()) out.insert(d.cliAlias);
    }
    return out;
}

std::set<std::string> paramSwitches(const std::vector<NodeKind>& kinds,
                                    const std::vector<std::string>& keys) {
    std::set<std::string> out;
    for (const ParamDecl& d : parameterDeclarations()) {
        if (ofKinds(d, kinds, keys) && d.type == ParamType::Bool) out.insert(d.cliFlag);
    }
    return out;
}

std::vector<std::pair<const ParamDecl*, ParamValue>>
paramsFromArgs(const Args& args, const std::vector<NodeKind>& kinds,
               const std::vector<std::string>& keys) {
    std::vector<std::pair<const ParamDecl*, ParamValue>> out;
    for (const ParamDecl& d : parameterDeclarations()) {
        if (!ofKinds(d, kinds, keys)) continue;
        if (d.type == ParamType::Bool) {
            const bool on = !d.cliNegated;
            if (args.has(d.cliFlag))
                out.emplace_back(std::piecewise_construct, std::forward_as_tuple(&d),
                                 std::forward_as_tuple(on));
            continue;
        }
        for (const std::string* flag : {&d.cliFlag, &d.cliAlias}) {
            if (flag->empty()) continue;
            if (auto v = args.value(*flag)) {
                out.push_back({&d, parseParamText(d, *v, *flag)});
                break;
            }
        }
    }
    return out;
}

} // namespace hlod::cli
