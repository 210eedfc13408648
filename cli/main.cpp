// luxel: render stills, compare shader models, count shader costs, export and describe scenes, bake lightmaps,
// color-correct images, report speed against error (see `luxel --help`).

#include "commands.hpp"

#include <iostream>
#include <vector>

int main(int argc, char** argv) {
  CLI::App app{"luxel - a CPU rasterizer for the DirectX 9-era Source engine shading pipeline"};
  app.require_subcommand(1);
  // Bad arguments: one line on stderr and exit code 2.
  app.failure_message([](const CLI::App* a, const CLI::Error& e) {
    return std::string(a->get_name().empty() ? "luxel" : a->get_name()) + ": " + e.what() + " (see --help)\n";
  });
  std::vector<luxel::cli::Runner> runners = {luxel::cli::add_render_command(app), luxel::cli::add_compare_command(app),
                                            luxel::cli::add_cost_command(app),
                                            luxel::cli::add_export_command(app), luxel::cli::add_info_command(app),
                                            luxel::cli::add_bake_command(app), luxel::cli::add_grade_command(app),
                                            luxel::cli::add_report_command(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "luxel: " << e.what() << " (see luxel --help)\n";
    return 2;
  }
  for (const auto& run : runners) {
    const int code = run();
    if (code >= 0) return code;
  }
  return 2;
}
