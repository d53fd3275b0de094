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
// Sides: back faces are culled unless the material is double-sided (glTF 2.0 3.9.5, what every
// engine does); VTK's two-sided lighting then lights a double-sided back face as glTF does,
// with the normal flipped.
// Emission (glTF: emissive factor x emissive texture, added after lighting): a uniform
// `hlodEmissive` (linear RGB) added to the lit colour in linear terms (colours reach VTK as
// sRGB values: decoded with gamma 2.2, the emission added, encoded again). When the emissive
// texture is the base colour texture (AC3D's `emis`, a proxy atlas) it is added before VTK
// multiplies by the texture, (lit + emissive) x texture, exactly glTF's sum for that case;
// otherwise after texturing, the emissive factor times its texture's mean (a flat glow: one
// texture per actor).
#pragma once

#include <algorithm>
#include <string>

#include <glm/glm.hpp>
#include <vtkProperty.h>
#include <vtkUniforms.h>

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

// How an actor draws its surface, beyond colours and texture (see the header comment).
struct VtkMaterialLook {
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
    glm::vec3 emissive{0.0f};          // linear RGB; zero: none
    bool emissiveTimesTexture = false; // the emissive texture is the actor's texture
};

inline void applyMaterialLook(vtkActor& actor, const VtkMaterialLook& look) {
    actor.GetProperty()->SetBackfaceCulling(look.doubleSided ? 0 : 1);
    const bool emits = look.emissive != glm::vec3(0.0f);
    // Decoded from sRGB (gamma 2.2), emission added, encoded again.
    const std::string addEmission =
        "  gl_FragData[0].rgb = pow(pow(max(gl_FragData[0].rgb, vec3(0.0)), vec3(2.2)) + "
        "hlodEmissive, vec3(1.0 / 2.2));\n";
    vtkShaderProperty* shader = actor.GetShaderProperty();
    if (emits) {
        const float e[3] = {look.emissive.r, look.emissive.g, look.emissive.b};
        shader->GetFragmentCustomUniforms()->SetUniform3f("hlodEmissive", e);
        if (look.emissiveTimesTexture)
            shader->AddFragmentShaderReplacement("//VTK::Light::Impl", true,
                                                 "//VTK::Light::Impl\n" + addEmission, false);
    }
    std::string code = "//VTK::TCoord::Impl\n";
    if (emits && !look.emissiveTimesTexture) code += addEmission;
    if (look.alphaMode == AlphaMode::Mask)
        code += "  if (gl_FragData[0].a < " + std::to_string(look.alphaCutoff) + ") discard;\n";
    if (look.alphaMode != AlphaMode::Blend) {
        actor.ForceOpaqueOn();
        code += "  gl_FragData[0].a = 1.0;\n";
    }
    if (code != "//VTK::TCoord::Impl\n")
        shader->AddFragmentShaderReplacement("//VTK::TCoord::Impl", true, code, false);
}

// The look of scene material `material` for an actor drawing it (`textured`: with the
// material's base colour texture on the actor).
inline VtkMaterialLook materialLookOf(const Scene& scene, Id material, bool textured) {
    VtkMaterialLook look;
    if (material >= scene.materials.size()) return look;
    const Material& m = scene.materials[material];
    look.alphaMode = m.alphaMode;
    look.alphaCutoff = m.alphaCutoff;
    look.doubleSided = m.doubleSided;
    look.emissiveTimesTexture =
        textured && m.emissiveTexture != kNoId && m.emissiveTexture == m.texture;
    look.emissive = look.emissiveTimesTexture ? m.emissive : m.effectiveEmissive();
    return look;
}

} // namespace hlod::widgets
