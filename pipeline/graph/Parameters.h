// Every pipeline parameter, declared once as data (docs/architecture.md, "The path of a
// parameter"): its key, label, type, default, range, unit, tooltip, enum choices and CLI flag.
// The editor's parameter panel, the flags of `hlod build`, `plan` and `bench`, the project file
// and every check of a value a user gives are generated from these declarations, so a
// parameter's range, default and unit are written in exactly one place (Parameters.cpp).
//
// Values: a ParamValue holds bool (Bool), int (Int), double (Double) or std::string (Enum: one
// of `choices`; Path: a file or folder, empty allowed; Text: free text checked by the node that
// uses it). ParamValues maps keys to values of one node; a missing key means its default.
// Failure: everything that takes a value from outside (CLI text, JSON) validates it against the
// declaration and throws hlod::Error(InvalidArgument) with a message that names the parameter
// and what is wrong ("k must be within [0, 16], got 20"); the JSON readers throw Malformed with
// the file and key when given a file.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "pipeline/cluster/Cluster.h"
#include "pipeline/io/Import.h"
#include "pipeline/proxy/ProxyBaker.h"

namespace hlod {

// The pipeline stages; every parameter belongs to one of them.
enum class NodeKind { Import, Cluster, Bake, Export };
const char* toString(NodeKind kind);
NodeKind nodeKindFromString(const std::string& text); // throws InvalidArgument

enum class ParamType { Enum, Double, Int, Bool, Path, Text };
const char* toString(ParamType type);

using ParamValue = std::variant<bool, int, double, std::string>;
using ParamValues = std::map<std::string, ParamValue>;

struct ParamDecl {
    std::string key;   // snake_case, the project-file key ("max_children")
    std::string label; // for the panel ("Max children")
    ParamType type = ParamType::Double;
    NodeKind node = NodeKind::Cluster;
    ParamValue defaultValue;
    double min = 0.0; // Int/Double: inclusive range
    double max = 0.0;
    std::string unit; // "px", "°", "m", "" when none
    std::string tooltip;
    std::vector<std::string> choices; // Enum only
    // CLI: the flag ("--k"), empty when the parameter has none; an alias ("--output"); for a
    // Bool a switch that sets the value to false when `cliNegated` ("--no-cache"), else true.
    std::string cliFlag;
    std::string cliAlias;
    bool cliNegated = false;
    // Int/Double: a slider makes sense (bounded, continuous for the user).
    bool slider = false;
    // Text: checks a non-empty value, throws InvalidArgument (e.g. parseGeoLocation).
    void (*checkText)(const std::string& text) = nullptr;
};

// All declarations, in panel order (grouped by node kind).
const std::vector<ParamDecl>& parameterDeclarations();
// The declarations of one node kind, in panel order.
std::vector<const ParamDecl*> parametersOf(NodeKind kind);
// Throws InvalidArgument for an unknown key.
const ParamDecl& parameterDeclaration(const std::string& key);
const ParamDecl* findParameter(const std::string& key); // nullptr when unknown

// Defaults of every parameter of `kind`.
ParamValues defaultValues(NodeKind kind);

// Throws InvalidArgument when `value` has the wrong type or is out of range / not a choice.
// An int is accepted for a Double parameter (and converted by normalizedValue).
void validateValue(const ParamDecl& decl, const ParamValue& value);
ParamValue normalizedValue(const ParamDecl& decl, const ParamValue& value);

// Parses user text (a CLI argument, a text field) for `decl`; `name` is what the message calls
// the parameter ("--k" on the command line). Throws InvalidArgument.
ParamValue parseParamText(const ParamDecl& decl, const std::string& text, const std::string& name);
std::string formatParamValue(const ParamValue& value);

// Typed reads with the default as fallback (the key must be declared).
double paramNumber(const ParamValues& values, const std::string& key);
int paramInt(const ParamValues& values, const std::string& key);
bool paramBool(const ParamValues& values, const std::string& key);
std::string paramText(const ParamValues& values, const std::string& key);

// JSON: {"k": 1.0, "volume": "sphere", ...} (every declared key of the kind, defaults
// included, so a project file is explicit). Reading ignores nothing: an unknown key, a wrong
// type or a value out of range throws Malformed naming `file` and the key (InvalidArgument
// when `file` is empty).
nlohmann::json paramsToJson(NodeKind kind, const ParamValues& values);
ParamValues paramsFromJson(NodeKind kind, const nlohmann::json& j,
                           const std::filesystem::path& file = {});

// Conversions to and from the pipeline's parameter structs (hand edits are not parameters:
// they live in HandEdits.h and reach the clusterer through the Cluster step, NodeSteps.cpp).
ImportOptions importOptionsFrom(const ParamValues& importValues);
ClusterParams clusterParamsFrom(const ParamValues& clusterValues);
// `cache` on and `cache_dir` empty resolve to defaultProxyCacheDir().
BakeParams bakeParamsFrom(const ParamValues& bakeValues);
ParamValues paramsFrom(const ImportOptions& options);
ParamValues paramsFrom(const ClusterParams& params);
ParamValues paramsFrom(const BakeParams& params);

// A user-level proxy cache shared by all builds, like ccache: $XDG_CACHE_HOME/hlod/proxies,
// else ~/.cache/hlod/proxies; empty (no cache) when neither variable is set.
std::filesystem::path defaultProxyCacheDir();

} // namespace hlod
