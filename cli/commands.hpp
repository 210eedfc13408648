#pragma once
// Each subcommand of `luxel` registers its options on the app and returns the function that runs
// it. Runners return the process exit code.

#include <CLI/CLI.hpp>

#include <functional>

namespace luxel::cli {

using Runner = std::function<int()>;

Runner add_render_command(CLI::App& app);
Runner add_compare_command(CLI::App& app);
Runner add_cost_command(CLI::App& app);
Runner add_export_command(CLI::App& app);
Runner add_info_command(CLI::App& app);
Runner add_bake_command(CLI::App& app);
Runner add_grade_command(CLI::App& app);
Runner add_report_command(CLI::App& app);

}  // namespace luxel::cli
