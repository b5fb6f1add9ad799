// The command line of `lab` and `course`: subcommands parsed by CLI11, the
// chosen one run, and each error printed as `TOOL: error: ...` with the exit
// status its type calls for (docs/contract.md, Exit status and errors).
// Header-only: the executables that include it link CLI11; the framework
// library does not.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <functional>
#include <vector>

#include "framework/error.hpp"

namespace fw::cli {

// A subcommand and what runs it once its options are parsed.
struct Command {
    CLI::App* app;
    std::function<int()> run;  // returns the exit status
};

// The exit status of a command that threw: `error` for an fw::Error (by its
// type), `internal` for any other exception. A usage error on the command
// line itself is 2 for every tool.
struct ExitStatus {
    int (*error)(const fw::Error&);
    int internal;
};

// Parses `argv` (exactly one subcommand of `app`), then runs the chosen command.
inline int run(CLI::App& app, int argc, char** argv, const std::vector<Command>& commands,
               const char* tool, ExitStatus exit) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        const std::vector<CLI::App*> chosen = app.get_subcommands();
        std::fprintf(stderr, "%s: %s\nRun '%s --help' or '%s %s --help' for usage.\n", tool,
                     e.what(), tool, tool,
                     chosen.empty() ? "COMMAND" : chosen[0]->get_name().c_str());
        return 2;
    }
    try {
        for (const Command& command : commands)
            if (*command.app) return command.run();
    } catch (const fw::Error& e) {
        std::fprintf(stderr, "%s: error: %s\n", tool, e.what());
        return exit.error(e);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: internal error: %s\n", tool, e.what());
        return exit.internal;
    }
    return 0;
}

}  // namespace fw::cli
