// CAD import through OpenCASCADE 7.6: STEP and IGES via the XCAF readers (assembly, names,
// colours; CadXcaf.cpp builds the scene), BREP via BRepTools::Read (bare shapes).
//
// Based on the OCCT 7.6 data exchange guides (STEP/IGES translators with XDE,
// STEPCAFControl_Reader / IGESCAFControl_Reader, BRepTools) and the meshing guide.
//
// Units: the XCAF readers convert every entity to the document's length unit (millimetres
// unless "xstep.cascade.unit" says otherwise); XCAFDoc_DocumentTool::GetLengthUnit tells that
// unit in metres and we scale by it. BREP has no unit field: options.cadBrepUnitMetres.
// Errors: every OCCT failure (Standard_Failure) and std::exception becomes hlod::Error; a
// fault signal inside OCCT (it dereferences null handles on some corrupt STEP files) becomes
// an error through CadCrashGuard, and BREP is parsed from a stream that throws on a failed
// read (OCCT can otherwise loop forever at the end of corrupt data).
// OCCT's own console messages are switched off: the pipeline never prints.
#include <cctype>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <streambuf>
#include <string>
#include <utility>
#include <vector>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shape.hxx>
#include <UnitsMethods.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>

#include "pipeline/core/Error.h"
#include "pipeline/core/OnDemand.h"
#include "pipeline/io/CadCrashGuard.h"
#include "pipeline/io/CadProgress.h"
#include "pipeline/io/CadTessellation.h"
#include "pipeline/io/CadXcaf.h"
#include "pipeline/io/Import.h"
#include "pipeline/io/ImportModules.h"
#include "pipeline/io/StepInstancing.h"

