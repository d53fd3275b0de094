// End-to-end tests of the hlod-studio executable: screenshot mode and failure exit codes.
// They run the built binary (build hlod-studio before the tests) in the same X display.
#include <gtest/gtest.h>

#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>

namespace {

const QString kStudio = QStringLiteral(HLOD_BINARY_DIR "/app/hlod-studio");

struct StudioRun {
    int exitCode = -1;
    QString stderrText;
};

StudioRun runStudio(const QStringList& args) {
    QProcess process;
    process.start(kStudio, args);
    StudioRun run;
    if (!process.waitForFinished(120000)) {
        process.kill();
        process.waitForFinished();
        return run;
    }
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
    run.stderrText = QString::fromLocal8Bit(process.readAllStandardError());
    return run;
}

class StudioApp : public ::testing::Test {
protected:
    void SetUp() override {
        if (!QFileInfo::exists(kStudio))
            GTEST_SKIP() << "build the hlod-studio target first: " << kStudio.toStdString();
    }
    QTemporaryDir dir;
};

TEST_F(StudioApp, ScreenshotOfTheSampleSceneHasTheRequestedSize) {
    const QString out = dir.filePath(QStringLiteral("sample.png"));
    const StudioRun run = runStudio({QStringLiteral("--screenshot"), out, QStringLiteral("--size"),
                               QStringLiteral("900x640")});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText.toStdString();
    const QImage image(out);
    EXPECT_EQ(image.size(), QSize(900, 640));
}

TEST_F(StudioApp, ViewportOnlyScreenshotIsSmallerThanTheWindow) {
    const QString out = dir.filePath(QStringLiteral("view.png"));
    const StudioRun run = runStudio({QStringLiteral("--screenshot"), out, QStringLiteral("--viewport-only"),
                               QStringLiteral("--size"), QStringLiteral("900x640")});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText.toStdString();
    const QImage image(out);
    ASSERT_FALSE(image.isNull());
    EXPECT_LT(image.width(), 900); // the scene dock takes part of the width
    EXPECT_LT(image.height(), 640); // menu, log dock and status bar take part of the height
}

TEST_F(StudioApp, BrokenFileExitsWithCodeOneAndNamesTheFile) {
    const QString broken = dir.filePath(QStringLiteral("broken.gltf"));
    QFile file(broken);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("{ \"asset\": ");
    file.close();
    const QString out = dir.filePath(QStringLiteral("never.png"));
    const StudioRun run = runStudio({broken, QStringLiteral("--screenshot"), out});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.stderrText.contains(QStringLiteral("broken.gltf"))) << run.stderrText.toStdString();
    EXPECT_FALSE(QFileInfo::exists(out));
}

TEST_F(StudioApp, BadSizeArgumentExitsWithCodeTwo) {
    const StudioRun run = runStudio({QStringLiteral("--size"), QStringLiteral("huge")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.stderrText.contains(QStringLiteral("--size")));
}

} // namespace
