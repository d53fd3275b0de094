// hlod-studio: the HLOD Studio editor. Sets up OpenGL, translations and the command line, probes
// for an OpenGL 3.2 context before any window exists, then opens the main window.
//
//   hlod-studio [FILES...|PROJECT.hlodproj] [--screenshot OUT.png [--viewport-only]] [--size WxH]
//   [--orbit AZ,EL]
//               [--build] [--build-all] [--mode original|clusters|hlod] [--level N]
//               [--tint-depth] [--compare LEFT:RIGHT]
//
// With no file the embedded sample scene opens; a .hlodproj opens as a project (issue 20). --build
// runs the shown branch of the pipeline once the scene is loaded, --build-all every branch (each
// Bake node); --mode picks the display mode (clusters and hlod need a build and imply --build);
// --level the cluster level shown in Clusters mode; --tint-depth tints the HLOD preview's
// drawn nodes by their depth in the tree. --compare opens View ▸ Compare Configurations with
// two configurations (e.g. sphere:aabb-k2, see widgets/compare/CompareConfig.h); with
// --screenshot the comparison window is saved once both sides are built. --screenshot waits
// until the scene is loaded (and built) and rendered, saves the window (or only the 3D view)
// and exits: 0 on success, 1 when loading, building or saving fails, 2 when the arguments are
// wrong or OpenGL is unavailable (then the image shows the window with its explanation in
// place of the 3D view).
#include <cstdio>

#include <QApplication>
#include <QCommandLineParser>
#include <QLibraryInfo>
#include <QLocale>
#include <QPointF>
#include <QRegularExpression>
#include <QSurfaceFormat>
#include <QTranslator>

#include "MainWindow.h"
#include "widgets/GlSupport.h"
#include "widgets/StudioModel.h"
#include "widgets/compare/CompareConfig.h"

