#include "pipeline/select/CameraPath.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>

#include <nlohmann/json.hpp>

#include "pipeline/core/AtomicFile.h"
#include "pipeline/core/Error.h"

namespace hlod {

namespace {

glm::dvec3 catmullRom(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2,
                      const glm::dvec3& p3, double s) {
    const double s2 = s * s, s3 = s2 * s;
    return 0.5 * ((2.0 * p1) + (-p0 + p2) * s + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * s2 +
                  (-p0 + 3.0 * p1 - 3.0 * p2 + p3) * s3);
}

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// A unit vector perpendicular to `up`.
glm::dvec3 perpendicular(const glm::dvec3& up) {
    const glm::dvec3 a = std::abs(up.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(up, a));
}

} // namespace

Camera CameraPath::at(double t, int width, int height) const {
    Camera c;
    c.fovY = glm::radians(fovYDegrees);
    c.aspect = static_cast<double>(std::max(width, 1)) / static_cast<double>(std::max(height, 1));
    c.viewportHeight = std::max(height, 1);
    c.up = up;
    if (keys.empty()) return c;
    std::size_t i = 0;
    if (keys.size() == 1 || t <= keys.front().time) {
        c.eye = keys.front().eye;
        c.target = keys.front().target;
    } else if (t >= keys.back().time) {
        c.eye = keys.back().eye;
        c.target = keys.back().target;
    } else {
        i = static_cast<std::size_t>(
            std::upper_bound(keys.begin(), keys.end(), t,
                             [](double v, const CameraKey& k) { return v < k.time; }) -
            keys.begin() - 1);
        const CameraKey& k1 = keys[i];
        const CameraKey& k2 = keys[i + 1];
        const CameraKey& k0 = keys[i == 0 ? 0 : i - 1];
        const CameraKey& k3 = keys[std::min(i + 2, keys.size() - 1)];
        const double s = (t - k1.time) / (k2.time - k1.time);
        c.eye = catmullRom(k0.eye, k1.eye, k2.eye, k3.eye, s);
        c.target = catmullRom(k0.target, k1.target, k2.target, k3.target, s);
    }
    // Keep the view direction off the up axis (lookAt degenerates there).
    const glm::dvec3 dir = c.target - c.eye;
    const double len = glm::length(dir);
    if (len <= 0.0) c.target = c.eye - up; // cannot happen for validated keys
    if (len > 0.0 && std::abs(glm::dot(dir / len, up)) > 0.9999) c.up = perpendicular(up);
    c.nearPlane = std::max(minNear, nearFactor * std::max(len, 0.0));
    c.farPlane = std::max(farDistance, c.nearPlane * 10.0);
    return c;
}

CameraPath automaticCameraPath(const Scene& scene, double fovYDegrees) {
    if (scene.instances.empty())
        throw Error(ErrorCode::NoGeometry, "camera path: the scene has no mesh instances");
    const Aabb bounds = scene.worldBounds();
    const glm::dvec3 center = bounds.center();
    const double radius = std::max(bounds.diagonal() * 0.5, 1e-6);

    CameraPath path;
    path.fovYDegrees = fovYDegrees;
    // Up: +Z for CAD sources (STEP, IGES, BREP are Z up by convention), else +Y (glTF, AC3D,
    // and most mesh formats).
    glm::dvec3 up(0.0, 1.0, 0.0);
    for (const std::filesystem::path& f : scene.sourceFiles) {
        std::string ext = f.extension().string();
        for (char& ch : ext)
            ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        if (ext == ".stp" || ext == ".step" || ext == ".igs" || ext == ".iges" || ext == ".brep" ||
            ext == ".brp")
            up = glm::dvec3(0.0, 0.0, 1.0);
    }
    path.up = up;

    // Focus: the instance centre nearest the component-wise median of instance centres.
    std::vector<glm::dvec3> centers;
    std::vector<double> radii;
    centers.reserve(scene.instances.size());
    for (Id i = 0; i < scene.instances.size(); ++i) {
        const Aabb b = scene.instanceBounds(i);
        if (b.empty()) continue;
        centers.push_back(b.center());
        radii.push_back(b.diagonal() * 0.5);
    }
    if (centers.empty())
        throw Error(ErrorCode::NoGeometry, "camera path: the scene has no geometry");
    glm::dvec3 median;
    for (int a = 0; a < 3; ++a) {
        std::vector<double> v(centers.size());
        for (std::size_t i = 0; i < centers.size(); ++i)
            v[i] = centers[i][a];
        std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
        median[a] = v[v.size() / 2];
    }
    std::size_t best = 0;
    double bestD = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < centers.size(); ++i) {
        const double d = glm::length(centers[i] - median);
        if (d < bestD) {
            bestD = d;
            best = i;
        }
    }
    const glm::dvec3 focus = centers[best];
    double closeDistance = std::clamp(2.0 * radii[best], 0.06 * radius, 0.25 * radius);
    const double farDistance = radius / std::sin(glm::radians(fovYDegrees) * 0.5);

