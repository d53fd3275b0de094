// The Export stage of the pipeline graph: statistics of the build (thesis tables: Original,
// the DLOD chain baseline, the HLOD) and the engine-ready package (Package.h). Shared by the
// CLI (`hlod build`) and the editor's export, so both write the same hlod.json.
//
// hlod.json "parameters.cluster" holds volume, k, max_children and, when the tree carries hand
// edits, "hand_edits" (HandEdits.h JSON), so a package says how it was made.
// Failure: Error(InvalidArgument) without an output folder; whatever writePackage throws
// (atomic: no half package is left behind); Error(Cancelled) on cancel.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/export/DiskUsage.h"
#include "pipeline/export/Package.h"
#include "pipeline/graph/HandEdits.h"
#include "pipeline/proxy/BakeStats.h"
#include "pipeline/proxy/BuildOutput.h"

namespace hlod {

struct ExportOptions {
    std::filesystem::path output;
    bool dlod = true;               // compute the DLOD chain row (costs a few seconds)
    std::optional<GeoLocation> geo; // root transform on the globe; local frame otherwise
    GlbCompression compression = GlbCompression::Meshopt;
};

struct ExportResult {
    std::filesystem::path output;
    BuildInfo info; // inputs, parameters, statistics rows, proxy share
    PackageSummary written;
    DiskFootprint source; // the scene files and what they reference, on disk
    double dlodSeconds = 0.0;
    double writeSeconds = 0.0;
};

// What a build was made of, as the Export stage needs it.
struct BuildInputs {
    const Scene& scene;
    const ClusterTree& tree;
    const BakeResult& bake;
    const ClusterParams& cluster;
    const HandEdits& edits;
    const BakeParams& bakeParams;
    const std::vector<std::string>& inputs; // source scene paths as given
    // When set, the statistics take mesh and proxy sizes from here (the scene's meshes and the
    // proxies may be absent: a distributed bake's final step, BakePlan.h).
    const SizeTable* sizes = nullptr;
};

// The statistics and parameters of a build (without writing anything).
BuildInfo makeBuildInfo(const BuildInputs& in, bool dlod, double* dlodSeconds = nullptr);

ExportResult exportPackage(const BuildInputs& in, const ExportOptions& options,
                           const Progress& progress = {});

// The package options of a build: its inputs, geo and compression, and the statistics summary
// hlod.json carries (what this run did, baked or found in the cache, left out).
PackageOptions packageOptionsFor(const BuildInputs& in, const BuildInfo& info,
                                 const ExportOptions& options);

} // namespace hlod
