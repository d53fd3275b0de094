// `.hlodproj` project files: a Document as versioned JSON, plus autosave and recovery helpers
// for the editor (issue #7).
//
// Format (version 1):
//   {"format": "hlod-project", "version": 1, "generator": "HLOD Studio X.Y.Z",
//    "graph": PipelineGraph JSON (parameters of every node, hand edits of Cluster nodes,
//             scene paths of Import nodes stored relative to the project file's folder),
//    "view": the editor's view state}
// Paths: on save, a path (the scene files of Import nodes, and every Path parameter: an Export's
// output folder, a Bake's cache folder) is written relative to the project's folder (with '/'
// separators) when it can be expressed so, otherwise absolute; on open, relative paths are
// resolved against the project's folder. So a project and its packages move together, and
// `hlod build PROJECT` writes each Export's package where the editor would, from any folder.
// Saving is atomic (a temporary file in the same folder, then rename): a failed save leaves the
// previous file intact. Opening throws hlod::Error naming the file and the problem:
// FileNotFound (no project, or a scene file it names is missing: both paths in the message),
// Malformed (bad JSON, wrong format, missing or wrong keys: the key is named), and
// Malformed "unsupported project version N (this build reads 1)" for other versions.
// Autosave: writeAutosave() writes `<project>.autosave` (same format, paths relative to the
// project's folder) atomically; autosaveIsNewer() tells the editor on open that a recovery is
// possible (the autosave exists and is newer than the project, or the project was never saved);
// openAutosave() reads it as if it were the project; removeAutosave() after a save or a
// declined recovery.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "pipeline/doc/Document.h"

namespace hlod {

inline constexpr int kProjectVersion = 1;
inline constexpr const char* kProjectExtension = ".hlodproj";

nlohmann::json projectJson(const Document& doc, const std::filesystem::path& projectFile);
// `projectFile` names the file in errors and anchors relative paths; checks the scene files.
Document projectFromJson(const nlohmann::json& j, const std::filesystem::path& projectFile);

void saveProject(const Document& doc, const std::filesystem::path& file);
Document openProject(const std::filesystem::path& file);

std::filesystem::path autosavePath(const std::filesystem::path& projectFile);
void writeAutosave(const Document& doc, const std::filesystem::path& projectFile);
bool autosaveIsNewer(const std::filesystem::path& projectFile);
Document openAutosave(const std::filesystem::path& projectFile);
void removeAutosave(const std::filesystem::path& projectFile);

} // namespace hlod
