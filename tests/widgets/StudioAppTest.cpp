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
    QString stdoutText;
    QString stderrText;
};

StudioRun runStudio(const QStringList& args, const QStringList& extraEnvironment = {},
                    const QStringList& unset = {}) {
    QProcess process;
    QStringList environment = QProcess::systemEnvironment();
    environment << extraEnvironment;
    for (const QString& name : unset)
        environment.removeIf([&](const QString& e) { return e.startsWith(name + '='); });
    process.setEnvironment(environment);
    process.start(kStudio, args);
    StudioRun run;
    if (!process.waitForFinished(120000)) {
        process.kill();
        process.waitForFinished();
        return run;
    }
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
    run.stdoutText = QString::fromUtf8(process.readAllStandardOutput());
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

TEST_F(StudioApp, WithoutADisplayItSaysSoInsteadOfAborting) {
    const StudioRun run = runStudio({}, {},
                                    {QStringLiteral("DISPLAY"), QStringLiteral("WAYLAND_DISPLAY"),
                                     QStringLiteral("QT_QPA_PLATFORM")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.stderrText.contains(QStringLiteral("no display")))
        << run.stderrText.toStdString();
    // --help needs none.
    const StudioRun help =
        runStudio({QStringLiteral("--help")}, {},
                  {QStringLiteral("DISPLAY"), QStringLiteral("WAYLAND_DISPLAY")});
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_TRUE(help.stdoutText.contains(QStringLiteral("PROJECT.hlodproj")));
}

TEST_F(StudioApp, ScreenshotOfTheSampleSceneHasTheRequestedSize) {
    const QString out = dir.filePath(QStringLiteral("sample.png"));
    const StudioRun run = runStudio(
        {QStringLiteral("--screenshot"), out, QStringLiteral("--size"), QStringLiteral("900x640")});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText.toStdString();
    const QImage image(out);
    EXPECT_EQ(image.size(), QSize(900, 640));
}

TEST_F(StudioApp, ViewportOnlyScreenshotIsSmallerThanTheWindow) {
    const QString out = dir.filePath(QStringLiteral("view.png"));
    const StudioRun run =
        runStudio({QStringLiteral("--screenshot"), out, QStringLiteral("--viewport-only"),
                   QStringLiteral("--size"), QStringLiteral("900x640")});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText.toStdString();
    const QImage image(out);
    ASSERT_FALSE(image.isNull());
    EXPECT_LT(image.width(), 900);  // the scene dock takes part of the width
    EXPECT_LT(image.height(), 640); // menu, log dock and status bar take part of the height
}

TEST_F(StudioApp, BuildsAndScreenshotsEachDisplayMode) {
    // --mode clusters and hlod imply --build: the screenshot waits for the HLOD of the sample.
    for (const char* mode : {"original", "clusters", "hlod"}) {
        const QString out = dir.filePath(QStringLiteral("%1.png").arg(QLatin1String(mode)));
        const StudioRun run = runStudio(
            {QStringLiteral("--mode"), QLatin1String(mode), QStringLiteral("--level"),
             QStringLiteral("2"), QStringLiteral("--viewport-only"), QStringLiteral("--screenshot"),
             out, QStringLiteral("--size"), QStringLiteral("900x640")});
        ASSERT_EQ(run.exitCode, 0) << mode << ": " << run.stderrText.toStdString();
        EXPECT_FALSE(QImage(out).isNull()) << mode;
    }
}

TEST_F(StudioApp, BadModeOrLevelExitsWithCodeTwo) {
    StudioRun run = runStudio({QStringLiteral("--mode"), QStringLiteral("wireframe")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.stderrText.contains(QStringLiteral("--mode")));
    run = runStudio({QStringLiteral("--level"), QStringLiteral("-1")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.stderrText.contains(QStringLiteral("--level")));
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
    EXPECT_TRUE(run.stderrText.contains(QStringLiteral("broken.gltf")))
        << run.stderrText.toStdString();
    EXPECT_FALSE(QFileInfo::exists(out));
}

TEST_F(StudioApp, BadSizeArgumentExitsWithCodeTwo) {
    const StudioRun run = runStudio({QStringLiteral("--size"), QStringLiteral("huge")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.stderrText.contains(QStringLiteral("--size")));
}

TEST_F(StudioApp, BadOrbitArgumentExitsWithCodeTwo) {
    const StudioRun run = runStudio({QStringLiteral("--orbit"), QStringLiteral("30")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.stderrText.contains(QStringLiteral("--orbit")));
}

TEST_F(StudioApp, WithoutOpenGlTheWindowExplainsInsteadOfCrashing) {
    // QT_XCB_GL_INTEGRATION=none takes GLX away from Qt: no context can be created at all.
    const QString out = dir.filePath(QStringLiteral("nogl.png"));
    const StudioRun run = runStudio({QStringLiteral("--screenshot"), out},
                                    {QStringLiteral("QT_XCB_GL_INTEGRATION=none")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.stderrText.contains(QStringLiteral("OpenGL 3.2 is not available")))
        << run.stderrText.toStdString();
    EXPECT_FALSE(QImage(out).isNull()); // the window, with the explanation in the centre
}

TEST_F(StudioApp, SwedishLocaleLoadsTheSwedishTranslation) {
    // The help text comes from tr(): in a Swedish locale it must come out of
    // :/translations/hlod-studio_sv.qm, proving the resource path and the locale check.
    const StudioRun run =
        runStudio({QStringLiteral("--help")},
                  {QStringLiteral("LANG=sv_SE.UTF-8"), QStringLiteral("LC_ALL=sv_SE.UTF-8"),
                   QStringLiteral("LANGUAGE=sv")});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_TRUE(run.stdoutText.contains(QStringLiteral("Spara en skärmbild")))
        << run.stdoutText.toStdString();
}

} // namespace
