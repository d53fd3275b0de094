// How a textured surface is set up in VTK, shared by the editor's viewport and `hlod bench`
// (header only and free of Qt, so the CLI can use it without linking the widgets library).
//
// Textures: the decoded image (RgbaImage, top row first) goes into row 0 of the vtkImageData
// first, which VTK samples at t = 0, the same place glTF's v = 0 names, so uvs are used as
// given. Mipmaps, repeat wrap and linear filtering (glTF's default sampler); texel values are
// handed over as stored (sRGB), like every other colour we give VTK (no colour management).
// VTK multiplies the lit vertex or actor colour by the texture (base colour factor x vertex
// colour x texture, as glTF defines the base colour).
// Alpha: OPAQUE and MASK surfaces are drawn in the opaque pass (VTK would otherwise treat an
// actor whose texture has alpha as translucent and blend it); MASK discards fragments whose
// alpha is below the cut-off; both then write alpha 1. BLEND is left to VTK's translucent pass.
#pragma once

#include <algorithm>
#include <string>

#include <vtkActor.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkShaderProperty.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>

#include "pipeline/scene/RgbaImage.h"
#include "pipeline/scene/Scene.h"

namespace hlod::widgets {

inline vtkSmartPointer<vtkTexture> makeVtkTexture(const RgbaImage& image) {
    vtkNew<vtkImageData> data;
    data->SetDimensions(image.width, image.height, 1);
    data->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
    std::copy(image.pixels.begin(), image.pixels.end(),
              static_cast<unsigned char*>(data->GetScalarPointer()));
    auto texture = vtkSmartPointer<vtkTexture>::New();
    texture->SetInputData(data);
    texture->SetColorModeToDirectScalars();
    texture->InterpolateOn();
    texture->MipmapOn();
    texture->RepeatOn();
    texture->EdgeClampOff();
    return texture;
}

inline void applyAlphaMode(vtkActor& actor, AlphaMode mode, float cutoff) {
    if (mode == AlphaMode::Blend) return;
    actor.ForceOpaqueOn();
    std::string code = "//VTK::TCoord::Impl\n";
    if (mode == AlphaMode::Mask)
        code += "  if (gl_FragData[0].a < " + std::to_string(cutoff) + ") discard;\n";
    code += "  gl_FragData[0].a = 1.0;\n";
    actor.GetShaderProperty()->AddFragmentShaderReplacement("//VTK::TCoord::Impl", true, code,
                                                            false);
}

} // namespace hlod::widgets
