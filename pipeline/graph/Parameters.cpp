// The parameter declarations and their validation, text and JSON forms (see Parameters.h).
// Ranges are the ones `hlod build` has always enforced (ScreenParams' validate(), the
// clusterer's constraints), so the CLI, the panel and the project file agree.
#include "pipeline/graph/Parameters.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pipeline/core/Error.h"
#include "pipeline/export/Geo.h"

namespace hlod {

namespace {

ParamDecl decl(std::string key, std::string label, ParamType type, NodeKind node, ParamValue def,
               std::string unit, std::string tooltip, std::string flag) {
    ParamDecl d;
    d.key = std::move(key);
    d.label = std::move(label);
    d.type = type;
    d.node = node;
    d.defaultValue = std::move(def);
    d.unit = std::move(unit);
    d.tooltip = std::move(tooltip);
    d.cliFlag = std::move(flag);
    return d;
}

ParamDecl ranged(ParamDecl d, double lo, double hi, bool slider = false) {
    d.min = lo;
    d.max = hi;
    d.slider = slider;
    return d;
}

ParamDecl choices(ParamDecl d, std::vector<std::string> c) {
    d.choices = std::move(c);
    return d;
}

using T = ParamType;
using N = NodeKind;

// The import budget (ImportLimits.h, where each default is explained): what one scene file
// may expand into before it is refused (textures: left undecoded).
void addImportLimits(std::vector<ParamDecl>& v) {
    const ImportLimits l;
    const auto limit = [&](const char* key, const char* label, std::uint64_t value,
                           const char* help, const char* flag) {
        v.push_back(ranged(decl(key, label, T::Int, N::Import, static_cast<int>(value), "",
                                std::string("Import limit: ") + help, flag),
                           1, 2147483647.0));
    };
    limit("max_triangles", "Max triangles", l.maxTriangles,
          "triangles of all placed meshes (as `hlod info` counts them); a file over it is refused",
          "--max-triangles");
    limit("max_unique_triangles", "Max unique triangles", l.maxUniqueTriangles,
          "triangles the file's meshes hold, each mesh counted once; a file over it is refused",
          "--max-unique-triangles");
    limit("max_instances", "Max instances", l.maxInstances,
          "placed meshes (and nodes) once every level of instancing is expanded; a file over "
          "it is refused",
          "--max-instances");
    limit("max_texels", "Max texels", l.maxTexels,
          "texels of all decoded textures of a file; images past it are not decoded (their "
          "materials keep their colour)",
          "--max-texels");
}

void addImportAndCluster(std::vector<ParamDecl>& v) {
    const ImportOptions io;
    const ClusterParams cp;
    v.push_back(ranged(decl("deflection", "CAD deflection", T::Double, N::Import,
                            io.cadRelativeDeflection, "× diagonal",
                            "Linear deflection of the CAD tessellation (STEP, IGES, BREP), "
                            "relative to the model's bounding-box diagonal",
                            "--deflection"),
                       1e-6, 0.5));
    v.push_back(
        ranged(decl("brep_unit", "BREP unit", T::Double, N::Import, io.cadBrepUnitMetres, "m",
                    "Metres per BREP coordinate unit (BREP files carry no unit; 0.001 = "
                    "millimetres)",
                    "--brep-unit"),
               1e-9, 1e3));
    addImportLimits(v);
    v.push_back(choices(decl("volume", "Volume", T::Enum, N::Cluster, std::string("sphere"), "",
                             "Clustering volume: bounding spheres (Sappa & Garcia), AABBs with "
                             "the proportion constraint k, loose octree, or the original "
                             "hierarchy",
                             "--volume"),
                        {"sphere", "aabb", "octree", "original"}));
    v.push_back(ranged(decl("k", "Proportion k", T::Double, N::Cluster, cp.k, "",
                            "AABB proportion constraint exponent: higher k prefers cubic "
                            "clusters (the thesis evaluates 0, 1 and 2)",
                            "--k"),
                       0.0, 16.0, true));
    v.push_back(ranged(decl("max_children", "Max children", T::Int, N::Cluster, cp.maxChildren, "",
                            "Largest number of children one merge gives a cluster (level growth "
                            "and the proxy economy may widen clusters afterwards)",
                            "--max-children"),
                       2, 1024));
    v.push_back(ranged(decl("level_growth", "Level growth", T::Double, N::Cluster,
                            kDefaultLevelGrowth, "× diameter",
                            "Sphere and AABB trees: a cluster is at least this many times wider "
                            "than the clusters below it (thinner levels are dissolved), so each "
                            "proxy's error budget grows enough to drop triangles; 1 keeps every "
                            "merge",
                            "--level-growth"),
                       1.0, 16.0));
}

void addBakeAndExport(std::vector<ParamDecl>& v) {
    const ScreenParams sp;
    v.push_back(choices(decl("proxy", "Proxy method", T::Enum, N::Bake, std::string("decimate"), "",
                             "How inner nodes get their mesh: aggregate + quadric decimation, "
                             "voxel remesh (watertight shell), or sloppy aggregate",
                             "--proxy"),
                        {"decimate", "remesh", "sloppy"}));
    v.push_back(
        ranged(decl("screen_size", "Screen size", T::Double, N::Bake, sp.screenSize, "px",
                    "Switch size S: a cluster is drawn as its proxy once it looks smaller than S "
                    "pixels. A smaller S switches proxies in later (the camera farther away), "
                    "so more original triangles are drawn; a larger S draws fewer",
                    "--screen-size"),
               1.0, 100000.0, true));
    v.push_back(
        ranged(decl("pixel_error", "Pixel error", T::Double, N::Bake, sp.pixelError, "px",
                    "Largest proxy deviation on screen at the switch point", "--pixel-error"),
               0.01, 1000.0, true));
    v.push_back(
        ranged(decl("fov", "Field of view", T::Double, N::Bake, sp.fovYDegrees, "°",
                    "Vertical field of view of the reference camera (switch distances)", "--fov"),
               1.0, 179.0, true));
    v.push_back(ranged(
        decl("viewport_height", "Viewport height", T::Double, N::Bake, sp.viewportHeight, "px",
             "Viewport height of the reference camera (switch distances)", "--viewport-height"),
        1.0, 100000.0));
    v.push_back(ranged(decl("proxy_ratio", "Proxy ratio", T::Double, N::Bake,
                            BakeParams{}.proxyRatio, "× input",
                            "A cluster keeps its proxy only when the proxy has at most this "
                            "fraction of the triangles it replaces; otherwise the cluster is "
                            "dissolved into its parent. All proxies together then hold at most "
                            "ratio / (1 - ratio) of the original; 1 keeps every proxy",
                            "--proxy-ratio"),
                       0.05, 1.0, true));
    v.push_back(
        choices(decl("proxy_textures", "Proxy textures", T::Enum, N::Bake, std::string("on"), "",
                     "Bake a base-colour atlas for every proxy (charts, one texel per "
                     "pixel at the switch, sampled from the originals); off: the "
                     "proxies carry vertex colours only",
                     "--proxy-textures"),
                {"on", "off"}));
    v.push_back(ranged(decl("threads", "Threads", T::Int, N::Bake, 0, "",
                            "Worker threads for baking; 0 = all hardware threads", "--threads"),
                       0, 1024));
    ParamDecl cache = decl("cache", "Proxy cache", T::Bool, N::Bake, true, "",
                           "Reuse proxies baked before (content-hash cache on disk)", "--no-cache");
    cache.cliNegated = true;
    v.push_back(cache);
    v.push_back(decl("cache_dir", "Cache folder", T::Path, N::Bake, std::string(), "",
                     "Folder of the proxy cache; empty = the user cache (~/.cache/hlod/proxies)",
                     "--cache"));
    ParamDecl out = decl("output", "Output folder", T::Path, N::Export, std::string(), "",
                         "Folder the package is written to (replaced atomically)", "-o");
    out.cliAlias = "--output";
    v.push_back(out);
    ParamDecl dlod =
        decl("dlod", "DLOD statistics", T::Bool, N::Export, true, "",
             "Compute the DLOD chain baseline row of the statistics table", "--no-dlod");
    dlod.cliNegated = true;
    v.push_back(dlod);
    v.push_back(
        choices(decl("compression", "Compression", T::Enum, N::Export, std::string("meshopt"), "",
                     "Geometry of the package's tiles: quantised and compressed "
                     "(KHR_mesh_quantization + EXT_meshopt_compression, what 3D Tiles "
                     "runtimes decode) or plain glTF floats",
                     "--compression"),
                {"meshopt", "none"}));
    ParamDecl geo = decl("geo", "Geolocation", T::Text, N::Export, std::string(), "",
                         "lat,lon,height (degrees, degrees, metres): places the root on the "
                         "globe; empty = local frame",
                         "--geo");
    geo.checkText = [](const std::string& text) { parseGeoLocation(text); };
    v.push_back(geo);
}

std::vector<ParamDecl> makeDeclarations() {
    std::vector<ParamDecl> v;
    addImportAndCluster(v);
    addBakeAndExport(v);
    return v;
}

std::string formatNumber(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

[[noreturn]] void invalid(const std::string& what) {
    throw Error(ErrorCode::InvalidArgument, what);
}

} // namespace

const char* toString(NodeKind kind) {
    switch (kind) {
    case NodeKind::Import:
        return "import";
    case NodeKind::Cluster:
        return "cluster";
    case NodeKind::Bake:
        return "bake";
    case NodeKind::Export:
        return "export";
    }
    return "?";
}

NodeKind nodeKindFromString(const std::string& text) {
    for (NodeKind k : {NodeKind::Import, NodeKind::Cluster, NodeKind::Bake, NodeKind::Export}) {
        if (text == toString(k)) return k;
    }
    invalid("unknown node kind '" + text + "' (import, cluster, bake or export)");
}

const char* toString(ParamType type) {
    switch (type) {
    case ParamType::Enum:
        return "enum";
    case ParamType::Double:
        return "double";
    case ParamType::Int:
        return "int";
    case ParamType::Bool:
        return "bool";
    case ParamType::Path:
        return "path";
    case ParamType::Text:
        return "text";
    }
    return "?";
}

const std::vector<ParamDecl>& parameterDeclarations() {
    static const std::vector<ParamDecl> decls = makeDeclarations();
    return decls;
}

std::vector<const ParamDecl*> parametersOf(NodeKind kind) {
    std::vector<const ParamDecl*> out;
    for (const ParamDecl& d : parameterDeclarations()) {
        if (d.node == kind) out.push_back(&d);
    }
    return out;
}

const ParamDecl* findParameter(const std::string& key) {
    for (const ParamDecl& d : parameterDeclarations()) {
        if (d.key == key) return &d;
    }
    return nullptr;
}

const ParamDecl& parameterDeclaration(const std::string& key) {
    if (const ParamDecl* d = findParameter(key)) return *d;
    invalid("unknown parameter '" + key + "'");
}

ParamValues defaultValues(NodeKind kind) {
    ParamValues v;
    for (const ParamDecl* d : parametersOf(kind))
        v[d->key] = d->defaultValue;
    return v;
}

void validateValue(const ParamDecl& d, const ParamValue& value) {
    const std::string& k = d.key;
    switch (d.type) {
    case ParamType::Bool:
        if (!std::holds_alternative<bool>(value)) invalid(k + " expects true or false");
        return;
    case ParamType::Int:
    case ParamType::Double: {
        double x = 0.0;
        if (const int* i = std::get_if<int>(&value)) {
            x = *i;
        } else if (const double* f = std::get_if<double>(&value);
                   f && d.type == ParamType::Double) {
            x = *f;
        } else {
            invalid(k + (d.type == ParamType::Int ? " expects an integer" : " expects a number"));
        }
        if (!std::isfinite(x) || x < d.min || x > d.max) {
            invalid(k + " must be within [" + formatNumber(d.min) + ", " + formatNumber(d.max) +
                    "], got " + formatNumber(x));
        }
        return;
    }
    case ParamType::Enum: {
        const std::string* s = std::get_if<std::string>(&value);
        if (!s) invalid(k + " expects one of its choices");
        for (const std::string& c : d.choices) {
            if (c == *s) return;
        }
        std::string list;
        for (const std::string& c : d.choices)
            list += (list.empty() ? "" : ", ") + c;
        invalid(k + " must be one of " + list + ", got '" + *s + "'");
    }
    case ParamType::Path:
    case ParamType::Text: {
        const std::string* s = std::get_if<std::string>(&value);
        if (!s) invalid(k + " expects text");
        if (d.checkText && !s->empty()) d.checkText(*s);
        return;
    }
    }
}

ParamValue normalizedValue(const ParamDecl& d, const ParamValue& value) {
    validateValue(d, value);
    if (d.type == ParamType::Double) {
        if (const int* i = std::get_if<int>(&value)) return static_cast<double>(*i);
    }
    return value;
}

ParamValue parseParamText(const ParamDecl& d, const std::string& text, const std::string& name) {
    ParamValue v;
    if (d.type == ParamType::Double || d.type == ParamType::Int) {
        const char* b = text.data();
        const char* e = b + text.size();
        if (d.type == ParamType::Int) {
            int i = 0;
            auto [ptr, ec] = std::from_chars(b, e, i);
            if (ec != std::errc() || ptr != e || text.empty())
                invalid(name + " expects an integer, got '" + text + "'");
            v = i;
        } else {
            double x = 0.0;
            auto [ptr, ec] = std::from_chars(b, e, x);
            if (ec != std::errc() || ptr != e || text.empty() || !std::isfinite(x))
                invalid(name + " expects a number, got '" + text + "'");
            v = x;
        }
    } else if (d.type == ParamType::Bool) {
        if (text == "true" || text == "1" || text == "on") {
            v = true;
        } else if (text == "false" || text == "0" || text == "off") {
            v = false;
        } else {
            invalid(name + " expects true or false, got '" + text + "'");
        }
    } else {
        v = text;
    }
    try {
        return normalizedValue(d, v);
    } catch (const Error& e) {
        // Name the parameter as the user wrote it (the flag), not by its key.
        std::string msg = e.problem();
        if (msg.rfind(d.key, 0) == 0) msg = name + msg.substr(d.key.size());
        invalid(msg);
    }
}

std::string formatParamValue(const ParamValue& value) {
    if (const bool* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
    if (const int* i = std::get_if<int>(&value)) return std::to_string(*i);
    if (const double* d = std::get_if<double>(&value)) return formatNumber(*d);
    return std::get<std::string>(value);
}

namespace {

const ParamValue& valueOrDefault(const ParamValues& values, const std::string& key) {
    auto it = values.find(key);
    return it != values.end() ? it->second : parameterDeclaration(key).defaultValue;
}

} // namespace

double paramNumber(const ParamValues& values, const std::string& key) {
    const ParamValue& v = valueOrDefault(values, key);
    if (const int* i = std::get_if<int>(&v)) return *i;
    return std::get<double>(v);
}

int paramInt(const ParamValues& values, const std::string& key) {
    return std::get<int>(valueOrDefault(values, key));
}

bool paramBool(const ParamValues& values, const std::string& key) {
    return std::get<bool>(valueOrDefault(values, key));
}

std::string paramText(const ParamValues& values, const std::string& key) {
    return std::get<std::string>(valueOrDefault(values, key));
}

nlohmann::json paramsToJson(NodeKind kind, const ParamValues& values) {
    nlohmann::json j = nlohmann::json::object();
    for (const ParamDecl* d : parametersOf(kind)) {
        const ParamValue& v = valueOrDefault(values, d->key);
        std::visit([&](const auto& x) { j[d->key] = x; }, v);
    }
    return j;
}

ParamValues paramsFromJson(NodeKind kind, const nlohmann::json& j,
                           const std::filesystem::path& file) {
    auto fail = [&](const std::string& what) -> void {
        if (file.empty()) invalid(what);
        throw Error(ErrorCode::Malformed, file, what);
    };
    ParamValues out = defaultValues(kind);
    if (!j.is_object()) {
        fail(std::string(toString(kind)) + " parameters must be an object");
        return out;
    }
    for (const auto& [key, jv] : j.items()) {
        const ParamDecl* d = findParameter(key);
        if (!d || d->node != kind) {
            fail("unknown " + std::string(toString(kind)) + " parameter '" + key + "'");
            continue;
        }
        ParamValue v;
        if (jv.is_boolean()) {
            v = jv.get<bool>();
        } else if (jv.is_number_integer() && d->type != ParamType::Double) {
            const auto i = jv.get<long long>();
            if (i < -2147483647LL || i > 2147483647LL) fail(key + " is out of range");
            v = static_cast<int>(i);
        } else if (jv.is_number()) {
            v = jv.get<double>();
        } else if (jv.is_string()) {
            v = jv.get<std::string>();
        } else {
            fail(key + " has a value of the wrong type (" + std::string(jv.type_name()) + ")");
            continue;
        }
        try {
            out[key] = normalizedValue(*d, v);
        } catch (const Error& e) {
            fail(e.problem());
        }
    }
    return out;
}

std::filesystem::path defaultProxyCacheDir() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
        return std::filesystem::path(xdg) / "hlod" / "proxies";
    }
    if (const char* home = std::getenv("HOME"); home && *home) {
        return std::filesystem::path(home) / ".cache" / "hlod" / "proxies";
    }
    return {};
}

ImportOptions importOptionsFrom(const ParamValues& v) {
    ImportOptions o;
    o.cadRelativeDeflection = paramNumber(v, "deflection");
    o.cadBrepUnitMetres = paramNumber(v, "brep_unit");
    o.limits.maxTriangles = static_cast<std::uint64_t>(paramInt(v, "max_triangles"));
    o.limits.maxUniqueTriangles = static_cast<std::uint64_t>(paramInt(v, "max_unique_triangles"));
    o.limits.maxInstances = static_cast<std::uint64_t>(paramInt(v, "max_instances"));
    o.limits.maxTexels = static_cast<std::uint64_t>(paramInt(v, "max_texels"));
    return o;
}

ClusterParams clusterParamsFrom(const ParamValues& v) {
    ClusterParams p;
    p.volume = volumeTypeFromString(paramText(v, "volume"));
    p.k = paramNumber(v, "k");
    p.maxChildren = paramInt(v, "max_children");
    p.levelGrowth = paramNumber(v, "level_growth");
    return p;
}

BakeParams bakeParamsFrom(const ParamValues& v) {
    BakeParams p;
    p.method = proxyMethodFromString(paramText(v, "proxy"));
    p.screen.screenSize = paramNumber(v, "screen_size");
    p.screen.pixelError = paramNumber(v, "pixel_error");
    p.screen.fovYDegrees = paramNumber(v, "fov");
    p.screen.viewportHeight = paramNumber(v, "viewport_height");
    p.proxyRatio = paramNumber(v, "proxy_ratio");
    p.atlas.enabled = paramText(v, "proxy_textures") == "on";
    p.threads = paramInt(v, "threads");
    if (paramBool(v, "cache")) {
        const std::string dir = paramText(v, "cache_dir");
        p.cacheDir = dir.empty() ? defaultProxyCacheDir() : std::filesystem::path(dir);
    }
    return p;
}

ParamValues paramsFrom(const ImportOptions& o) {
    ParamValues v = defaultValues(NodeKind::Import);
    v["deflection"] = o.cadRelativeDeflection;
    v["brep_unit"] = o.cadBrepUnitMetres;
    const auto count = [](std::uint64_t n) {
        return static_cast<int>(std::min<std::uint64_t>(n, 2147483647u));
    };
    v["max_triangles"] = count(o.limits.maxTriangles);
    v["max_unique_triangles"] = count(o.limits.maxUniqueTriangles);
    v["max_instances"] = count(o.limits.maxInstances);
    v["max_texels"] = count(o.limits.maxTexels);
    return v;
}

ParamValues paramsFrom(const ClusterParams& p) {
    ParamValues v = defaultValues(NodeKind::Cluster);
    v["volume"] = std::string(toString(p.volume));
    v["k"] = p.k;
    v["max_children"] = p.maxChildren;
    v["level_growth"] = p.levelGrowth;
    return v;
}

ParamValues paramsFrom(const BakeParams& p) {
    ParamValues v = defaultValues(NodeKind::Bake);
    v["proxy"] = std::string(toString(p.method));
    v["screen_size"] = p.screen.screenSize;
    v["pixel_error"] = p.screen.pixelError;
    v["fov"] = p.screen.fovYDegrees;
    v["viewport_height"] = p.screen.viewportHeight;
    v["proxy_ratio"] = p.proxyRatio;
    v["proxy_textures"] = std::string(p.atlas.enabled ? "on" : "off");
    v["threads"] = p.threads;
    v["cache"] = !p.cacheDir.empty();
    v["cache_dir"] = p.cacheDir.string();
    return v;
}

} // namespace hlod
