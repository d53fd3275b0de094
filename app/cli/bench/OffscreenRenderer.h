// Offscreen VTK rendering for `hlod bench`: one layer (vtkRenderer) per configuration, one
// actor per drawable (mesh instance, DLOD level of an instance, or proxy) built once, and per
// frame the visible set toggled, like an engine's draw calls.
//
// Needs an X display: Debian's VTK 9.1 is built without EGL and OSMesa, so its offscreen
// rendering still opens a (hidden) GLX window. Run under `xvfb-run -a` on a headless machine;
// the constructor throws hlod::Error when DISPLAY is unset.
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "pipeline/eval/Image.h"
#include "pipeline/proxy/ProxyMesh.h"
#include "pipeline/scene/Scene.h"
#include "pipeline/select/Camera.h"

namespace hlod::cli {

// Geometry: one grey for everything. Colour: material colour (base colour x texture mean) x
// vertex colour, as a proxy with vertex colours shows it, plus the emitted colour (emissive
// factor x its texture's mean). Textured: base colour factor x base colour texture x vertex
// colour, alpha as the material says (MASK tested at its cut-off, BLEND blended), plus
// emission (VtkSurfaceLook.h), what an engine draws. In all three, back faces are culled
// unless the material (or the proxy, ProxyLook.h) is double-sided, as engines do.
// All three use the same simple lighting (ambient + diffuse from a headlight), colours given
// to the GPU as sRGB values (products of sRGB values are close to the sRGB of the product).
enum class Shading { Geometry, Colour, Textured };

// What Textured shading needs of a surface. `texture` must outlive the renderer (it is shared
// by every drawable using it, uploaded once with mipmaps, repeat wrap, linear filtering).
struct SurfaceLook {
    glm::vec4 factor{1.0f};             // linear RGBA base colour factor
    const RgbaImage* texture = nullptr; // sRGB RGBA, top row first; null = untextured
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
    glm::vec3 emissive{0.0f};       // linear emissive factor
    glm::vec3 emissiveMean{1.0f};   // mean of its texture (where the texture is not drawn)
    bool emissiveIsTexture = false; // the emissive texture is `texture`
};

// The look of a scene material.
SurfaceLook lookOf(const Scene& scene, Id material);

class OffscreenRenderer {
public:
    OffscreenRenderer(int width, int height, Shading shading);
    ~OffscreenRenderer();
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

    int addLayer();
    // A mesh placed with `world`; `color` used in Colour shading (vertex colours multiply it),
    // `look` in Textured shading. Meshes are converted once and shared by every drawable that
    // uses the same Mesh object.
    int addMesh(int layer, const Mesh& mesh, const glm::dmat4& world, const glm::vec4& color,
                const SurfaceLook& look = {});
    // A proxy: its vertex colours in Colour shading; its baked atlas in Textured shading
    // (vertex colours when it has none); its sidedness and emission (ProxyMesh.h) in both;
    // placed by its node's frame (NodeBake::frame). The atlas image must outlive the renderer.
    int addProxy(int layer, const ProxyMesh& proxy, const glm::dmat4& frame);

    // Makes exactly `drawables` of `layer` visible (indices returned by add*).
    void setVisible(int layer, const std::vector<int>& drawables);
    // Shows all of a layer's drawables and renders once, so every buffer is on the GPU before
    // timing (an engine loads its meshes before it draws them).
    void warmUp(int layer, const Camera& camera);
    // Renders `layer` only; returns the wall time of Render() plus glFinish, in milliseconds.
    double render(int layer, const Camera& camera);
    RgbImage readPixels();
    // Closes the window; the renderer cannot render afterwards.
    void close();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace hlod::cli
