#include "command_line.hpp"

#include <iostream>
#include <string>
#include <utility>

namespace luxel::cli {

CommandLine::CommandLine()
    : app_{"luxel - a CPU rasterizer for the DirectX 9-era Source engine shading pipeline"} {
  app_.require_subcommand(1);
  runners_ = {add_render_command(app_), add_compare_command(app_), add_cost_command(app_),
              add_export_command(app_), add_info_command(app_),    add_bake_command(app_),
              add_grade_command(app_),  add_report_command(app_)};
}

std::optional<int> CommandLine::parse(int argc, const char* const* argv) {
  // CLI11 would answer a mistyped command with "A subcommand is required", not naming it.
  if (argc > 1 && argv[1][0] != '-') {
    std::string names;
    bool known = false;
    for (const CLI::App* sub : std::as_const(app_).get_subcommands([](const CLI::App*) { return true; })) {
      names += (names.empty() ? "" : ", ") + sub->get_name();
      known = known || sub->get_name() == argv[1];
    }
    if (!known) {
      std::cerr << "luxel: '" << argv[1] << "' is not a command (" << names << "; see luxel --help)\n";
      return 2;
    }
  }
  try {
    app_.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app_.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app_.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "luxel: " << e.what() << " (see luxel --help)\n";
    return 2;
  }
  return std::nullopt;
}

int CommandLine::run() const {
  for (const Runner& runner : runners_) {
    const int code = runner();
    if (code >= 0) return code;
  }
  return 2;
}

int run(int argc, const char* const* argv) {
  CommandLine command_line;
  if (const std::optional<int> code = command_line.parse(argc, argv)) return *code;
  return command_line.run();
}

}  // namespace luxel::cli