    // Instance boxes a close-up eye must stay out of (not the ones holding most of the scene,
    // like a room's walls, which the eye is meant to be inside).
    std::vector<Aabb> solid;
    const double sceneVolume = std::max(bounds.volume(), 1e-300);
    for (Id i = 0; i < scene.instances.size(); ++i) {
        const Aabb b = scene.instanceBounds(i);
        if (!b.empty() && b.volume() < 0.25 * sceneVolume) solid.push_back(b);
    }
    auto insideSolid = [&](const glm::dvec3& p) {
        for (const Aabb& b : solid)
            if (p.x > b.min.x && p.y > b.min.y && p.z > b.min.z && p.x < b.max.x && p.y < b.max.y &&
                p.z < b.max.z)
                return true;
        return false;
    };

    const glm::dvec3 e1 = perpendicular(up);
    const glm::dvec3 e2 = glm::cross(up, e1);
    const double pi = std::numbers::pi;
    auto smooth = [](double x) {
        x = std::clamp(x, 0.0, 1.0);
        return x * x * (3.0 - 2.0 * x);
    };
    // Grow the close distance (up to half the scene radius) until no close-up key puts the eye
    // inside a part.
    for (int attempt = 0; attempt < 16; ++attempt) {
        path.keys.clear();
        bool blocked = false;
        for (int second = 0; second <= static_cast<int>(kAutomaticPathSeconds); ++second) {
            const double t = second;
            const double azimuth = 0.25 * pi + 2.0 * pi * t / 16.0;
            const double s = smooth((t - 12.0) / 12.0); // 0 before the fly-in, 1 after it
            const double distance = farDistance * std::pow(closeDistance / farDistance, s);
            const double elevation = glm::radians(35.0 + (25.0 - 35.0) * s);
            const glm::dvec3 target = center + (focus - center) * s;
            const glm::dvec3 dir =
                std::cos(elevation) * (std::cos(azimuth) * e1 + std::sin(azimuth) * e2) +
                std::sin(elevation) * up;
            path.keys.push_back({t, target + dir * distance, target});
            if (t >= 20.0 && insideSolid(path.keys.back().eye)) blocked = true;
        }
        if (!blocked || closeDistance >= 0.5 * radius) break;
        closeDistance = std::min(closeDistance * 1.25, 0.5 * radius);
    }
    fitClipPlanes(path, bounds);
    return path;
}

void fitClipPlanes(CameraPath& path, const Aabb& bounds) {
    const glm::dvec3 center = bounds.center();
    const double radius = std::max(bounds.diagonal() * 0.5, 1e-6);
    double far = 0.0;
    for (const CameraKey& k : path.keys)
        far = std::max(far, glm::length(k.eye - center));
    path.farDistance = far + 2.0 * radius;
    path.minNear = radius * 1e-4;
}

namespace {

glm::dvec3 readVec3(const nlohmann::json& j, const std::filesystem::path& file,
                    const std::string& what) {
    if (!j.is_array() || j.size() != 3)
        throw Error(ErrorCode::Malformed, file, what + " must be an array of 3 numbers");
    glm::dvec3 v;
    for (int a = 0; a < 3; ++a) {
        if (!j[static_cast<std::size_t>(a)].is_number())
            throw Error(ErrorCode::Malformed, file, what + " must be an array of 3 numbers");
        v[a] = j[static_cast<std::size_t>(a)].get<double>();
    }
    if (!finite(v)) throw Error(ErrorCode::Malformed, file, what + " is not finite");
    return v;
}

} // namespace

