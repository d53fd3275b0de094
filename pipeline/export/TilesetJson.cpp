// tileset.json after OGC 3D Tiles 1.1 (sections 5.1 tiles, 5.3 coordinate reference system and
// tile transforms, 5.5 bounding volumes "box", 5.7 geometric error, 5.8 refinement), from the
// layout of PackageLayout.h. See Package.h for the axis convention and why the geometric error
// is the proxy error.
//
// Transforms: a tile's `transform` maps its frame to its parent's (5.3.3), so it is
// inverse(parent frame) x frame, moved from our Y-up package frame into the Z-up tileset
// frame: A x M x inverse(A) with A: (x, y, z) -> (x, -z, y). Content is glTF and Y up; the
// runtime turns it Z up before the tile transforms apply (5.3.4), which is what A does to the
// package frame.
// Boxes: in the tile's frame: its whole box, content and children (axis-aligned in the package
// frame, PackageLayout.h), relative to its origin; in a turned frame that box is written as an
// oriented box (the package's axes seen from the tile's frame), its numbers in full and grown
// by far more than the double rounding of the turn (turnedBoxVolume).
#include <algorithm>

#include "pipeline/export/JsonNumbers.h"
#include "pipeline/export/Package.h"

namespace hlod {

namespace {

// (x, y, z)_Y-up -> (x, -z, y)_Z-up as a matrix (columns are the images of the axes).
const glm::dmat4 kYupToZup(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 0, 1, 0), glm::dvec4(0, -1, 0, 0),
                           glm::dvec4(0, 0, 0, 1));

nlohmann::json matrixJson(const glm::dmat4& m) {
    nlohmann::json t = nlohmann::json::array();
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            // 0 and 1 as integers (no "-0.0", and most of a translation's 16 numbers are these)
            if (m[c][r] == 0.0 || m[c][r] == 1.0)
                t.push_back(static_cast<int>(m[c][r]));
            else
                t.push_back(m[c][r]);
    }
    return t;
}

// A Y-up box as a Z-up 3D Tiles box, rounded outward.
nlohmann::json boxVolume(const Aabb& b) {
    const glm::dvec3 cy = b.center(), hy = b.extent() * 0.5;
    const glm::dvec3 c(cy.x, -cy.z, cy.y), h(hy.x, hy.z, hy.y);
    nlohmann::json box = nlohmann::json::array();
    glm::dvec3 half;
    for (int a = 0; a < 3; ++a) {
        const double rc = shortNumber(c[a]);
        box.push_back(rc == 0.0 ? 0.0 : rc);
        half[a] = shortNumberUp(h[a] + std::abs(c[a] - rc));
    }
    for (int a = 0; a < 3; ++a) {
        for (int k = 0; k < 3; ++k)
            box.push_back(a == k ? half[a] : 0.0);
    }
    return box;
}

// The inverse of a rigid frame: exact for a translation (the identity's transpose is itself).
glm::dmat4 rigidInverse(const glm::dmat4& m) {
    const glm::dmat3 back = glm::transpose(glm::dmat3(m));
    glm::dmat4 out(back);
    out[3] = glm::dvec4(-(back * glm::dvec3(m[3])), 1.0);
    return out;
}

// A package-frame box seen from a turned frame, as a Z-up oriented box. Its numbers are written
// in full (shortest round trip): rounded to 7 digits, the turned half axes would poke out of
// the parent's box by the rounding (1e-6 of the box), more than the containment a validator
// accepts. Grown by 1e-9 of the box and its distance from the origin, far above the double
// rounding of turning it and far below any tolerance.
nlohmann::json turnedBoxVolume(const Aabb& b, const glm::dmat4& frame) {
    const glm::dmat3 back = glm::transpose(glm::dmat3(frame));
    const glm::dmat3 zUp(kYupToZup);
    const glm::dvec3 origin(frame[3]);
    const glm::dvec3 c = zUp * (back * (b.center() - origin));
    const glm::dvec3 h = b.extent() * 0.5;
    const double grow = 1e-9 * (h.x + h.y + h.z + glm::length(b.center()) + glm::length(origin));
    nlohmann::json box = nlohmann::json::array();
    for (int k = 0; k < 3; ++k)
        box.push_back(c[k] + 0.0); // no negative zeros
    for (int a = 0; a < 3; ++a) {
        glm::dvec3 axis(0.0);
        axis[a] = h[a] + grow;
        const glm::dvec3 turned = zUp * (back * axis);
        for (int k = 0; k < 3; ++k)
            box.push_back(turned[k] + 0.0);
    }
    return box;
}

nlohmann::json boundingBox(const TilePlan& t) {
    if (glm::dmat3(t.frame) != glm::dmat3(1.0)) return turnedBoxVolume(t.worldBox, t.frame);
    const glm::dvec3 o(t.frame[3]);
    return boxVolume(Aabb{t.worldBox.min - o, t.worldBox.max - o});
}

nlohmann::json tile(const PackageLayout& layout, int index,
                    const std::vector<std::string>& contentUris,
                    const std::optional<GeoLocation>& geo) {
    const TilePlan& t = layout.tiles[static_cast<std::size_t>(index)];
    nlohmann::json j;
    glm::dmat4 m = t.frame;
    if (t.parent >= 0)
        m = rigidInverse(layout.tiles[static_cast<std::size_t>(t.parent)].frame) * t.frame;
    glm::dmat4 z = kYupToZup * m * glm::inverse(kYupToZup);
    if (t.parent < 0 && geo) z = enuToEcef(*geo) * z;
    if (z != glm::dmat4(1.0)) j["transform"] = matrixJson(z);
    j["boundingVolume"] = {{"box", boundingBox(t)}};
    j["geometricError"] = shortNumberUp(t.geometricError);
    if (t.content >= 0) j["content"] = {{"uri", contentUris[static_cast<std::size_t>(t.content)]}};
    if (!t.children.empty()) {
        nlohmann::json children = nlohmann::json::array();
        for (int c : t.children)
            children.push_back(tile(layout, c, contentUris, geo));
        j["children"] = std::move(children);
    }
    return j;
}

} // namespace

nlohmann::json buildTileset(const PackageLayout& layout,
                            const std::vector<std::string>& contentUris,
                            const std::optional<GeoLocation>& geo) {
    nlohmann::json root = tile(layout, 0, contentUris, geo);
    root["refine"] = "REPLACE"; // inherited by every descendant
    // Error when nothing is drawn: the whole model's size, so a runtime shows the root as soon
    // as the tileset is in view.
    const TilePlan& r = layout.tiles[0];
    const double top = std::max(r.worldBox.diagonal(), r.geometricError * 2.0);
    return {
        {"asset", {{"version", "1.1"}, {"generator", std::string("HLOD Studio ") + HLOD_VERSION}}},
        {"geometricError", shortNumberUp(std::max(top, 1e-3))},
        {"root", std::move(root)}};
}

} // namespace hlod
