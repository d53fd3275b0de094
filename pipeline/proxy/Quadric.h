// Plane quadrics of a triangle mesh for choosing and placing edge collapses.
//
// Based on: Garland & Heckbert, "Surface Simplification Using Quadric Error Metrics" (SIGGRAPH
// 1997): per vertex the sum of the squared distances to the planes of its faces, plus their
// constraint planes along feature edges (a plane through the edge, perpendicular to its face).
// Weights: a face plane weighs the square root of its area (so errors scale linearly with
// size, as meshoptimizer weighs them, which keeps silhouettes better than area weights); a
// constraint plane weighs kFeatureWeight per metre of edge length, so that sliding a vertex off
// a feature line costs more than leaving a face of similar size. Feature edges: border edges
// (one face), non-manifold edges (three or more), folds (two faces turned more than 140 degrees
// apart, a sheet's rim) and edges between inconsistently oriented faces.
// The error is a weighted mean squared distance (divided by the summed weight), not a bound:
// the simplifier's certificate is what bounds the deviation (MappingBound.h).
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace hlod {

struct Quadric {
    double a00 = 0, a01 = 0, a02 = 0, a11 = 0, a12 = 0, a22 = 0;
    double b0 = 0, b1 = 0, b2 = 0, c = 0, w = 0;

    void addPlane(const glm::dvec3& n, double d, double weight) {
        a00 += weight * n.x * n.x;
        a01 += weight * n.x * n.y;
        a02 += weight * n.x * n.z;
        a11 += weight * n.y * n.y;
        a12 += weight * n.y * n.z;
        a22 += weight * n.z * n.z;
        b0 += weight * n.x * d;
        b1 += weight * n.y * d;
        b2 += weight * n.z * d;
        c += weight * d * d;
        w += weight;
    }
    void add(const Quadric& q) {
        a00 += q.a00, a01 += q.a01, a02 += q.a02, a11 += q.a11, a12 += q.a12, a22 += q.a22;
        b0 += q.b0, b1 += q.b1, b2 += q.b2, c += q.c, w += q.w;
    }
    // Weighted mean squared distance of p to the planes.
    double error(const glm::dvec3& p) const {
        if (!(w > 0.0)) return 0.0;
        const double rx = a00 * p.x + a01 * p.y + a02 * p.z + b0;
        const double ry = a01 * p.x + a11 * p.y + a12 * p.z + b1;
        const double rz = a02 * p.x + a12 * p.y + a22 * p.z + b2;
        const double r = rx * p.x + ry * p.y + rz * p.z + b0 * p.x + b1 * p.y + b2 * p.z + c;
        return std::abs(r) / w;
    }
    // The point of least error, when the planes pin one down well (not a line or a plane).
    bool minimum(glm::dvec3& p) const;
};

// Per vertex (positions.size() entries in `out`, which must be zero on entry): its faces'
// planes and the constraint planes of its feature edges.
void addQuadrics(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                 std::vector<Quadric>& out);

} // namespace hlod
