// What a runtime needs to place and frame a package (issue 28): where the scene is, which way
// is up, and a view that shows all of it, written into tileset.json (extras.hlod) and hlod.json
// (placement). A package built without --geo is in a local frame, not on the globe: CesiumJS
// draws it at the Earth's centre until the application gives it a model matrix, three.js at
// its origin; either needs the scene's extent and up axis to put a camera on it.
//
// Frames (Package.h): the package frame is the content's (Y up for glTF and AC3D sources,
// metres); the tileset frame is that frame turned Z up, (x, y, z) -> (x, -z, y), and is what a
// 3D Tiles runtime places. With --geo the root transform then takes it to ECEF
// ("localToWorld"); without it the tileset frame is the world ("frame": "local").
// - boundingSphere: centre and radius of the scene's bounds (half their diagonal).
// - sceneUp: the scene's up axis: +Y of the package frame, but +Z for CAD sources (STEP, IGES
//   and BREP are Z up by convention; CameraPath.h makes the same choice).
// - view: the first camera of `hlod bench`'s automatic path (CameraPath.h): 35 degrees above
//   the horizon, at the distance where the bounding sphere fills a 60 degree view; eye, target
//   and up.
// - maximumScreenSpaceError: the pixel error; a runtime using it switches tiles where the
//   package was baked to switch (Package.h).
#pragma once

#include <optional>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "pipeline/export/Geo.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

struct Placement {
    glm::dvec3 center{0.0}; // package frame
    double radius = 0.0;
    glm::dvec3 sceneUp{0.0, 1.0, 0.0};
    glm::dvec3 eye{0.0}, target{0.0}, up{0.0, 1.0, 0.0};
    double fovYDegrees = 60.0;
};

// Throws Error(NoGeometry) for a scene without instances.
Placement packagePlacement(const Scene& scene);

// tileset.json's extras.hlod: the placement in the tileset frame, the frame kind, localToWorld
// with --geo, and maximumScreenSpaceError.
nlohmann::json placementTilesetJson(const Placement& p, const std::optional<GeoLocation>& geo,
                                    double maximumScreenSpaceError);

// hlod.json's placement: the same in the package frame.
nlohmann::json placementManifestJson(const Placement& p, const std::optional<GeoLocation>& geo);

} // namespace hlod
