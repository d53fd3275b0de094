// XCAF document -> hlod::Scene: the assembly tree, names, colours and shared parts of a STEP
// or IGES file read by OpenCASCADE (STEPCAFControl_Reader / IGESCAFControl_Reader).
//
// Based on the OCCT 7.6 XDE user guide (XCAFDoc_ShapeTool: free shapes, assemblies,
// components referring to shapes, sub-shapes; XCAFDoc_ColorTool) and on the style
// precedence of XCAFPrs (a sub-shape's colour beats its shape's, an instance's colour beats
// the referred shape's, which beats what the parent assembly passes down).
//
// Mapping:
//  - every free shape becomes a child node of the root; every assembly component becomes a
//    node under its assembly with the component's TopLoc_Location as local transform;
//  - a part (simple shape) is tessellated once and becomes one Mesh per colour (faces with
//    their own colour go to their own mesh, so each Mesh keeps one material); every
//    component that refers to the part instances those same meshes on its own node.
//    An instance with a colour of its own gets its own copy of the meshes, since a Mesh
//    carries its material;
//  - names: the component's TDataStd_Name, else the referred shape's (XCAF's generated
//    "=>[0:1:1:n]" names are skipped); meshes are named after the part;
//  - colours become one Material per distinct RGBA (linear), named by its sRGB hex code;
//  - components and parts marked invisible in the document are left out.
#pragma once

#include <filesystem>

#include <TDocStd_Document.hxx>

#include "pipeline/io/Import.h"
#include "pipeline/scene/Scene.h"

namespace hlod::cad {

// Builds the scene of a transferred XCAF document. `unitScale` is metres per document unit.
// Before anything is built or tessellated, the assembly graph is walked once (each shape label
// once, placements counted along the way) so that sub-assemblies reused at every level cannot
// expand into billions of nodes: more placements than options.limits.maxInstances is refused.
// Tessellation reports per face on `progress` (CadProgress.h).
// Throws hlod::Error naming `file`: NoGeometry when no face tessellates, TooLarge past
// options.limits (placements, tessellated triangles), Malformed for an assembly nested
// absurdly deep, Cancelled when `progress` is cancelled.
Scene sceneFromXcaf(const Handle(TDocStd_Document) & doc, double unitScale,
                    const ImportOptions& options, const std::filesystem::path& file,
                    const Progress& progress = {});

} // namespace hlod::cad
