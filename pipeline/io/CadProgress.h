// Per-face progress and cancellation of a CAD file's tessellation (issue 22): a dense surface
// can keep BRepMesh busy for seconds, so the user sees which face of how many is being meshed
// and can stop it.
//
// Counting: `total` is the number of distinct faces of the parts the file tessellates (a part
// placed many times is meshed once). Faces of one BRepMesh pass come from OCCT's own per-face
// progress scope ("Face Discret", OCCT 7.6; the pass's overall position where that scope is
// not found), so a report is made when a face is finished. Reports never go backwards.
// Cancellation: OCCT asks UserBreak() between its steps (within a face too, at a coarser pace:
// ~5 s on a 256 x 256 B-spline face), after which the caller throws Error(Cancelled). In the
// isolated reader the parent kills the child instead (IsolatedImport.h), which is immediate.
// Stage: "tessellate", detail "<file name>: face N of M".
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include <Message_ProgressIndicator.hxx>
#include <TopoDS_Shape.hxx>

#include "pipeline/core/Progress.h"

namespace hlod::cad {

class FaceProgress {
public:
    FaceProgress(const Progress& progress, std::filesystem::path file, std::uint64_t totalFaces);

    // A shape of `faces` faces starts meshing; its faces count from where the last one ended.
    void beginPart(std::uint64_t faces);
    // At least `done` of the current shape's faces are meshed.
    void partDone(std::uint64_t done);
    void endPart();

    bool cancelled() const { return progress_.cancelled(); }
    // Throws Error(Cancelled) naming the file when the cancel flag is raised.
    void throwIfCancelled() const;

    // An OCCT progress indicator whose UserBreak() is the cancel flag; with `reportFaces` its
    // face counter feeds partDone (for a whole-shape pass, not a single face's).
    Handle(Message_ProgressIndicator) indicator(bool reportFaces);

    std::uint64_t done() const { return base_ + partDone_; }
    std::uint64_t total() const { return total_; }

private:
    void emit();

    const Progress& progress_;
    std::filesystem::path file_;
    std::uint64_t total_ = 0;
    std::uint64_t base_ = 0; // faces of finished shapes
    std::uint64_t partFaces_ = 0;
    std::uint64_t partDone_ = 0;
};

// Progress of the STEP/IGES transfer to shapes (OCCT's reader has no face count to give
// there): stage "transfer", done/total = OCCT's position in per mille, detail
// "<file name>: converting to shapes"; UserBreak() is the cancel flag. Reports never go
// backwards; the last is 1000 of 1000 once finish() is called.
class StepProgress {
public:
    StepProgress(const Progress& progress, std::filesystem::path file);
    Handle(Message_ProgressIndicator) indicator();
    // Position 0..1 reached (clamped, never backwards).
    void reached(double position);
    void finish() { reached(1.0); }
    bool cancelled() const { return progress_.cancelled(); }
    // Throws Error(Cancelled) naming the file when the cancel flag is raised.
    void throwIfCancelled() const;

private:
    const Progress& progress_;
    std::filesystem::path file_;
    std::uint64_t done_ = 0;
    bool started_ = false;
};

// Distinct faces of `shape` (TopoDS_Shape::IsSame: a face shared by two shells counts once).
std::uint64_t faceCount(const TopoDS_Shape& shape);

} // namespace hlod::cad
