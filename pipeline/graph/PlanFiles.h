// The plan folder's file helpers (BakePlan.h), shared by the plan, the shards and the final
// step (BakePlan.cpp, LeanFinal.cpp). Internal to pipeline/graph.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace hlod::plan {

inline constexpr int kFormat = 3; // 2: keys.bin, measured costs; 3: the lean final step
inline constexpr const char* kPlanFile = "plan.json";
inline constexpr const char* kTreeFile = "tree.bin";
inline constexpr const char* kKeysFile = "keys.bin";
inline constexpr const char* kRunPlan = " (run hlod plan SCENE --shards N --cache DIR first)";

inline std::string sliceName(int index) { return "shard-" + std::to_string(index) + ".scene"; }
inline std::string markerName(int index) { return "shard-" + std::to_string(index) + ".done"; }

// Bytes followed by their checksum (written atomically), so a damaged or half-copied file is
// never used; readChecked throws Malformed naming the file for a bad checksum, FileNotFound
// ("run hlod plan") for a missing one.
void writeChecked(const std::filesystem::path& file, std::string bytes);
std::string readChecked(const std::filesystem::path& file);

// Whether plan folder `folder` holds shard `index`'s marker (shard-I.done) for plan `planId`.
bool shardFinished(const std::filesystem::path& folder, const std::string& planId, int index);

// CACHE/plan/plan.json, checked for its format and shape.
nlohmann::json readPlanJson(const std::filesystem::path& cacheDir);

} // namespace hlod::plan
