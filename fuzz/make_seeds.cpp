// Writes the generated seed inputs of the fuzz targets into FOLDER/<target>/ (scripts/fuzz.sh
// runs it before fuzzing): scenes in the isolated importers' wire format, bake-cache entries
// (with and without normals, a degenerate one) and camera paths, all made with the pipeline's
// own writers from tiny hand-built scenes, so they start the fuzzer on valid inputs.
// Usage: make_seeds FOLDER
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/proxy/ProxyCache.h"
#include "pipeline/scene/Primitives.h"
#include "pipeline/scene/SceneBinary.h"
#include "pipeline/select/CameraPath.h"

namespace fs = std::filesystem;
using namespace hlod;

namespace {

void put(const fs::path& file, const std::string& bytes) {
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << bytes;
}

Scene twoBoxes() {
    Scene s;
    const Id box = s.addMesh(makeBox({1.0f, 2.0f, 3.0f}));
    const Id a = s.addNode("a", 0);
    const Id b = s.addNode("b", a, glm::translate(glm::dmat4(1.0), glm::dvec3(4.0, 0.0, 0.0)));
    s.addInstance(box, a);
    s.addInstance(box, b);
    s.updateWorldTransforms();
    return s;
}

ProxyMesh proxyOf(const Mesh& m, bool normals) {
    ProxyMesh p;
    p.origin = {1.0, 2.0, 3.0};
    p.positions = m.positions;
    if (normals) p.normals = m.normals;
    p.colors.assign(m.positions.size(), glm::u8vec4(200, 100, 50, 255));
    p.indices = m.indices;
    return p;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_seeds FOLDER\n");
        return 2;
    }
    const fs::path out = argv[1];
    const Scene scene = twoBoxes();
    put(out / "scene/two-boxes.bin", writeSceneBinary(scene));
    Scene one;
    one.addInstance(one.addMesh(makeSphere(1.0f, 6, 4)), one.addNode("s", 0));
    put(out / "scene/sphere.bin", writeSceneBinary(one));

    const auto entry = [&](const char* name, std::uint64_t key, const ProxyMesh& p) {
        const std::vector<std::uint8_t> bytes = encodeProxy(key, p);
        // The control byte of fuzz_proxy_cache (fuzz/Targets.h): 1 = fix the checksum up.
        put(out / "proxy_cache" / name, "\x01" + std::string(bytes.begin(), bytes.end()));
    };
    entry("box-normals.hlodproxy", 0x1234, proxyOf(makeBox({1, 1, 1}), true));
    entry("cylinder.hlodproxy", 0xfeedbeef, proxyOf(makeCylinder(0.5f, 2.0f, 6), false));
    entry("empty.hlodproxy", 7, ProxyMesh{});

    fs::create_directories(out / "camera_path");
    CameraPath path = automaticCameraPath(scene);
    writeCameraPath(out / "camera_path/automatic.json", path);
    path.keys.resize(2);
    writeCameraPath(out / "camera_path/two-keys.json", path);
    return 0;
}
