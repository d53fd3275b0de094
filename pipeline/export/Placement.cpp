// Placement and framing metadata of a package (Placement.h).
#include "pipeline/export/Placement.h"

#include <algorithm>

#include "pipeline/core/Error.h"
#include "pipeline/export/JsonNumbers.h"
#include "pipeline/select/CameraPath.h"

namespace hlod {

namespace {

// Package frame (Y up) -> tileset frame (Z up): (x, y, z) -> (x, -z, y) (Package.h).
glm::dvec3 toTileset(const glm::dvec3& v) { return {v.x, -v.z, v.y}; }

nlohmann::json vec(const glm::dvec3& v) {
    auto n = [](double x) {
        const double s = shortNumber(x);
        return s == 0.0 ? 0.0 : s; // no "-0.0"
    };
    return {n(v.x), n(v.y), n(v.z)};
}

nlohmann::json placementJson(const glm::dvec3& center, double radius, const glm::dvec3& sceneUp,
                             const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up,
                             double fov) {
    return {{"boundingSphere", {{"center", vec(center)}, {"radius", shortNumberUp(radius)}}},
            {"sceneUp", vec(sceneUp)},
            {"view",
             {{"eye", vec(eye)}, {"target", vec(target)}, {"up", vec(up)}, {"fovYDegrees", fov}}}};
}

} // namespace

Placement packagePlacement(const Scene& scene) {
    const CameraPath path = automaticCameraPath(scene); // throws NoGeometry without instances
    const Aabb bounds = scene.worldBounds();
    Placement p;
    p.center = bounds.center();
    p.radius = std::max(bounds.diagonal() * 0.5, 1e-6);
    p.sceneUp = path.up;
    const Camera first = path.at(path.keys.front().time, 1920, 1080);
    p.eye = first.eye;
    p.target = first.target;
    p.up = first.up;
    p.fovYDegrees = path.fovYDegrees;
    return p;
}

nlohmann::json placementTilesetJson(const Placement& p, const std::optional<GeoLocation>& geo,
                                    double maximumScreenSpaceError) {
    nlohmann::json j =
        placementJson(toTileset(p.center), p.radius, toTileset(p.sceneUp), toTileset(p.eye),
                      toTileset(p.target), toTileset(p.up), p.fovYDegrees);
    j["units"] = "metre";
    j["maximumScreenSpaceError"] = maximumScreenSpaceError;
    if (geo) {
        // Coordinates above are in the local east-north-up frame the root transform places.
        j["frame"] = "east-north-up";
        j["geo"] = {{"latitudeDeg", geo->latitudeDeg},
                    {"longitudeDeg", geo->longitudeDeg},
                    {"heightM", geo->heightM}};
        const glm::dmat4 m = enuToEcef(*geo);
        nlohmann::json matrix = nlohmann::json::array();
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                matrix.push_back(m[c][r]);
        j["localToWorld"] = matrix;
    } else {
        j["frame"] = "local"; // the tileset frame is the world: put it where it belongs
    }
    return j;
}

nlohmann::json placementManifestJson(const Placement& p, const std::optional<GeoLocation>& geo) {
    nlohmann::json j =
        placementJson(p.center, p.radius, p.sceneUp, p.eye, p.target, p.up, p.fovYDegrees);
    j["frame"] = "package";
    j["geo"] = geo ? nlohmann::json{{"latitudeDeg", geo->latitudeDeg},
                                    {"longitudeDeg", geo->longitudeDeg},
                                    {"heightM", geo->heightM}}
                   : nlohmann::json(nullptr);
    return j;
}

} // namespace hlod
