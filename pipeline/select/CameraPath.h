// Camera paths for the evaluation (`hlod bench`), after the thesis' chapter 6.2: "animating the
// camera along a path for a duration of 30 seconds, showcasing every model's key features both
// from a close distance and also far away". Frame i is the path at time t = i / fps.
//
// A path is a list of keys (time, eye, target) interpolated with a Catmull-Rom spline (eye and
// target separately; the first and last keys are repeated as end tangents), plus the up axis and
// the vertical field of view. Between keys it passes through every key exactly.
//
// The automatic path (deterministic: a pure function of the scene's geometry), 30 s:
//   0-12 s  orbit around the whole scene at the distance where its bounding sphere fills the
//           view (r / sin(fov/2)), 35° above the horizon;
//   12-24 s fly in: the distance shrinks geometrically (constant relative speed) to the close
//           distance while the look-at point moves from the scene centre to the focus point and
//           the camera drops to 25°;
//   24-30 s close-up: keeps circling the focus point at the close distance.
// The azimuth turns 360° every 16 s throughout. The focus point is the centre of the instance
// nearest the median of all instance centres (a point on real geometry, not empty space), the
// close distance 6% of the scene's bounding radius (but at least twice the focus instance's
// radius, and at most 25% of the scene radius), then grown by 25% steps (up to half the scene
// radius) while a close-up key (t >= 20 s) would put the eye inside an instance's box (boxes
// holding a quarter of the scene's volume or more, like a room's walls, do not count). Up is
// +Z for CAD sources (STEP, IGES, BREP files in Scene::sourceFiles), else +Y (glTF, AC3D).
// Keys are stored every second, so the automatic path round-trips through JSON.
//
// JSON format (written by writeCameraPath, read by readCameraPath):
//   {"up": [0, 1, 0], "fov_deg": 60,
//    "keys": [{"t": 0, "eye": [x, y, z], "target": [x, y, z]}, ...]}
// t in seconds, strictly increasing, at least 2 keys; eye != target; all numbers finite; "up"
// (default [0,1,0]) and "fov_deg" (default 60, in (0, 180)) are optional. World units (metres).
#pragma once

#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "pipeline/scene/Scene.h"
#include "pipeline/select/Camera.h"

namespace hlod {

struct CameraKey {
    double time = 0.0; // seconds
    glm::dvec3 eye{0.0};
    glm::dvec3 target{0.0};
};

struct CameraPath {
    std::vector<CameraKey> keys;
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovYDegrees = 60.0;
    // Clip planes: near = nearFactor * |eye - target| (bounded below by minNear), far =
    // farDistance.
    double nearFactor = 0.01;
    double minNear = 1e-4;
    double farDistance = 1.0e5;

    double duration() const { return keys.empty() ? 0.0 : keys.back().time - keys.front().time; }
    // The camera at time t (clamped to the path), for a viewport of width x height pixels.
    Camera at(double t, int width, int height) const;
};

inline constexpr double kAutomaticPathSeconds = 30.0;

// Throws Error(NoGeometry) for a scene without instances.
CameraPath automaticCameraPath(const Scene& scene, double fovYDegrees = 60.0);

// Throws Error(Malformed, file, what is wrong) for bad JSON or keys, Error(FileNotFound /
// FileUnreadable) when it cannot be read. Clip planes are set from the keys' extent.
CameraPath readCameraPath(const std::filesystem::path& file);
void writeCameraPath(const std::filesystem::path& file, const CameraPath& path);

// Sets the clip planes for a scene: far = farthest key eye from the scene centre + its bounding
// diameter, minNear = 1e-4 of the bounding radius (so nothing of the scene is ever far-clipped).
void fitClipPlanes(CameraPath& path, const Aabb& sceneBounds);

// Frame i at t = i / fps, i in [0, frames).
std::vector<Camera> sampleCameraPath(const CameraPath& path, int frames, double fps, int width,
                                     int height);

} // namespace hlod
