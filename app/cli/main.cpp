// `hlod`: the headless HLOD Studio. See README.md (CLI usage) and docs/architecture.md (the CLI
// runs the pipeline graph; where its contract is described).
// The commands and their flags are declared in CommandTable.cpp; the help is generated from
// those declarations and the pipeline's parameter declarations (Usage.h).
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "Commands.h"
#include "Usage.h"
#include "pipeline/core/Error.h"

namespace {

using hlod::cli::CommandSpec;

bool isHelp(const std::string& arg) { return arg == "--help" || arg == "-h"; }

std::string unknownCommand(const std::string& name) {
    std::vector<std::string> names;
    for (const CommandSpec& c : hlod::cli::commands())
        names.push_back(c.name);
    const std::string hint = hlod::cli::closestMatch(name, names);
    return "unknown command '" + name + "'" +
           (hint.empty() ? std::string(" (try hlod --help)") : " (did you mean " + hint + "?)");
}

// `hlod help [COMMAND]`.
int help(const std::vector<std::string>& args) {
    if (args.size() < 2) {
        std::fputs(hlod::cli::fullHelp().c_str(), stdout);
        return 0;
    }
    const CommandSpec* c = hlod::cli::findCommand(args[1]);
    if (!c) {
        std::fprintf(stderr, "hlod help: error: %s\n", unknownCommand(args[1]).c_str());
        return 2;
    }
    std::fputs(hlod::cli::commandHelp(*c).c_str(), stdout);
    return 0;
}

int run(const CommandSpec& c, const std::vector<std::string>& args) {
    try {
        return c.run(args);
    } catch (const hlod::Error& e) {
        std::fprintf(stderr, "hlod %s: error: %s\n", c.name.c_str(), e.what());
        return e.code() == hlod::ErrorCode::InvalidArgument ? 2 : 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "hlod %s: error: out of memory\n", c.name.c_str());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "hlod %s: error: %s\n", c.name.c_str(), e.what());
        return 1;
    }
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty()) {
        std::fputs(hlod::cli::shortUsage().c_str(), stderr);
        return 2;
    }
    if (isHelp(args[0])) {
        std::fputs(hlod::cli::fullHelp().c_str(), stdout);
        return 0;
    }
    if (args[0] == "help") return help(args);
    if (args[0] == "--version") {
        std::printf("hlod %s\n", HLOD_VERSION);
        return 0;
    }
    const CommandSpec* c = hlod::cli::findCommand(args[0]);
    if (!c) {
        std::fprintf(stderr, "hlod: error: %s\n", unknownCommand(args[0]).c_str());
        return 2;
    }
    for (std::size_t i = 1; i < args.size(); ++i) {
        if (!isHelp(args[i])) continue;
        std::fputs(hlod::cli::commandHelp(*c).c_str(), stdout);
        return 0;
    }
    return run(*c, std::vector<std::string>(args.begin() + 1, args.end()));
}
