// Small hand-built scenes and image measurements shared by the widget tests.
#include "TestScenes.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <QDir>
#include <QFileInfo>
#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/scene/Primitives.h"

namespace hlod::widgets::test {

namespace {

Mesh triangleMesh() {
    Mesh mesh;
    mesh.name = "tri";
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.normals.assign(3, {0, 0, 1});
    mesh.indices = {0, 1, 2};
    return mesh;
}

Mesh quadMesh() {
    Mesh mesh;
    mesh.name = "quad";
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    mesh.normals.assign(4, {0, 0, 1});
    mesh.indices = {0, 1, 2, 0, 2, 3};
    mesh.material = 1;
    return mesh;
}

int channelDiff(QRgb a, QRgb b) {
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                     std::abs(qBlue(a) - qBlue(b))});
}

} // namespace

Scene makeTinyScene() {
    Scene scene;
    Material red;
    red.name = "red";
    red.baseColor = {1.0f, 0.0f, 0.0f, 1.0f};
    scene.addMaterial(red);
    const Id tri = scene.addMesh(triangleMesh());
    const Id quad = scene.addMesh(quadMesh());
    const Id left = scene.addNode("left", 0, glm::translate(glm::dmat4(1.0), {10, 0, 0}));
    const Id group = scene.addNode("group", 0);
    const Id right = scene.addNode(
        "right", group, glm::scale(glm::translate(glm::dmat4(1.0), {0, 5, 0}), glm::dvec3(2.0)));
    scene.addInstance(tri, left);
    scene.addInstance(tri, right);
    scene.addInstance(quad, 0);
    scene.updateWorldTransforms();
    return scene;
}

Scene makeCubeGrid(int count) {
    Scene scene;
    Material red;
    red.name = "red";
    red.baseColor = {0.8f, 0.05f, 0.03f, 1.0f};
    const Id redId = scene.addMaterial(red);
    const Id grey = scene.addMesh(makeBox({1.0f, 1.0f, 1.0f}));
    Mesh redCube = makeBox({1.0f, 1.0f, 1.0f});
    redCube.material = redId;
    const Id redMesh = scene.addMesh(redCube);
    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 at(2.0 * (i % side), 0.6 * (i % 3), 2.0 * (i / side));
        const Id node =
            scene.addNode("cube " + std::to_string(i), 0, glm::translate(glm::dmat4(1.0), at));
        scene.addInstance(i % 5 == 0 ? redMesh : grey, node);
    }
    scene.updateWorldTransforms();
    return scene;
}

double foregroundShare(const QImage& image, const QImage& background, int threshold) {
    if (image.size() != background.size() || image.isNull()) return 0.0;
    const QImage a = image.convertToFormat(QImage::Format_RGB32);
    const QImage b = background.convertToFormat(QImage::Format_RGB32);
    qint64 count = 0;
    for (int y = 0; y < a.height(); ++y) {
        const auto* ra = reinterpret_cast<const QRgb*>(a.constScanLine(y));
        const auto* rb = reinterpret_cast<const QRgb*>(b.constScanLine(y));
        for (int x = 0; x < a.width(); ++x)
            count += channelDiff(ra[x], rb[x]) > threshold;
    }
    return static_cast<double>(count) / (static_cast<double>(a.width()) * a.height());
}

QRect foregroundBox(const QImage& image, const QImage& background, int threshold) {
    if (image.size() != background.size() || image.isNull()) return {};
    const QImage a = image.convertToFormat(QImage::Format_RGB32);
    const QImage b = background.convertToFormat(QImage::Format_RGB32);
    QRect box;
    for (int y = 0; y < a.height(); ++y) {
        const auto* ra = reinterpret_cast<const QRgb*>(a.constScanLine(y));
        const auto* rb = reinterpret_cast<const QRgb*>(b.constScanLine(y));
        for (int x = 0; x < a.width(); ++x)
            if (channelDiff(ra[x], rb[x]) > threshold) box |= QRect(x, y, 1, 1);
    }
    return box;
}

double meanAbsDifference(const QImage& a, const QImage& b) {
    if (a.size() != b.size() || a.isNull()) return 255.0;
    const QImage ia = a.convertToFormat(QImage::Format_RGB32);
    const QImage ib = b.convertToFormat(QImage::Format_RGB32);
    double sum = 0.0;
    for (int y = 0; y < ia.height(); ++y) {
        const auto* ra = reinterpret_cast<const QRgb*>(ia.constScanLine(y));
        const auto* rb = reinterpret_cast<const QRgb*>(ib.constScanLine(y));
        for (int x = 0; x < ia.width(); ++x)
            sum += std::abs(qRed(ra[x]) - qRed(rb[x])) + std::abs(qGreen(ra[x]) - qGreen(rb[x])) +
                   std::abs(qBlue(ra[x]) - qBlue(rb[x]));
    }
    return sum / (3.0 * ia.width() * ia.height());
}

double compareWithBaseline(const QImage& image, const QString& name) {
    const QString dir = QStringLiteral(HLOD_TEST_SOURCE_DIR "/widgets/baselines");
    const QString path = dir + QLatin1Char('/') + name + QStringLiteral(".png");
    if (qEnvironmentVariable("HLOD_UPDATE_BASELINES") == QLatin1String("1")) {
        QDir().mkpath(dir);
        image.convertToFormat(QImage::Format_RGB32).save(path);
        return 0.0;
    }
    const QImage baseline(path);
    if (baseline.isNull() || baseline.size() != image.size()) return -1.0;
    return meanAbsDifference(image, baseline);
}

} // namespace hlod::widgets::test
