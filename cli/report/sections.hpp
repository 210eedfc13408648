#pragma once
// The report's sections, one function per file (cli/report/<name>.cpp); sections.cpp lists them
// in report order. A new section: its file, its line here and its line in sections.cpp.

#include "report/report.hpp"

namespace luxel::cli {

ReportSection lighting_bases_section();
ReportSection msaa_section();
ReportSection shader_models_section();
ReportSection texture_sampling_section();
ReportSection vertex_lighting_section();
ReportSection world_lighting_section();
ReportSection ambient_sampling_section();
ReportSection ambient_popping_section();
ReportSection tone_mapping_section();
ReportSection color_correction_section();
ReportSection exposure_section();
ReportSection cubemaps_section();
ReportSection lanes_section();

}  // namespace luxel::cli
