// Appends one mesh's geometry, placed by a matrix, to a merged mesh: what a leaf group's
// merged primitive is made of (TileContent.cpp) and what `hlod bench` draws for it.
// Positions go through `matrix`, normals through its inverse transpose (renormalised; a zero
// normal becomes +Y), and a mirroring matrix flips the winding so faces keep facing out. uvs and
// colours are copied as they are: callers merge only meshes that carry the same streams.
// Works on any pair of types with `positions`, `normals`, `uvs`, `colors` and `indices`
// vectors whose element types match (Mesh, and the export's prepared meshes).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_inverse.hpp>

namespace hlod {

// Returns the index of the first appended vertex.
template <class Out, class In>
std::uint32_t appendPlaced(Out& out, const In& in, const glm::dmat4& matrix) {
    const glm::dmat3 normalMatrix = glm::inverseTranspose(glm::dmat3(matrix));
    const auto base = static_cast<std::uint32_t>(out.positions.size());
    for (const glm::vec3& v : in.positions)
        out.positions.push_back(glm::vec3(matrix * glm::dvec4(glm::dvec3(v), 1.0)));
    for (const glm::vec3& n : in.normals) {
        const glm::dvec3 t = normalMatrix * glm::dvec3(n);
        const double len = glm::length(t);
        out.normals.push_back(len > 0.0 ? glm::vec3(t / len) : glm::vec3(0, 1, 0));
    }
    out.uvs.insert(out.uvs.end(), in.uvs.begin(), in.uvs.end());
    out.colors.insert(out.colors.end(), in.colors.begin(), in.colors.end());
    const bool mirrored = glm::determinant(glm::dmat3(matrix)) < 0.0;
    for (std::size_t t = 0; t + 2 < in.indices.size(); t += 3) {
        out.indices.push_back(base + in.indices[t]);
        out.indices.push_back(base + in.indices[t + (mirrored ? 2 : 1)]);
        out.indices.push_back(base + in.indices[t + (mirrored ? 1 : 2)]);
    }
    return base;
}

} // namespace hlod
