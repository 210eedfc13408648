#pragma once
// The `luxel` command line: every subcommand registered on one CLI::App, its arguments parsed, and
// the chosen command run. main() is run(); the CLI fuzz target (fuzz/cli_input.cpp) drives parse()
// alone, so that any argument vector a user can type is either accepted or refused with one line.

#include "commands.hpp"
#include "run.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <vector>

namespace luxel::cli {

class CommandLine {
 public:
  CommandLine();

  /// Parses `argv` (argv[0] is the program). nullopt: a command was chosen, run() runs it.
  /// Otherwise the exit code: 0 after --help printed on stdout, 2 after one line on stderr naming
  /// the argument and the problem.
  std::optional<int> parse(int argc, const char* const* argv);

  /// Runs the command parse() chose; its exit code.
  int run() const;

 private:
  CLI::App app_;
  std::vector<Runner> runners_;
};

}  // namespace luxel::cli
