// Camera paths of `hlod bench` (CameraPath.h): the automatic path is deterministic, starts far
// and ends close, stays finite; JSON paths round-trip and bad files name themselves.
#include <gtest/gtest.h>

#include <cmath>

#include "TestUtil.h"
#include "pipeline/core/Error.h"
#include "pipeline/io/SampleScene.h"
#include "pipeline/select/CameraPath.h"

using namespace hlod;

namespace {

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

TEST(CameraPath, AutomaticIsDeterministicFarToCloseAndFinite) {
    const Scene scene = makeSampleScene();
    const CameraPath a = automaticCameraPath(scene);
    const CameraPath b = automaticCameraPath(scene);
    ASSERT_EQ(a.keys.size(), b.keys.size());
    EXPECT_DOUBLE_EQ(a.duration(), kAutomaticPathSeconds);
    const auto cams = sampleCameraPath(a, 300, 10.0, 640, 360);
    const auto again = sampleCameraPath(b, 300, 10.0, 640, 360);
    ASSERT_EQ(cams.size(), 300u);
    for (std::size_t i = 0; i < cams.size(); ++i) {
        EXPECT_EQ(cams[i].eye, again[i].eye);
        EXPECT_EQ(cams[i].target, again[i].target);
        ASSERT_TRUE(finite(cams[i].eye) && finite(cams[i].target)) << i;
        EXPECT_GT(cams[i].nearPlane, 0.0);
        EXPECT_GT(cams[i].farPlane, cams[i].nearPlane);
        EXPECT_GT(glm::length(cams[i].eye - cams[i].target), 0.0);
    }
    const Aabb bounds = scene.worldBounds();
    const double radius = bounds.diagonal() * 0.5;
    const double first = glm::length(cams.front().eye - cams.front().target);
    const double last = glm::length(cams.back().eye - cams.back().target);
    EXPECT_GT(first, radius);      // the whole scene in view
    EXPECT_LT(last, 0.3 * radius); // close up
    EXPECT_GT(first, 5.0 * last);
    // The far clip plane never cuts the scene.
    for (const Camera& c : cams)
        EXPECT_GE(c.farPlane, glm::length(c.eye - bounds.center()) + radius);
    // Frame 0 is the first key.
    EXPECT_EQ(cams.front().eye, a.keys.front().eye);
}

TEST(CameraPath, PassesThroughKeysAndClamps) {
    CameraPath p;
    p.keys = {
        {0.0, {0, 0, 10}, {0, 0, 0}}, {1.0, {10, 0, 10}, {1, 0, 0}}, {3.0, {10, 5, 0}, {2, 0, 0}}};
    EXPECT_EQ(p.at(1.0, 100, 100).eye, glm::dvec3(10, 0, 10));
    EXPECT_EQ(p.at(-5.0, 100, 100).eye, glm::dvec3(0, 0, 10));
    EXPECT_EQ(p.at(99.0, 100, 100).target, glm::dvec3(2, 0, 0));
    const Camera mid = p.at(2.0, 200, 100);
    EXPECT_TRUE(finite(mid.eye));
    EXPECT_DOUBLE_EQ(mid.aspect, 2.0);
    EXPECT_EQ(mid.viewportHeight, 100);
}

TEST(CameraPath, JsonRoundTrip) {
    hlod::test::TempDir dir;
    const CameraPath a = automaticCameraPath(makeSampleScene());
    writeCameraPath(dir / "path.json", a);
    const CameraPath b = readCameraPath(dir / "path.json");
    ASSERT_EQ(a.keys.size(), b.keys.size());
    EXPECT_EQ(a.up, b.up);
    for (std::size_t i = 0; i < a.keys.size(); ++i) {
        EXPECT_NEAR(glm::length(a.keys[i].eye - b.keys[i].eye), 0.0, 1e-9);
        EXPECT_NEAR(a.keys[i].time, b.keys[i].time, 1e-12);
    }
}

TEST(CameraPath, BadJsonNamesTheFile) {
    hlod::test::TempDir dir;
    auto expectMalformed = [&](const std::string& text, const std::string& what) {
        const auto file = hlod::test::writeFile(dir / "p.json", text);
        try {
            readCameraPath(file);
            ADD_FAILURE() << "accepted: " << text;
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ErrorCode::Malformed) << e.what();
            EXPECT_NE(std::string(e.what()).find("p.json"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    };
    expectMalformed("{not json", "bad JSON");
    expectMalformed("[1, 2]", "object");
    expectMalformed("{\"keys\": []}", "at least 2");
    expectMalformed(R"({"keys": [{"t": 0, "eye": [0,0,1], "target": [0,0,0]},
                                 {"t": 0, "eye": [0,0,2], "target": [0,0,0]}]})",
                    "increase");
    expectMalformed(R"({"keys": [{"t": 0, "eye": [0,0,1], "target": [0,0,0]},
                                 {"t": 1, "eye": [0,0], "target": [0,0,0]}]})",
                    "3 numbers");
    expectMalformed(R"({"keys": [{"t": 0, "eye": [0,0,0], "target": [0,0,0]},
                                 {"t": 1, "eye": [0,0,2], "target": [0,0,0]}]})",
                    "same point");
    expectMalformed(R"({"fov_deg": 200, "keys": []})", "fov_deg");
    EXPECT_THROW(readCameraPath(dir / "missing.json"), Error);
}

TEST(CameraPath, EmptySceneThrows) { EXPECT_THROW(automaticCameraPath(Scene()), Error); }

TEST(CameraPath, UpAxisFollowsTheSourceFormat) {
    Scene scene = makeSampleScene();
    EXPECT_EQ(automaticCameraPath(scene).up, glm::dvec3(0, 1, 0)); // sample: Y up
    scene.sourceFiles = {"/data/part.STEP"};
    EXPECT_EQ(automaticCameraPath(scene).up, glm::dvec3(0, 0, 1)); // CAD: Z up
}

TEST(CameraPath, CloseUpEyeStaysOutOfParts) {
    const Scene scene = makeSampleScene();
    const CameraPath path = automaticCameraPath(scene);
    const double sceneVolume = scene.worldBounds().volume();
    for (const CameraKey& k : path.keys) {
        if (k.time < 20.0) continue;
        for (Id i = 0; i < scene.instances.size(); ++i) {
            const Aabb b = scene.instanceBounds(i);
            if (b.volume() >= 0.25 * sceneVolume) continue;
            const bool inside =
                glm::all(glm::greaterThan(k.eye, b.min)) && glm::all(glm::lessThan(k.eye, b.max));
            EXPECT_FALSE(inside) << "t=" << k.time << " instance " << i;
        }
    }
}
