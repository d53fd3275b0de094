// Test helper: writes a STEP file whose assembly reuses one sub-assembly twice at every level
// (level 0 is a box part, level i places level i-1 twice), so `levels` levels are 2^levels
// placed boxes from a file of a few kilobytes: the instancing DAG the import budget bounds
// (issue 22, ImportLimits.h). Written through OCCT's XCAF document and STEP writer (AP214), so
// the file is what a CAD system exports for such an assembly (one NEXT_ASSEMBLY_USAGE_OCCURRENCE
// per component).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include <BRepPrimAPI_MakeBox.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopLoc_Location.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Trsf.hxx>

namespace hlod::test {

inline void writeNestedAssemblyStep(const std::filesystem::path& file, int levels) {
    Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
    Handle(TDocStd_Document) doc;
    app->NewDocument("MDTV-XCAF", doc);
    Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    TDF_Label below = shapes->AddShape(BRepPrimAPI_MakeBox(1.0, 1.0, 1.0).Shape(), false);
    TDataStd_Name::Set(below, "box");
    for (int level = 1; level <= levels; ++level) {
        const TDF_Label assembly = shapes->NewShape();
        TDataStd_Name::Set(assembly, ("level" + std::to_string(level)).c_str());
        for (int copy = 0; copy < 2; ++copy) {
            gp_Trsf shift;
            shift.SetTranslation(gp_Vec(copy * 2.0 * (1 << (level - 1)), 0.0, 0.0));
            shapes->AddComponent(assembly, below, TopLoc_Location(shift));
        }
        below = assembly;
    }
    shapes->UpdateAssemblies();
    STEPCAFControl_Writer writer;
    if (!writer.Transfer(doc, STEPControl_AsIs) ||
        writer.Write(file.string().c_str()) != IFSelect_RetDone) {
        app->Close(doc);
        throw std::runtime_error("cannot write " + file.string());
    }
    app->Close(doc);
}

} // namespace hlod::test
