// Procedural primitives: textbook parametrisations (box faces, cylinder side + fan caps,
// latitude/longitude sphere).
#include "pipeline/scene/Primitives.h"

#include <cmath>

namespace hlod {

namespace {

constexpr float kPi = 3.14159265358979f;

void addQuad(Mesh& m, const glm::vec3& o, const glm::vec3& u, const glm::vec3& v) {
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    const glm::vec3 n = glm::normalize(glm::cross(u, v));
    for (const glm::vec3& p : {o, o + u, o + u + v, o + v}) {
        m.positions.push_back(p);
        m.normals.push_back(n);
    }
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

} // namespace

Mesh makeBox(const glm::vec3& size) {
    Mesh m;
    m.name = "box";
    const glm::vec3 h = size * 0.5f;
    const glm::vec3 x(size.x, 0, 0), y(0, size.y, 0), z(0, 0, size.z);
    addQuad(m, {-h.x, -h.y, h.z}, x, y);  // +Z
    addQuad(m, {h.x, -h.y, -h.z}, -x, y); // -Z
    addQuad(m, {h.x, -h.y, h.z}, -z, y);  // +X
    addQuad(m, {-h.x, -h.y, -h.z}, z, y); // -X
    addQuad(m, {-h.x, h.y, h.z}, x, -z);  // +Y
    addQuad(m, {-h.x, -h.y, -h.z}, x, z); // -Y
    return m;
}

Mesh makeCylinder(float radius, float height, int segments) {
    Mesh m;
    m.name = "cylinder";
    const auto s = static_cast<std::uint32_t>(segments);
    for (std::uint32_t i = 0; i <= s; ++i) { // side, seam duplicated for clean normals
        const float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(s);
        const glm::vec3 n(std::cos(a), 0.0f, -std::sin(a));
        m.positions.push_back(n * radius);
        m.positions.push_back(n * radius + glm::vec3(0, height, 0));
        m.normals.push_back(n);
        m.normals.push_back(n);
    }
    for (std::uint32_t i = 0; i < s; ++i) {
        const std::uint32_t a = 2 * i, b = 2 * i + 2;
        m.indices.insert(m.indices.end(), {a, b, b + 1, a, b + 1, a + 1});
    }
    for (int cap = 0; cap < 2; ++cap) {
        const float y = cap ? height : 0.0f;
        const glm::vec3 n(0, cap ? 1.0f : -1.0f, 0);
        const auto centre = static_cast<std::uint32_t>(m.positions.size());
        m.positions.push_back({0, y, 0});
        m.normals.push_back(n);
        for (std::uint32_t i = 0; i < s; ++i) {
            const float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(s);
            m.positions.push_back({radius * std::cos(a), y, -radius * std::sin(a)});
            m.normals.push_back(n);
        }
        for (std::uint32_t i = 0; i < s; ++i) {
            const std::uint32_t a = centre + 1 + i, b = centre + 1 + (i + 1) % s;
            if (cap)
                m.indices.insert(m.indices.end(), {centre, a, b});
            else
                m.indices.insert(m.indices.end(), {centre, b, a});
        }
    }
    return m;
}

Mesh makeSphere(float radius, int segments, int rings) {
    Mesh m;
    m.name = "sphere";
    for (int r = 0; r <= rings; ++r) {
        const float phi = kPi * static_cast<float>(r) / static_cast<float>(rings);
        for (int s = 0; s <= segments; ++s) {
            const float theta = 2.0f * kPi * static_cast<float>(s) / static_cast<float>(segments);
            const glm::vec3 n(std::sin(phi) * std::cos(theta), std::cos(phi),
                              -std::sin(phi) * std::sin(theta));
            m.positions.push_back(n * radius);
            m.normals.push_back(n);
        }
    }
    const auto row = static_cast<std::uint32_t>(segments + 1);
    for (std::uint32_t r = 0; r < static_cast<std::uint32_t>(rings); ++r) {
        for (std::uint32_t s = 0; s < static_cast<std::uint32_t>(segments); ++s) {
            const std::uint32_t a = r * row + s, b = a + row;
            if (r != 0) m.indices.insert(m.indices.end(), {a, b, a + 1});
            if (r + 1 != static_cast<std::uint32_t>(rings)) {
                m.indices.insert(m.indices.end(), {a + 1, b, b + 1});
            }
        }
    }
    return m;
}

} // namespace hlod
