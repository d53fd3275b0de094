// `.hlodproj` project files, autosave and recovery (contract in ProjectFile.h).
#include "pipeline/doc/ProjectFile.h"

#include <fstream>
#include <sstream>

#include "pipeline/core/AtomicFile.h"
#include "pipeline/core/Error.h"

namespace fs = std::filesystem;

namespace hlod {

namespace {

fs::path projectFolder(const fs::path& projectFile) {
    std::error_code ec;
    const fs::path abs = fs::absolute(projectFile, ec);
    return (ec ? projectFile : abs).parent_path();
}

std::string storedPath(const fs::path& p, const fs::path& folder) {
    std::error_code ec;
    const fs::path abs = fs::absolute(p, ec).lexically_normal();
    const fs::path rel = abs.lexically_relative(folder.lexically_normal());
    if (!ec && !rel.empty() && p.root_name() == folder.root_name()) return rel.generic_string();
    return abs.generic_string();
}

// Applies `f` to every path of a graph JSON: the "sources" of Import nodes and the non-empty
// values of Path parameters (an Export's output folder, a Bake's cache folder).
template <typename F> void forEachPath(nlohmann::json& graph, F f) {
    if (!graph.is_object() || !graph.contains("nodes") || !graph["nodes"].is_array()) return;
    for (auto& n : graph["nodes"]) {
        if (!n.is_object()) continue;
        if (n.contains("sources") && n["sources"].is_array()) {
            for (auto& s : n["sources"]) {
                if (s.is_string()) s = f(s.get<std::string>());
            }
        }
        if (!n.contains("params") || !n["params"].is_object()) continue;
        nlohmann::json& params = n["params"];
        for (auto it = params.begin(); it != params.end(); ++it) {
            const ParamDecl* d = findParameter(it.key());
            nlohmann::json& value = it.value();
            if (!d || d->type != ParamType::Path || !value.is_string()) continue;
            const std::string path = value.get<std::string>();
            if (!path.empty()) value = f(path);
        }
    }
}

std::string readText(const fs::path& file) {
    std::error_code ec;
    if (!fs::exists(file, ec)) throw Error(ErrorCode::FileNotFound, file, "no such file");
    if (fs::is_directory(file, ec))
        throw Error(ErrorCode::FileUnreadable, file, "is a folder, not a project file");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(ErrorCode::FileUnreadable, file, "cannot be opened");
    std::ostringstream s;
    s << in.rdbuf();
    if (!in && !in.eof()) throw Error(ErrorCode::FileUnreadable, file, "cannot be read");
    return s.str();
}

Document readProject(const fs::path& file, const fs::path& anchor) {
    const std::string text = readText(file);
    if (text.empty()) throw Error(ErrorCode::EmptyFile, file, "empty project file");
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw Error(ErrorCode::Malformed, file,
                    "not valid JSON (byte " + std::to_string(e.byte) + ")");
    } catch (const nlohmann::json::exception& e) {
        // A number out of double's range ("-1e3082") is out_of_range, not parse_error (found
        // by fuzz_project).
        throw Error(ErrorCode::Malformed, file, std::string("not valid JSON: ") + e.what());
    }
    try {
        return projectFromJson(j, anchor.empty() ? file : anchor);
    } catch (const Error& e) {
        // Errors from the graph's and parameters' own readers may name no file.
        if (!e.file().empty()) throw;
        throw Error(e.code(), file, e.problem());
    } catch (const nlohmann::json::exception& e) {
        throw Error(ErrorCode::Malformed, file, std::string("bad project: ") + e.what());
    }
}

} // namespace

nlohmann::json projectJson(const Document& doc, const fs::path& projectFile) {
    const fs::path folder = projectFolder(projectFile);
    nlohmann::json graph = doc.graph().toJson();
    forEachPath(graph, [&](const std::string& s) { return storedPath(s, folder); });
    return {{"format", "hlod-project"},
            {"version", kProjectVersion},
            {"generator", std::string("HLOD Studio ") + HLOD_VERSION},
            {"graph", std::move(graph)},
            {"view", doc.viewState()}};
}

Document projectFromJson(const nlohmann::json& j, const fs::path& projectFile) {
    auto bad = [&](const std::string& what) {
        throw Error(ErrorCode::Malformed, projectFile, what);
    };
    if (!j.is_object()) bad("a project file must hold a JSON object");
    if (j.value("format", std::string()) != "hlod-project")
        bad("key 'format' must be \"hlod-project\" (not an HLOD Studio project)");
    if (!j.contains("version") || !j["version"].is_number_integer())
        bad("key 'version' is missing or not an integer");
    if (const int v = j["version"].get<int>(); v != kProjectVersion) {
        bad("unsupported project version " + std::to_string(v) + " (this build reads " +
            std::to_string(kProjectVersion) + ")");
    }
    if (!j.contains("graph")) bad("key 'graph' is missing");
    const fs::path folder = projectFolder(projectFile);
    nlohmann::json graph = j["graph"];
    forEachPath(graph, [&](const std::string& s) {
        const fs::path p(s);
        return (p.is_absolute() ? p : (folder / p)).lexically_normal().string();
    });
    Document doc = Document::fromJson(
        {{"graph", graph}, {"view", j.value("view", nlohmann::json::object())}}, projectFile);
    for (NodeId id : doc.graph().nodeIds()) {
        for (const fs::path& src : doc.graph().node(id).sources) {
            std::error_code ec;
            if (!fs::exists(src, ec)) {
                throw Error(ErrorCode::FileNotFound, projectFile,
                            "scene file " + src.string() + " does not exist");
            }
        }
    }
    return doc;
}

void saveProject(const Document& doc, const fs::path& file) {
    writeFileAtomic(file, projectJson(doc, file).dump(2) + "\n");
}

Document openProject(const fs::path& file) { return readProject(file, {}); }

fs::path autosavePath(const fs::path& projectFile) {
    fs::path p = projectFile;
    p += ".autosave";
    return p;
}

void writeAutosave(const Document& doc, const fs::path& projectFile) {
    writeFileAtomic(autosavePath(projectFile), projectJson(doc, projectFile).dump(2) + "\n");
}

bool autosaveIsNewer(const fs::path& projectFile) {
    std::error_code ec;
    const fs::path a = autosavePath(projectFile);
    if (!fs::exists(a, ec)) return false;
    if (!fs::exists(projectFile, ec)) return true;
    const auto ta = fs::last_write_time(a, ec);
    if (ec) return false;
    const auto tp = fs::last_write_time(projectFile, ec);
    return ec || ta > tp;
}

Document openAutosave(const fs::path& projectFile) {
    const fs::path a = autosavePath(projectFile);
    // Relative paths were written against the project's folder, which is the autosave's too.
    return readProject(a, {});
}

void removeAutosave(const fs::path& projectFile) {
    std::error_code ec;
    fs::remove(autosavePath(projectFile), ec);
}

} // namespace hlod
