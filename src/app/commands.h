// The subcommands. Each adds its flags to the CLI and runs; errors are thrown as tumble::Error and
// turned into exit codes by main.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace tumble {

// Adds a subcommand to `app` and returns the function that runs it once parsed.
std::function<int()> addRenderCommand(CLI::App& app);
std::function<int()> addSimulateCommand(CLI::App& app);
std::function<int()> addCheckCommand(CLI::App& app);
std::function<int()> addJoinCommand(CLI::App& app);
// diff returns 0/1/2 (pass, fail, bad input) itself, as diff tools do; it throws nothing.
std::function<int()> addDiffCommand(CLI::App& app);

}  // namespace tumble
