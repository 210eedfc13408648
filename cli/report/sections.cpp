#include "report/sections.hpp"

namespace luxel::cli {

const std::vector<ReportSection>& report_sections() {
  static const std::vector<ReportSection> sections = {lighting_bases_section(),   msaa_section(),
                                                      shader_models_section(),    texture_sampling_section(),
                                                      vertex_lighting_section(),
                                                      world_lighting_section(),   ambient_sampling_section(),
                                                      ambient_popping_section(),  tone_mapping_section(),
                                                      color_correction_section(), exposure_section(),
                                                      cubemaps_section(),         lanes_section()};
  return sections;
}

}  // namespace luxel::cli
