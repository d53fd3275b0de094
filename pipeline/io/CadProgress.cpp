// Per-face tessellation progress over OCCT's Message_ProgressIndicator (OCCT 7.6 "Progress
// indication" in the Foundation Classes guide: Show() gets the innermost scope being advanced,
// UserBreak() is polled by the algorithm). See CadProgress.h.
#include "pipeline/io/CadProgress.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <Message_ProgressScope.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include "pipeline/core/Error.h"

namespace hlod::cad {

namespace {

class Indicator : public Message_ProgressIndicator {
public:
    Indicator(FaceProgress& owner, bool reportFaces, std::uint64_t faces)
        : owner_(owner), reportFaces_(reportFaces), faces_(faces) {}

    Standard_Boolean UserBreak() override { return owner_.cancelled(); }

    void Show(const Message_ProgressScope& scope, const Standard_Boolean) override {
        if (!reportFaces_ || faces_ == 0) return;
        // BRepMesh's per-face scope counts the face being meshed: the ones before it are done.
        for (const Message_ProgressScope* s = &scope; s != nullptr; s = s->Parent()) {
            if (s->Name() != nullptr && std::strcmp(s->Name(), "Face Discret") == 0) {
                const double started = std::max(0.0, s->Value());
                owner_.partDone(static_cast<std::uint64_t>(std::max(0.0, started - 1.0)));
                return;
            }
        }
        // Another OCCT version: the pass's position, most of which is face meshing.
        owner_.partDone(static_cast<std::uint64_t>(std::floor(GetPosition() * double(faces_))));
    }

private:
    FaceProgress& owner_;
    bool reportFaces_;
    std::uint64_t faces_;
};

class StepIndicator : public Message_ProgressIndicator {
public:
    explicit StepIndicator(StepProgress& owner) : owner_(owner) {}
    Standard_Boolean UserBreak() override { return owner_.cancelled(); }
    void Show(const Message_ProgressScope&, const Standard_Boolean) override {
        owner_.reached(GetPosition());
    }

private:
    StepProgress& owner_;
};

} // namespace

StepProgress::StepProgress(const Progress& progress, std::filesystem::path file)
    : progress_(progress), file_(std::move(file)) {
    reached(0.0);
}

Handle(Message_ProgressIndicator) StepProgress::indicator() { return new StepIndicator(*this); }

void StepProgress::reached(double position) {
    const auto d = static_cast<std::uint64_t>(std::floor(std::clamp(position, 0.0, 1.0) * 1000.0));
    if (started_ && d <= done_) return;
    started_ = true;
    done_ = d;
    progress_.emit({"transfer", done_, 1000, file_.filename().string() + ": converting to shapes"});
}

void StepProgress::throwIfCancelled() const {
    if (cancelled()) throw Error(ErrorCode::Cancelled, file_, "import cancelled");
}

FaceProgress::FaceProgress(const Progress& progress, std::filesystem::path file,
                           std::uint64_t totalFaces)
    : progress_(progress), file_(std::move(file)), total_(totalFaces) {
    emit();
}

void FaceProgress::beginPart(std::uint64_t faces) {
    partFaces_ = faces;
    partDone_ = 0;
}

void FaceProgress::partDone(std::uint64_t done) {
    done = std::min(done, partFaces_);
    if (done <= partDone_) return;
    partDone_ = done;
    emit();
}

void FaceProgress::endPart() {
    partDone(partFaces_);
    base_ += partFaces_;
    partFaces_ = partDone_ = 0;
}

void FaceProgress::throwIfCancelled() const {
    if (cancelled()) throw Error(ErrorCode::Cancelled, file_, "import cancelled");
}

Handle(Message_ProgressIndicator) FaceProgress::indicator(bool reportFaces) {
    return new Indicator(*this, reportFaces, partFaces_);
}

void FaceProgress::emit() {
    const std::uint64_t d = std::min(done(), total_);
    progress_.emit({"tessellate", d, total_,
                    file_.filename().string() + ": face " +
                        std::to_string(std::min(d + 1, total_)) + " of " + std::to_string(total_)});
}

std::uint64_t faceCount(const TopoDS_Shape& shape) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    return static_cast<std::uint64_t>(faces.Extent());
}

} // namespace hlod::cad