CameraPath readCameraPath(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec))
        throw Error(ErrorCode::FileNotFound, file, "no such file");
    std::ifstream in(file, std::ios::binary);
    if (!in || std::filesystem::is_directory(file, ec))
        throw Error(ErrorCode::FileUnreadable, file, "cannot read file");
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw Error(ErrorCode::Malformed, file, std::string("bad JSON: ") + e.what());
    }
    if (!j.is_object()) throw Error(ErrorCode::Malformed, file, "expected a JSON object");
    CameraPath path;
    if (j.contains("up")) {
        path.up = readVec3(j["up"], file, "\"up\"");
        if (glm::length(path.up) <= 0.0) throw Error(ErrorCode::Malformed, file, "\"up\" is zero");
        path.up = glm::normalize(path.up);
    }
    if (j.contains("fov_deg")) {
        if (!j["fov_deg"].is_number())
            throw Error(ErrorCode::Malformed, file, "\"fov_deg\" must be a number");
        path.fovYDegrees = j["fov_deg"].get<double>();
        if (!(path.fovYDegrees > 0.0 && path.fovYDegrees < 180.0))
            throw Error(ErrorCode::Malformed, file, "\"fov_deg\" must be in (0, 180)");
    }
    if (!j.contains("keys") || !j["keys"].is_array() || j["keys"].size() < 2)
        throw Error(ErrorCode::Malformed, file, "\"keys\" must be an array of at least 2 keys");
    Aabb extent;
    for (std::size_t i = 0; i < j["keys"].size(); ++i) {
        const nlohmann::json& k = j["keys"][i];
        const std::string where = "key " + std::to_string(i);
        if (!k.is_object() || !k.contains("t") || !k["t"].is_number() || !k.contains("eye") ||
            !k.contains("target"))
            throw Error(ErrorCode::Malformed, file,
                        where + " needs \"t\" (number), \"eye\" and \"target\"");
        CameraKey key;
        key.time = k["t"].get<double>();
        if (!std::isfinite(key.time))
            throw Error(ErrorCode::Malformed, file, where + ": \"t\" is not finite");
        if (!path.keys.empty() && key.time <= path.keys.back().time)
            throw Error(ErrorCode::Malformed, file, where + ": times must increase strictly");
        key.eye = readVec3(k["eye"], file, where + " \"eye\"");
        key.target = readVec3(k["target"], file, where + " \"target\"");
        if (glm::length(key.eye - key.target) <= 0.0)
            throw Error(ErrorCode::Malformed, file, where + ": eye and target are the same point");
        extent.expand(key.eye);
        extent.expand(key.target);
        path.keys.push_back(key);
    }
    fitClipPlanes(path, extent);
    return path;
}

void writeCameraPath(const std::filesystem::path& file, const CameraPath& path) {
    nlohmann::json j;
    j["up"] = {path.up.x, path.up.y, path.up.z};
    j["fov_deg"] = path.fovYDegrees;
    j["keys"] = nlohmann::json::array();
    for (const CameraKey& k : path.keys) {
        j["keys"].push_back({{"t", k.time},
                             {"eye", {k.eye.x, k.eye.y, k.eye.z}},
                             {"target", {k.target.x, k.target.y, k.target.z}}});
    }
    writeFileAtomic(file, j.dump(2) + "\n");
}

std::vector<Camera> sampleCameraPath(const CameraPath& path, int frames, double fps, int width,
                                     int height) {
    if (frames < 1 || !(fps > 0.0))
        throw Error(ErrorCode::InvalidArgument, "camera path: frames and fps must be positive");
    std::vector<Camera> cams;
    cams.reserve(static_cast<std::size_t>(frames));
    const double start = path.keys.empty() ? 0.0 : path.keys.front().time;
    for (int i = 0; i < frames; ++i)
        cams.push_back(path.at(start + i / fps, width, height));
    return cams;
}

} // namespace hlod