namespace {

void installTranslators(QCoreApplication& app) {
    // Swedish is the one translation we ship; Qt's own strings (dialog buttons) come from the
    // system's Qt translations when installed.
    const QLocale locale;
    if (locale.language() != QLocale::Swedish) return;
    auto* qt = new QTranslator(&app);
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
    auto* ours = new QTranslator(&app);
    if (ours->load(QStringLiteral(":/translations/hlod-studio_sv.qm")))
        QCoreApplication::installTranslator(ours);
}

struct Options {
    QStringList files;
    QString screenshot;
    bool viewportOnly = false;
    QSize size;
    QPointF orbit; // degrees added to the default view: azimuth, elevation
    MainWindow::StartupView startup;
    QString compare; // --compare LEFT:RIGHT
};

bool usage(const QString& message) {
    std::fprintf(stderr, "hlod-studio: %s\n", qPrintable(message));
    return false;
}

// --build, --mode, --level into `startup`; false (after printing why) on bad values.
bool parseStartup(const QCommandLineParser& parser, const QCommandLineOption& build,
                  const QCommandLineOption& buildAll, const QCommandLineOption& mode,
                  const QCommandLineOption& level, const QCommandLineOption& tint,
                  MainWindow::StartupView& startup) {
    startup.build = parser.isSet(build) || parser.isSet(buildAll);
    startup.buildAll = parser.isSet(buildAll);
    startup.tintByDepth = parser.isSet(tint);
    if (parser.isSet(mode)) {
        hlod::widgets::DisplayMode m;
        if (!hlod::widgets::displayModeFromString(parser.value(mode), m))
            return usage(QCoreApplication::translate(
                             "main", "--mode wants original, clusters or hlod, not \"%1\"")
                             .arg(parser.value(mode)));
        startup.mode = parser.value(mode).trimmed().toLower();
        startup.build = startup.build || m != hlod::widgets::DisplayMode::Original;
    }
    if (parser.isSet(level)) {
        bool ok = false;
        const int n = parser.value(level).toInt(&ok);
        if (!ok || n < 0)
            return usage(QCoreApplication::translate(
                             "main", "--level wants a cluster level (0 or more), not \"%1\"")
                             .arg(parser.value(level)));
        startup.level = n;
    }
    return true;
}

// --size and --orbit into `options`; false (after printing why) on bad values.
bool parseGeometry(const QCommandLineParser& parser, const QCommandLineOption& size,
                   const QCommandLineOption& orbit, Options& options) {
    if (parser.isSet(size)) {
        const auto match =
            QRegularExpression(QStringLiteral("^(\\d+)x(\\d+)$")).match(parser.value(size));
        if (!match.hasMatch() || match.captured(1).toInt() < 200 ||
            match.captured(2).toInt() < 150) {
            std::fprintf(stderr, "hlod-studio: %s\n",
                         qPrintable(QCoreApplication::translate(
                                        "main", "--size wants WIDTHxHEIGHT, at least 200x150, "
                                                "not \"%1\"")
                                        .arg(parser.value(size))));
            return false;
        }
        options.size = QSize(match.captured(1).toInt(), match.captured(2).toInt());
    }
    if (parser.isSet(orbit)) {
        const QStringList parts = parser.value(orbit).split(QLatin1Char(','));
        bool okAz = false, okEl = false;
        const double az = parts.size() == 2 ? parts[0].toDouble(&okAz) : 0.0;
        const double el = parts.size() == 2 ? parts[1].toDouble(&okEl) : 0.0;
        if (!okAz || !okEl) {
            std::fprintf(stderr, "hlod-studio: %s\n",
                         qPrintable(QCoreApplication::translate(
                                        "main", "--orbit wants two angles in degrees, AZ,EL, "
                                                "not \"%1\"")
                                        .arg(parser.value(orbit))));
            return false;
        }
        options.orbit = QPointF(az, el);
    }
    return true;
}

// Returns false (after printing why) on bad arguments.
bool parseOptions(QCoreApplication& app, Options& options) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "main", "HLOD Studio: build and inspect Hierarchical Level-of-Detail for 3D scenes."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        QStringLiteral("files"),
        QCoreApplication::translate("main", "Scene files or folders, opened as one scene; or one "
                                            ".hlodproj project (its scene, parameters and hand "
                                            "edits, built and shown)."),
        QStringLiteral("[FILES...|PROJECT.hlodproj]"));
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QCoreApplication::translate("main",
                                    "Save a screenshot once loaded and rendered, then quit."),
        QStringLiteral("OUT.png"));
    const QCommandLineOption viewportOnly(
        QStringLiteral("viewport-only"),
        QCoreApplication::translate("main", "With --screenshot: save only the 3D view."));
    const QCommandLineOption size(QStringLiteral("size"),
                                  QCoreApplication::translate("main", "Window size in pixels."),
                                  QStringLiteral("WxH"));
    const QCommandLineOption orbit(
        QStringLiteral("orbit"),
        QCoreApplication::translate("main", "Turn the initial view by AZ degrees around the up "
                                            "axis and tilt it by EL degrees, then fit."),
        QStringLiteral("AZ,EL"));
    const QCommandLineOption build(
        QStringLiteral("build"),
        QCoreApplication::translate("main", "Build the HLOD once the scene is loaded."));
    const QCommandLineOption buildAll(
        QStringLiteral("build-all"),
        QCoreApplication::translate("main", "Build every branch (each Bake node of the pipeline) "
                                            "once the scene is loaded."));
    const QCommandLineOption mode(
        QStringLiteral("mode"),
        QCoreApplication::translate("main", "Display mode: original, clusters or hlod (the "
                                            "last two build the HLOD first)."),
        QStringLiteral("MODE"));
    const QCommandLineOption level(
        QStringLiteral("level"),
        QCoreApplication::translate("main", "Cluster level shown in clusters mode."),
        QStringLiteral("N"));
    const QCommandLineOption tint(
        QStringLiteral("tint-depth"),
        QCoreApplication::translate("main", "HLOD preview: tint drawn nodes by tree depth."));
    const QCommandLineOption compare(
        QStringLiteral("compare"),
        QCoreApplication::translate("main", "Compare two branches side by side, e.g. "
                                            "sphere:aabb-k2 (also octree, original, current, "
                                            "@S for the screen size; #N: Bake node N)."),
        QStringLiteral("LEFT:RIGHT"));
    parser.addOptions(
        {screenshot, viewportOnly, size, orbit, build, buildAll, mode, level, tint, compare});
    parser.process(app);
    if (!parseStartup(parser, build, buildAll, mode, level, tint, options.startup)) return false;
    if (parser.isSet(compare)) {
        std::pair<hlod::widgets::CompareSide, hlod::widgets::CompareSide> sides;
        QString error;
        if (!hlod::widgets::parseSidePair(parser.value(compare), hlod::widgets::CompareConfig{},
                                          sides, &error))
            return usage(QStringLiteral("--compare: ") + error);
        options.compare = parser.value(compare);
    }

    options.files = parser.positionalArguments();
    options.screenshot = parser.value(screenshot);
    options.viewportOnly = parser.isSet(viewportOnly);
    return parseGeometry(parser, size, orbit, options);
}

