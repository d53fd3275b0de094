// Per-face progress and cancellation of CAD tessellation (pipeline/io/CadProgress.h, issue 22),
// in process (importCad) and through the isolated reader every application path uses
// (importScene), on generated BREP files and the AS1 STEP assembly.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <vector>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Pnt.hxx>

#include "pipeline/io/Import.h"
#include "tests/pipeline/TestUtil.h"
#include "tests/pipeline/io/DenseBsplineBrep.h"

namespace hlod {
namespace {

namespace fs = std::filesystem;

// Three separate boxes in one BREP compound: 18 distinct faces.
fs::path writeThreeBoxes(const fs::path& file) {
    TopoDS_Compound all;
    BRep_Builder builder;
    builder.MakeCompound(all);
    for (int i = 0; i < 3; ++i)
        builder.Add(all, BRepPrimAPI_MakeBox(gp_Pnt(3.0 * i, 0, 0), 1.0, 1.0, 1.0).Shape());
    BRepTools::Write(all, file.string().c_str());
    return file;
}

struct Recorder {
    std::mutex mutex;
    std::vector<ProgressInfo> reports;
    Progress progress() {
        Progress p;
        p.report = [this](const ProgressInfo& info) {
            const std::lock_guard lock(mutex);
            reports.push_back(info);
        };
        return p;
    }
    std::vector<ProgressInfo> stage(const std::string& name) {
        std::vector<ProgressInfo> out;
        for (const ProgressInfo& r : reports) {
            if (r.stage == name) out.push_back(r);
        }
        return out;
    }
};

// Reports of one stage never go backwards, keep one total, and end at it.
void expectMonotonicToTotal(const std::vector<ProgressInfo>& r, std::uint64_t total) {
    ASSERT_FALSE(r.empty());
    for (std::size_t i = 0; i < r.size(); ++i) {
        EXPECT_EQ(r[i].total, total) << i;
        EXPECT_LE(r[i].done, total) << i;
        if (i > 0) EXPECT_GE(r[i].done, r[i - 1].done) << i;
    }
    EXPECT_EQ(r.front().done, 0u);
    EXPECT_EQ(r.back().done, total);
}

TEST(CadProgress, EveryFaceOfABrepIsReportedInProcess) {
    test::TempDir dir;
    const fs::path file = writeThreeBoxes(dir / "boxes.brep");
    Recorder rec;
    const Scene s = importCad(file, {}, rec.progress());
    EXPECT_EQ(s.stats().triangles, 36u); // 3 boxes x 6 faces x 2 triangles
    const auto faces = rec.stage("tessellate");
    expectMonotonicToTotal(faces, 18);
    EXPECT_EQ(faces.back().detail, "boxes.brep: face 18 of 18");
}

TEST(CadProgress, StepAssemblyFacesArriveThroughTheIsolatedReader) {
    // AS1: its distinct parts' faces, each part meshed once however often it is placed. The
    // total is what the reports must agree on from first to last; the file has 5 distinct
    // meshed parts (hlod info: 5 unique meshes), so more faces than parts.
    const fs::path file = test::dataDir() / "scenes/as1-assembly/as1-oc-214.stp";
    Recorder rec;
    const Scene s = importScene({file}, {}, rec.progress());
    EXPECT_EQ(s.meshes.size(), 5u);
    const auto faces = rec.stage("tessellate");
    ASSERT_FALSE(faces.empty());
    const std::uint64_t total = faces.front().total;
    EXPECT_GT(total, 5u);
    expectMonotonicToTotal(faces, total);
    // Before tessellation, OCCT's transfer to shapes reports its position in per mille.
    expectMonotonicToTotal(rec.stage("transfer"), 1000);
    EXPECT_EQ(rec.stage("transfer").back().detail, "as1-oc-214.stp: converting to shapes");
    // The file-level stage still brackets the import.
    const auto files = rec.stage("import");
    ASSERT_FALSE(files.empty());
    EXPECT_EQ(files.back().done, 1u);
}

TEST(CadProgress, DenseFaceIsOneFaceOfOne) {
    test::TempDir dir;
    const fs::path file = dir / "terrain.brep";
    test::writeDenseBsplineBrep(file, 64, 1000.0);
    Recorder rec;
    (void)importScene({file}, {}, rec.progress());
    expectMonotonicToTotal(rec.stage("tessellate"), 1);
}

TEST(CadProgress, CancellingDuringTessellationStopsWithCancelledNamingTheFile) {
    test::TempDir dir;
    const fs::path file = dir / "terrain.brep";
    test::writeDenseBsplineBrep(file, 256, 10000.0); // ~1.5 s of meshing within its budget
    for (const bool isolated : {false, true}) {
        SCOPED_TRACE(isolated ? "isolated" : "in process");
        std::atomic<bool> cancel{false};
        Progress p;
        p.cancel = &cancel;
        std::uint64_t lastDone = 0;
        p.report = [&](const ProgressInfo& info) {
            if (info.stage == "tessellate") {
                lastDone = info.done;
                cancel = true; // the first face report: tessellation has started
            }
        };
        try {
            if (isolated)
                (void)importScene({file}, {}, p);
            else
                (void)importCad(file, {}, p);
            FAIL() << "not cancelled";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ErrorCode::Cancelled);
            EXPECT_EQ(std::string(e.what()), file.string() + ": import cancelled");
        }
        EXPECT_EQ(lastDone, 0u); // the face never finished
    }
}

} // namespace
} // namespace hlod
