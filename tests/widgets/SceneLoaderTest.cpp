// Tests of widgets/SceneLoader with widgets/LogView: background loads, errors, cancellation.
#include <gtest/gtest.h>

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include "widgets/LogView.h"
#include "widgets/SceneActors.h"
#include "widgets/SceneLoader.h"

namespace hlod::widgets {
namespace {

// Wires loader and log the way MainWindow does.
struct LoaderWithLog {
    SceneLoader loader;
    LogView log;
    QSignalSpy loaded{&loader, &SceneLoader::loaded};
    QSignalSpy failed{&loader, &SceneLoader::failed};
    LoaderWithLog() {
        QObject::connect(&loader, &SceneLoader::failed, &log,
                         [this](const QStringList&, const QString& m) { log.error(m); });
    }
    bool waitForResult() {
        return loaded.count() + failed.count() > 0 ||
               QTest::qWaitFor([this] { return loaded.count() + failed.count() > 0; }, 60000);
    }
};

TEST(SceneLoader, EmptyListLoadsTheSampleSceneWithRenderData) {
    LoaderWithLog t;
    t.loader.load({});
    EXPECT_TRUE(t.loader.busy());
    ASSERT_TRUE(t.waitForResult());
    ASSERT_EQ(t.loaded.count(), 1);
    const auto result = t.loaded.front().front().value<LoadedScene>();
    ASSERT_NE(result.scene, nullptr);
    ASSERT_NE(result.actors, nullptr);
    EXPECT_GT(result.scene->instances.size(), 0u);
    EXPECT_EQ(result.actors->instanceCount(), result.scene->instances.size());
    EXPECT_TRUE(result.files.isEmpty());
    EXPECT_FALSE(t.loader.busy());
}

TEST(SceneLoader, BrokenFileShowsAnErrorInTheLogAndDoesNotCrash) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("broken.glb"));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("glTF this is not a binary glTF container at all");
    file.close();

    LoaderWithLog t;
    t.loader.load({path});
    ASSERT_TRUE(t.waitForResult());
    EXPECT_EQ(t.loaded.count(), 0);
    ASSERT_EQ(t.failed.count(), 1);
    EXPECT_EQ(t.log.errorCount(), 1);
    // The message names the file, so the user knows which of several inputs is bad.
    EXPECT_TRUE(t.log.toPlainText().contains(QStringLiteral("broken.glb")))
        << t.log.toPlainText().toStdString();
    EXPECT_FALSE(t.loader.busy());
}

TEST(SceneLoader, MissingFileIsReportedByName) {
    LoaderWithLog t;
    t.loader.load({QStringLiteral("/nonexistent/folder/missing.gltf")});
    ASSERT_TRUE(t.waitForResult());
    ASSERT_EQ(t.failed.count(), 1);
    EXPECT_TRUE(t.failed.front().at(1).toString().contains(QStringLiteral("missing.gltf")));
}

TEST(SceneLoader, ANewLoadReplacesTheRunningOne) {
    LoaderWithLog t;
    t.loader.load({QStringLiteral("/nonexistent/first.glb")});
    t.loader.load({}); // the sample: only its result may arrive
    ASSERT_TRUE(t.waitForResult());
    QTest::qWait(200); // give a stray result of the first load time to show up
    EXPECT_EQ(t.failed.count(), 0);
    EXPECT_EQ(t.loaded.count(), 1);
}

TEST(SceneLoader, DestroyingTheLoaderWhileBusyJoinsItsWorker) {
    auto loader = std::make_unique<SceneLoader>();
    QSignalSpy loaded(loader.get(), &SceneLoader::loaded);
    loader->load({});
    loader.reset(); // cancels and joins; no result is delivered to a dead object
    QTest::qWait(100);
    EXPECT_EQ(loaded.count(), 0);
}

} // namespace
} // namespace hlod::widgets
