#pragma once
// What `luxel` does: its arguments parsed (command_line.hpp) and the chosen command run. Apart from
// command_line.hpp so that main() does not compile the command-line parser's headers again.

namespace luxel::cli {

/// Parses `argv` (argv[0] is the program) and runs the command it chooses; the exit code: 0, 1 for
/// a file or resource that failed, 2 for a bad argument (one line on stderr in both cases).
int run(int argc, const char* const* argv);

}  // namespace luxel::cli
