// Small hand-built scenes and image measurements shared by the widget tests.
#pragma once

#include <QImage>
#include <QRect>
#include <QString>

#include "pipeline/scene/Scene.h"

namespace hlod::widgets::test {

// Two meshes, two materials, three instances:
//  mesh 0 "tri": one triangle (0,0,0) (1,0,0) (0,1,0), normals +Z, material 0 (default grey)
//  mesh 1 "quad": two triangles spanning (0,0,0)-(1,1,0) in the XY plane, material 1 (red)
//  node 1 "left"  (under root, translated by (10,0,0)):  instance 0 = tri
//  node 2 "group" (under root)  -> node 3 "right" (translated (0,5,0), scaled 2): instance 1 = tri
//  root: instance 2 = quad
Scene makeTinyScene();

// A scene with `count` unit cubes on a grid (12 triangles each), every fifth one red.
Scene makeCubeGrid(int count);

// Share of pixels (0..1) whose largest channel difference to `background` exceeds `threshold`.
double foregroundShare(const QImage& image, const QImage& background, int threshold = 24);
// Bounding box of those pixels; null when there are none.
QRect foregroundBox(const QImage& image, const QImage& background, int threshold = 24);
// Mean absolute difference over all RGB channels of all pixels, 0..255. Sizes must match.
double meanAbsDifference(const QImage& a, const QImage& b);

// Compares `image` with tests/widgets/baselines/<name>.png. With HLOD_UPDATE_BASELINES=1 in the
// environment, writes the baseline instead and returns 0. Returns the mean absolute difference,
// or a negative value when the baseline is missing or has another size.
double compareWithBaseline(const QImage& image, const QString& name);

} // namespace hlod::widgets::test
