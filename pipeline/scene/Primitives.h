// Procedural primitive meshes (unit-free: sizes in metres as given), used by the sample scene
// and by tests that need shapes with known areas, volumes and triangle counts.
// All are closed, outward-facing (counter-clockwise seen from outside), with normals.
#pragma once

#include "pipeline/scene/Scene.h"

namespace hlod {

// Axis-aligned box centred at the origin: 12 triangles, 24 vertices (flat normals).
Mesh makeBox(const glm::vec3& size);
// Cylinder along +Y from y=0 to y=height, capped: 4*segments triangles.
Mesh makeCylinder(float radius, float height, int segments);
// UV sphere: 2*segments*(rings-1) triangles.
Mesh makeSphere(float radius, int segments, int rings);

} // namespace hlod
