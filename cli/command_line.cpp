#include "command_line.hpp"

#include <algorithm>
#include <iostream>
#include <string>

namespace luxel::cli {

CommandLine::CommandLine()
    : app_{"luxel - a CPU rasterizer for the DirectX 9-era Source engine shading pipeline"} {
  app_.require_subcommand(1);
  app_.failure_message([](const CLI::App* a, const CLI::Error& e) {
    return std::string(a->get_name().empty() ? "luxel" : a->get_name()) + ": " + e.what() + " (see --help)\n";
  });
  runners_ = {add_render_command(app_), add_compare_command(app_), add_cost_command(app_),
              add_export_command(app_), add_info_command(app_),    add_bake_command(app_),
              add_grade_command(app_),  add_report_command(app_)};
}

std::optional<int> CommandLine::parse(int argc, const char* const* argv) {
  // CLI11 would answer a mistyped command with "A subcommand is required", not naming it.
  const CLI::App& app = app_;
  const auto commands = app.get_subcommands([](const CLI::App*) { return true; });
  const auto named = [&](const CLI::App* sub) { return argc > 1 && sub->get_name() == argv[1]; };
  if (argc > 1 && argv[1][0] != '-' && std::none_of(commands.begin(), commands.end(), named)) {
    std::string names;
    for (const CLI::App* sub : commands) names += (names.empty() ? "" : ", ") + sub->get_name();
    std::cerr << "luxel: '" << argv[1] << "' is not a command (" << names << "; see luxel --help)\n";
    return 2;
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