namespace hlod {

namespace {

namespace fs = std::filesystem;

enum class CadKind { Step, Iges, Brep };

CadKind kindOf(const fs::path& file) {
    std::string ext = file.extension().string();
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".iges" || ext == ".igs") return CadKind::Iges;
    if (ext == ".brep" || ext == ".brp") return CadKind::Brep;
    return CadKind::Step;
}

// The XSControl readers keep global state (static parameters, the work session, the XCAF
// application's document list) and std::cout is swapped while they run (QuietStdout), so
// reads from several threads take turns here.
std::mutex& readerMutex() {
    static std::mutex m;
    return m;
}

// OCCT reports through Message::DefaultMessenger(), whose default printer writes to stdout
// (e.g. IGES: "Total number of loaded entities"). The pipeline never prints.
void silenceOcct() {
    static std::once_flag once;
    std::call_once(once, [] {
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    });
}

// Some OCCT 7.6 parsers write straight to std::cout (BRepTools::Read: "Not a surface table",
// "File was not written with this version of the topology"), bypassing the messenger. While
// a reader runs (under readerMutex), std::cout writes into a buffer that drops everything.
class QuietStdout {
public:
    QuietStdout() : previous_(std::cout.rdbuf(&sink_)) {}
    ~QuietStdout() { std::cout.rdbuf(previous_); }
    QuietStdout(const QuietStdout&) = delete;
    QuietStdout& operator=(const QuietStdout&) = delete;

private:
    struct Sink : std::streambuf {
        int overflow(int c) override { return traits_type::not_eof(c); }
        std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
    };
    Sink sink_;
    std::streambuf* previous_;
};

std::string statusText(IFSelect_ReturnStatus status) {
    switch (status) {
    case IFSelect_RetVoid:
        return "nothing to read (not a STEP/IGES file?)";
    case IFSelect_RetDone:
        return "done";
    case IFSelect_RetError:
        return "syntax error in the file";
    case IFSelect_RetFail:
        return "the file could not be read";
    case IFSelect_RetStop:
        return "reading was stopped";
    }
    return "unknown reader status";
}

// An XCAF document that is closed (and released by the application) on scope exit.
class XcafDocument {
public:
    XcafDocument() {
        const std::lock_guard lock(readerMutex());
        app_ = XCAFApp_Application::GetApplication();
        app_->NewDocument("MDTV-XCAF", doc_);
    }
    ~XcafDocument() {
        const std::lock_guard lock(readerMutex());
        if (!doc_.IsNull() && doc_->IsOpened()) app_->Close(doc_);
    }
    XcafDocument(const XcafDocument&) = delete;
    XcafDocument& operator=(const XcafDocument&) = delete;
    Handle(TDocStd_Document) & get() { return doc_; }

private:
    Handle(XCAFApp_Application) app_;
    Handle(TDocStd_Document) doc_;
};

template <typename Reader> void configure(Reader& reader) {
    reader.SetColorMode(true);
    reader.SetNameMode(true);
    reader.SetLayerMode(false); // layers carry nothing the scene model keeps
}

// Reads and transfers a STEP or IGES file into `doc`; throws Malformed naming the file.
void readXcaf(const fs::path& file, CadKind kind, Handle(TDocStd_Document) & doc,
              const Progress& progress) {
    const std::string path = file.string();
    const auto fail = [&](const std::string& problem) {
        throw Error(ErrorCode::Malformed, file, problem);
    };
    const auto readAndTransfer = [&](auto& reader, const char* format) {
        configure(reader);
        const IFSelect_ReturnStatus status = reader.ReadFile(path.c_str());
        if (status != IFSelect_RetDone) {
            fail(std::string(format) + " reader failed: " + statusText(status));
        }
        if (reader.NbRootsForTransfer() <= 0) {
            fail(std::string(format) + " file has no transferable roots (no product or shape)");
        }
        cad::StepProgress transfer(progress, file);
        const Handle(Message_ProgressIndicator) indicator = transfer.indicator();
        const bool transferred = reader.Transfer(doc, indicator->Start());
        transfer.throwIfCancelled();
        if (!transferred) fail(std::string(format) + " transfer to shapes failed");
        transfer.finish();
    };
    if (kind == CadKind::Iges) {
        IGESCAFControl_Reader reader;
        readAndTransfer(reader, "IGES");
    } else {
        STEPCAFControl_Reader reader;
        reader.SetPropsMode(false); // validation properties, not geometry
        reader.SetGDTMode(false);
        reader.SetViewMode(false);
        readAndTransfer(reader, "STEP");
    }
}

// Metres per document length unit, as the reader left it in the document.
double documentUnitMetres(const Handle(TDocStd_Document) & doc) {
    Standard_Real metres = 0.0;
    if (XCAFDoc_DocumentTool::GetLengthUnit(doc, metres) && std::isfinite(metres) && metres > 0.0) {
        return metres;
    }
    // No unit recorded: the readers then used the session unit, "xstep.cascade.unit".
    return UnitsMethods::GetCasCadeLengthUnit(UnitsMethods_LengthUnit_Meter);
}

Scene importXcaf(const fs::path& file, CadKind kind, const ImportOptions& options,
                 const Progress& progress) {
    // Before OCCT's transfer, which builds every expanded placement of the assembly.
    if (kind == CadKind::Step) checkStepInstancing(file, options.limits);
    XcafDocument document;
    {
        // Outside the guarded call: a fault abandons its frames without unlocking/restoring.
        const std::lock_guard lock(readerMutex());
        const QuietStdout quiet;
        cad::runGuarded([&] { readXcaf(file, kind, document.get(), progress); });
    }
    Scene scene;
    cad::runGuarded([&] {
        scene = cad::sceneFromXcaf(document.get(), documentUnitMetres(document.get()), options,
                                   file, progress);
    });
    return scene;
}

// The pieces a BREP file is split into: its solids, then shells outside solids, then faces
// outside shells (a compound of free faces, like the kitchen's Room.brep).
std::vector<TopoDS_Shape> brepItems(const TopoDS_Shape& shape) {
    std::vector<TopoDS_Shape> items;
    for (TopExp_Explorer ex(shape, TopAbs_SOLID); ex.More(); ex.Next()) {
        items.push_back(ex.Current());
    }
    for (TopExp_Explorer ex(shape, TopAbs_SHELL, TopAbs_SOLID); ex.More(); ex.Next()) {
        items.push_back(ex.Current());
    }
    for (TopExp_Explorer ex(shape, TopAbs_FACE, TopAbs_SHELL); ex.More(); ex.Next()) {
        items.push_back(ex.Current());
    }
    return items;
}

// Reads from a stream that throws once a read fails: OCCT 7.6's BRepTools_ShapeSet loops
// forever on some corrupt files (a changed curve representation code) reading past the end
// of the data, because it never checks the stream state.
TopoDS_Shape readBrep(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(ErrorCode::FileUnreadable, file, "cannot open for reading");
    in.exceptions(std::ios::failbit | std::ios::badbit);
    TopoDS_Shape shape;
    BRep_Builder builder;
    try {
        const std::lock_guard lock(readerMutex());
        const QuietStdout quiet;
        cad::runGuarded([&] { BRepTools::Read(shape, in, builder); });
    } catch (const std::ios_base::failure&) {
        throw Error(ErrorCode::Malformed, file, "BREP data is truncated or corrupt");
    }
    if (shape.IsNull()) {
        throw Error(ErrorCode::Malformed, file, "not a readable OpenCASCADE BREP file");
    }
    return shape;
}

// One node and mesh per BREP item; items that are the same TShape placed at different
// locations share one mesh (meshed in the item's own frame, placed by the node transform).
Scene brepScene(const fs::path& file, const TopoDS_Shape& shape, const ImportOptions& options,
                const Progress& progress) {
    const std::vector<TopoDS_Shape> items = brepItems(shape);
    if (items.empty()) {
        throw Error(ErrorCode::NoGeometry, file, "the shape has no faces (curves or points only)");
    }
    const double diagonal = cad::modelDiagonal(shape);
    if (diagonal <= 0.0) {
        throw Error(ErrorCode::NoGeometry, file, "the shape's faces have no finite extent");
    }
    cad::clearTriangulation(shape);
    const double scale = options.cadBrepUnitMetres;
    const double deflection = options.cadRelativeDeflection * diagonal;
    cad::TessellationBudget budget =
        cad::makeBudget(file, diagonal, deflection, options.cadAngularDeflection);
    cad::FaceProgress faces(progress, file, cad::faceCount(shape));
    cad::tessellate(shape, deflection, options.cadAngularDeflection, &budget, scale, &faces);
    Scene scene;
    scene.importNotes = std::move(budget.notes);
    const std::string stem = file.stem().string();
    std::map<std::pair<const void*, int>, Id> shared;
    std::size_t triangles = 0;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const TopoDS_Shape& item = items[i];
        const std::string name = items.size() == 1 ? stem : stem + "_" + std::to_string(i + 1);
        const auto key = std::make_pair(static_cast<const void*>(item.TShape().get()),
                                        static_cast<int>(item.Orientation()));
        auto it = shared.find(key);
        if (it == shared.end()) {
            std::vector<cad::ColouredMesh> groups =
                cad::extractMeshes(item.Located(TopLoc_Location()), scale, std::nullopt, nullptr);
            if (groups.empty()) continue; // nothing of this item tessellated
            groups.front().mesh.name = name;
            triangles += groups.front().mesh.triangleCount();
            cad::checkTessellatedTriangles(triangles, options, file);
            it = shared.emplace(key, scene.addMesh(std::move(groups.front().mesh))).first;
        }
        const Id node = scene.addNode(name, 0, cad::toGlm(item.Location().Transformation(), scale));
        scene.addInstance(it->second, node);
    }
    if (scene.instances.empty()) {
        throw Error(ErrorCode::NoGeometry, file, "no face could be tessellated");
    }
    return scene;
}

