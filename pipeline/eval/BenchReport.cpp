#include "pipeline/eval/BenchReport.h"

#include "pipeline/core/AtomicFile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <system_error>

#include "pipeline/core/Error.h"

namespace hlod {

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const double rank = std::ceil(std::clamp(p, 0.0, 100.0) / 100.0 * values.size());
    const std::size_t i = static_cast<std::size_t>(std::max(rank, 1.0)) - 1;
    return values[std::min(i, values.size() - 1)];
}

std::vector<ConfigSummary> summarizeFrames(const std::vector<FrameRecord>& records) {
    std::vector<std::string> order;
    std::map<std::string, std::vector<const FrameRecord*>> by;
    for (const FrameRecord& r : records) {
        auto& v = by[r.config];
        if (v.empty()) order.push_back(r.config);
        v.push_back(&r);
    }
    std::vector<ConfigSummary> out;
    for (const std::string& name : order) {
        const auto& v = by[name];
        ConfigSummary s;
        s.config = name;
        s.frames = static_cast<int>(v.size());
        s.psnrMin = v.front()->psnrDb;
        std::vector<double> ms;
        for (const FrameRecord* r : v) {
            s.drawCallsMean += static_cast<double>(r->drawCalls);
            s.drawCallsMax = std::max(s.drawCallsMax, r->drawCalls);
            s.trianglesMean += static_cast<double>(r->triangles);
            s.frameMsMean += r->frameMs;
            s.psnrMean += r->psnrDb;
            s.psnrMin = std::min(s.psnrMin, r->psnrDb);
            s.diffShareMean += r->diffShare;
            s.selectionUsMean += r->selectionUs;
            s.flipMean += r->flip;
            s.flipMax = std::max(s.flipMax, r->flip);
            if (r->lodSwitch) {
                ++s.switches;
                s.popMean += r->pop;
                s.popMax = std::max(s.popMax, r->pop);
            }
            ms.push_back(r->frameMs);
        }
        const double n = static_cast<double>(v.size());
        s.drawCallsMean /= n;
        s.trianglesMean /= n;
        s.frameMsMean /= n;
        s.psnrMean /= n;
        s.diffShareMean /= n;
        s.selectionUsMean /= n;
        s.flipMean /= n;
        if (s.switches > 0) s.popMean /= s.switches;
        s.frameMsP95 = percentile(ms, 95.0);
        out.push_back(s);
    }
    return out;
}

std::string framesCsv(const std::vector<FrameRecord>& records) {
    std::string out = std::string(kFramesCsvHeader) + "\n";
    char buf[512];
    for (const FrameRecord& r : records) {
        std::string name;
        for (char c : r.config) {
            if (c == '"') name += '"';
            name += c;
        }
        std::snprintf(buf, sizeof(buf),
                      "%d,%.4f,\"%s\",%llu,%llu,%llu,%.4f,%.3f,%.6f,%.6f,%d,%.6f\n", r.frame,
                      r.timeSeconds, name.c_str(), static_cast<unsigned long long>(r.drawCalls),
                      static_cast<unsigned long long>(r.triangles),
                      static_cast<unsigned long long>(r.nodesVisited), r.frameMs, r.psnrDb,
                      r.diffShare, r.flip, r.lodSwitch ? 1 : 0, r.pop);
        out += buf;
    }
    return out;
}

nlohmann::json summaryJson(const std::vector<ConfigSummary>& summaries,
                           const nlohmann::json& extra) {
    nlohmann::json j = extra.is_object() ? extra : nlohmann::json::object();
    j["configs"] = nlohmann::json::array();
    for (const ConfigSummary& s : summaries) {
        j["configs"].push_back(
            {{"config", s.config},
             {"frames", s.frames},
             {"draw_calls", {{"mean", s.drawCallsMean}, {"max", s.drawCallsMax}}},
             {"triangles", {{"mean", s.trianglesMean}}},
             {"frame_ms", {{"mean", s.frameMsMean}, {"p95", s.frameMsP95}}},
             {"psnr_db", {{"mean", s.psnrMean}, {"min", s.psnrMin}}},
             {"diff_pixels", {{"mean", s.diffShareMean}}},
             {"selection_us", {{"mean", s.selectionUsMean}}},
             {"flip", {{"mean", s.flipMean}, {"max", s.flipMax}}},
             {"pop", {{"switches", s.switches}, {"mean", s.popMean}, {"max", s.popMax}}}});
    }
    return j;
}

namespace {

std::string count(double v) {
    char buf[64];
    if (v >= 1e6)
        std::snprintf(buf, sizeof(buf), "%.2fM", v / 1e6);
    else if (v >= 1e4)
        std::snprintf(buf, sizeof(buf), "%.0fK", v / 1e3);
    else if (v >= 1e3)
        std::snprintf(buf, sizeof(buf), "%.1fK", v / 1e3);
    else
        std::snprintf(buf, sizeof(buf), "%.0f", v);
    return buf;
}

} // namespace

std::string tablesMarkdown(const std::string& title, const std::vector<GeometryStats>& stats,
                           const std::vector<ConfigSummary>& summaries) {
    std::string out = "# " + title + "\n\n";
    char buf[512];
    if (!stats.empty()) {
        out += "Statistics in the shape of the thesis' tables 6.2-6.6 (counts per mesh instance, "
               "HLOD rows = original meshes + proxies, space = geometry bytes):\n\n"
               "| Version | Triangles | Vertices | Meshes | Space (MB) |\n"
               "|---|---:|---:|---:|---:|\n";
        for (const GeometryStats& s : stats) {
            std::snprintf(buf, sizeof(buf), "| %s | %s | %s | %zu | %.2f |\n", s.version.c_str(),
                          count(static_cast<double>(s.triangles)).c_str(),
                          count(static_cast<double>(s.vertices)).c_str(), s.meshes,
                          static_cast<double>(s.bytes) / 1e6);
            out += buf;
        }
        out += "\n";
    }
    if (!summaries.empty()) {
        out += "Along the camera path (per frame; PSNR and FLIP against the Original frame, PSNR "
               "capped at 100 dB; pop: FLIP of what a level switch changes beyond the Original's "
               "own change, over the frames with a switch):\n\n"
               "| Version | Draw calls (mean) | Draw calls (max) | Triangles (mean) | "
               "Frame ms (mean) | Frame ms (p95) | PSNR dB (mean) | PSNR dB (min) | "
               "Pixels differing (mean) | Selection us (mean) | FLIP (mean) | FLIP (max) | "
               "Switches | Pop (mean) | Pop (max) |\n"
               "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        for (const ConfigSummary& s : summaries) {
            std::snprintf(buf, sizeof(buf),
                          "| %s | %.1f | %llu | %s | %.2f | %.2f | %.1f | %.1f | %.2f%% | %.1f | "
                          "%.4f | %.4f | %d | %.4f | %.4f |\n",
                          s.config.c_str(), s.drawCallsMean,
                          static_cast<unsigned long long>(s.drawCallsMax),
                          count(s.trianglesMean).c_str(), s.frameMsMean, s.frameMsP95, s.psnrMean,
                          s.psnrMin, s.diffShareMean * 100.0, s.selectionUsMean, s.flipMean,
                          s.flipMax, s.switches, s.popMean, s.popMax);
            out += buf;
        }
    }
    return out;
}

void writeTextFileAtomic(const std::filesystem::path& path, const std::string& text) {
    writeFileAtomic(path, text);
}

} // namespace hlod