void setApplicationNames() {
    QCoreApplication::setApplicationName(QStringLiteral("hlod-studio"));
    QCoreApplication::setOrganizationName(QStringLiteral("hlod"));
    QCoreApplication::setApplicationVersion(QStringLiteral(HLOD_VERSION));
}

// --help and --version print and exit without a window, so they work without a display (over
// ssh, and for help2man when the man page is made at build time).
bool onlyPrints(int argc, char* argv[]) {
    for (int i = 1; i < argc; ++i) {
        const QByteArray arg(argv[i]);
        if (arg == "--help" || arg == "-h" || arg == "-?" || arg == "--help-all" ||
            arg == "--version" || arg == "-v")
            return true;
    }
    return false;
}

// Qt aborts when it cannot reach a display; say why and what to do instead (exit code 2).
bool displayMissing() {
#if defined(Q_OS_LINUX)
    return qEnvironmentVariableIsEmpty("DISPLAY") &&
           qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") &&
           qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
#else
    return false;
#endif
}

} // namespace

int main(int argc, char* argv[]) {
    if (onlyPrints(argc, argv)) {
        QCoreApplication app(argc, argv);
        Q_INIT_RESOURCE(resources); // the translation
        setApplicationNames();
        installTranslators(app);
        Options options;
        return parseOptions(app, options) ? 0 : 2; // process() exits after printing
    }
    if (displayMissing()) {
        QCoreApplication app(argc, argv);
        Q_INIT_RESOURCE(resources); // the translation
        installTranslators(app);
        std::fprintf(stderr, "hlod-studio: %s\n",
                     qPrintable(QCoreApplication::translate(
                         "main", "no display to open a window on (DISPLAY and WAYLAND_DISPLAY "
                                 "are unset). Run it in a desktop session or under xvfb-run -a, "
                                 "or use the hlod command-line tool (hlod --help).")));
        return 2;
    }
    // Must precede QApplication: every GL context Qt creates later uses this format, and
    // sharing lets the viewport survive being moved between top-level windows.
    QSurfaceFormat::setDefaultFormat(hlod::widgets::viewportSurfaceFormat());
    QApplication::setAttribute(Qt::AA_ShareOpenGLContexts);

    QApplication app(argc, argv);
    Q_INIT_RESOURCE(resources); // the icons live in a static library
    setApplicationNames();
    QApplication::setApplicationDisplayName(QStringLiteral("HLOD Studio"));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/hlod-studio.png")));
    QApplication::setDesktopFileName(QStringLiteral("hlod-studio"));
    installTranslators(app);

    Options options;
    if (!parseOptions(app, options)) return 2;

    const hlod::widgets::GlProbeResult gl = hlod::widgets::probeOpenGl();
    const QString glProblem = gl.ok ? QString() : hlod::widgets::glUnavailableMessage(gl.problem);

    MainWindow window(glProblem);
    if (!options.screenshot.isEmpty())
        window.requestScreenshot(options.screenshot, options.viewportOnly);
    else
        window.restoreSettings();
    if (options.size.isValid()) window.resize(options.size);
    window.setInitialOrbit(options.orbit.x(), options.orbit.y());
    window.setStartupView(options.startup);
    if (!options.compare.isEmpty()) window.setStartupCompare(options.compare);
    window.show();
    window.openFiles(options.files);
    return app.exec();
}