Scene importBrep(const fs::path& file, const ImportOptions& options, const Progress& progress) {
    const TopoDS_Shape shape = readBrep(file);
    Scene scene;
    cad::runGuarded([&] { scene = brepScene(file, shape, options, progress); });
    return scene;
}

void checkOptions(const fs::path& file, const ImportOptions& options) {
    const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
    if (!positive(options.cadRelativeDeflection) || !positive(options.cadAngularDeflection) ||
        !positive(options.cadBrepUnitMetres)) {
        throw Error(ErrorCode::InvalidArgument, file,
                    "CAD deflections and BREP unit must be positive numbers");
    }
}

} // namespace

Scene importCadHere(const fs::path& file, const ImportOptions& options, const Progress& progress) {
    checkOptions(file, options);
    silenceOcct();
    const CadKind kind = kindOf(file);
    Scene scene;
    try {
        scene = kind == CadKind::Brep ? importBrep(file, options, progress)
                                      : importXcaf(file, kind, options, progress);
    } catch (const Error&) {
        throw;
    } catch (const Standard_Failure& e) {
        const char* what = e.GetMessageString();
        throw Error(ErrorCode::Malformed, file,
                    std::string("OpenCASCADE failed: ") + (what != nullptr ? what : "unknown"));
    } catch (const std::bad_alloc&) {
        throw Error(ErrorCode::TooLarge, file, "out of memory while reading the CAD model");
    } catch (const std::exception& e) {
        throw Error(ErrorCode::Malformed, file, e.what());
    }
    scene.sourceFiles.push_back(file);
    scene.updateWorldTransforms();
    validateScene(scene, file);
    return scene;
}

} // namespace hlod

HLOD_MODULE_ENTRY(hlod::CadModule, cad, &hlod::importCadHere)
