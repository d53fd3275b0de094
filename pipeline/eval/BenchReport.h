// What `hlod bench` writes: per-frame records, per-configuration summaries and the files made
// from them (frames.csv, summary.json, tables.md). Pure data in, text out; the rendering that
// produces the numbers lives in app/cli/bench/.
//
// Files are written to "<name>.tmp" and renamed, so a reader never sees half a file;
// `hlod bench` writes summary.json last, so its presence means the run finished.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/proxy/BakeStats.h"

namespace hlod {

struct FrameRecord {
    int frame = 0;
    double timeSeconds = 0.0;
    std::string config; // "Original", "DLOD chain", "HLOD, sphere", ...
    std::uint64_t drawCalls = 0;
    std::uint64_t triangles = 0;
    std::uint64_t nodesVisited = 0; // bounds tested by the selection (instances for Original/DLOD)
    double frameMs = 0.0;           // render wall time, selection excluded
    double selectionUs = 0.0;       // LOD selection (and culling) time
    double psnrDb = 0.0;            // against the Original frame (ImageError.h: capped)
    double diffShare = 0.0;         // share of pixels differing by more than the threshold
    double flip = 0.0;              // mean FLIP against the Original frame (Flip.h), [0, 1]
    bool lodSwitch = false;         // the selection switched a level since the previous frame
    double pop = 0.0;               // Popping.h, at a switch (0 otherwise), [0, 1]
};

struct ConfigSummary {
    std::string config;
    int frames = 0;
    double drawCallsMean = 0.0;
    std::uint64_t drawCallsMax = 0;
    double trianglesMean = 0.0;
    double frameMsMean = 0.0;
    double frameMsP95 = 0.0; // nearest-rank 95th percentile
    double psnrMean = 0.0;
    double psnrMin = 0.0;
    double diffShareMean = 0.0;
    double selectionUsMean = 0.0;
    double flipMean = 0.0;
    double flipMax = 0.0;
    int switches = 0;     // frames with a level-of-detail switch
    double popMean = 0.0; // over the frames with a switch (0 without any)
    double popMax = 0.0;
};

// One summary per configuration, in order of first appearance in `records`.
std::vector<ConfigSummary> summarizeFrames(const std::vector<FrameRecord>& records);

// Nearest-rank percentile (p in [0, 100]) of `values`; 0 for none.
double percentile(std::vector<double> values, double p);

// Header: frame,time_s,config,draw_calls,triangles,nodes_visited,frame_ms,psnr_db,diff_pixels,
// flip,lod_switch,pop (diff_pixels is the share in [0, 1]; flip and pop in [0, 1]; lod_switch 0
// or 1, pop 0 where it is 0); the config is quoted (names contain commas).
std::string framesCsv(const std::vector<FrameRecord>& records);
inline constexpr const char* kFramesCsvHeader =
    "frame,time_s,config,draw_calls,triangles,nodes_visited,frame_ms,psnr_db,diff_pixels,flip,"
    "lod_switch,pop";

// {"configs": [{"config": ..., "draw_calls": {"mean", "max"}, "triangles": {"mean"},
//   "frame_ms": {"mean", "p95"}, "psnr_db": {"mean", "min"}, "diff_pixels": {"mean"},
//   "selection_us": {"mean"}, "flip": {"mean", "max"}, "pop": {"switches", "mean", "max"},
//   "frames"}], ...`extra` merged at the top level}
nlohmann::json summaryJson(const std::vector<ConfigSummary>& summaries,
                           const nlohmann::json& extra = nlohmann::json::object());

// Thesis tables 6.2-6.6 style (Version | Triangles | Vertices | Meshes | Space (MB)) followed
// by the per-configuration run summary.
std::string tablesMarkdown(const std::string& title, const std::vector<GeometryStats>& stats,
                           const std::vector<ConfigSummary>& summaries);

// Writes `text` to "<path>.tmp" then renames it over `path`; Error(Io) naming the file.
void writeTextFileAtomic(const std::filesystem::path& path, const std::string& text);

} // namespace hlod
