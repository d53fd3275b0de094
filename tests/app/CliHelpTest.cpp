// `hlod` as a first-time user meets it (issue 20): `hlod` alone, `hlod --help`, `hlod help
// COMMAND` and `hlod COMMAND --help` print the usage with every flag, its default, unit and
// range, generated from the parameter declarations the editor's panel uses; a mistyped flag
// or command names the closest valid one.
#include <gtest/gtest.h>

#include <string>

#include "RunCli.h"
#include "pipeline/graph/Parameters.h"

using hlod::test::runCli;

namespace {

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

TEST(CliHelp, NoArgumentsPrintsTheShortUsageOnStderr) {
    const auto r = runCli({});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(r.out.empty());
    for (const char* line : {"hlod info", "hlod cluster", "hlod build", "hlod plan", "hlod bench",
                             "hlod help [COMMAND]", "hlod --version"})
        EXPECT_TRUE(contains(r.err, line)) << line << "\n" << r.err;
    // Short: the synopses and a pointer to the rest, not every flag.
    EXPECT_FALSE(contains(r.err, "--screen-size")) << r.err;
    EXPECT_TRUE(contains(r.err, "hlod help COMMAND")) << r.err;
}

TEST(CliHelp, BuildHelpListsEveryDeclaredFlagWithDefaultUnitAndRange) {
    const auto r = runCli({"build", "--help"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const hlod::ParamDecl& d : hlod::parameterDeclarations())
        if (!d.cliFlag.empty()) {
            EXPECT_TRUE(contains(r.out, "  " + d.cliFlag)) << d.cliFlag;
        }
    // The screen size: placeholder, default with its unit, range (Parameters.cpp: 300 px in
    // [1, 100000]).
    EXPECT_TRUE(contains(r.out, "--screen-size PX")) << r.out;
    EXPECT_TRUE(contains(r.out, "Default 300 px; 1 to 100000 px.")) << r.out;
    EXPECT_TRUE(contains(r.out, "--volume sphere|aabb|octree|original")) << r.out;
    EXPECT_TRUE(contains(r.out, "-o, --output DIR")) << r.out;
    EXPECT_TRUE(contains(r.out, "--no-cache")) << r.out;
    EXPECT_TRUE(contains(r.out, "--json")) << r.out;
    EXPECT_TRUE(contains(r.out, "Usage: hlod build")) << r.out;
}

TEST(CliHelp, HelpCommandAndHelpFlagPrintTheSame) {
    for (const char* command : {"info", "cluster", "build", "plan", "bench"}) {
        const auto a = runCli({"help", command});
        const auto b = runCli({command, "--help"});
        const auto c = runCli({command, "-h"});
        EXPECT_EQ(a.exitCode, 0) << command;
        EXPECT_EQ(b.exitCode, 0) << command;
        EXPECT_EQ(a.out, b.out) << command;
        EXPECT_EQ(a.out, c.out) << command;
        EXPECT_TRUE(contains(a.out, std::string("Usage: hlod ") + command)) << a.out;
    }
}

TEST(CliHelp, EachCommandListsOnlyTheFlagsItTakes) {
    const auto cluster = runCli({"help", "cluster"});
    EXPECT_TRUE(contains(cluster.out, "  --k K")) << cluster.out;
    EXPECT_TRUE(contains(cluster.out, "  --deflection R")) << cluster.out;
    EXPECT_FALSE(contains(cluster.out, "--proxy ")) << cluster.out;
    const auto bench = runCli({"help", "bench"});
    EXPECT_TRUE(contains(bench.out, "--frames N")) << bench.out;
    EXPECT_TRUE(contains(bench.out, "--size WxH")) << bench.out;
    EXPECT_TRUE(contains(bench.out, "640x360.")) << bench.out;
}

TEST(CliHelp, FullHelpHasEveryCommandAndItsFlags) {
    const auto r = runCli({"--help"});
    ASSERT_EQ(r.exitCode, 0);
    EXPECT_EQ(runCli({"help"}).out, r.out);
    for (const char* usage :
         {"Usage: hlod info", "Usage: hlod cluster", "Usage: hlod build", "Usage: hlod bench"})
        EXPECT_TRUE(contains(r.out, usage)) << usage;
    EXPECT_TRUE(contains(r.out, "--proxy-ratio R")) << r.out;
}

TEST(CliHelp, AMistypedFlagNamesTheClosestValidOne) {
    const auto r = runCli({"build", "--screensize", "200"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, "hlod build: error: unknown option --screensize (did you mean "
                     "--screen-size?)\n");
    const auto cut = runCli({"build", "--pixel", "2"});
    EXPECT_TRUE(contains(cut.err, "(did you mean --pixel-error?)")) << cut.err;
    // Nothing close: no guess.
    const auto far = runCli({"info", "--bogus"});
    EXPECT_EQ(far.err, "hlod info: error: unknown option --bogus\n");
}

TEST(CliHelp, AMistypedCommandNamesTheClosestOne) {
    const auto r = runCli({"biuld", "scene.glb"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, "hlod: error: unknown command 'biuld' (did you mean build?)\n");
    EXPECT_EQ(runCli({"help", "clsuter"}).err,
              "hlod help: error: unknown command 'clsuter' (did you mean cluster?)\n");
}
