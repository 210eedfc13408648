// LUTs by name: built-in presets or files (lut_source.hpp).

#include "luxel/postfx/lut_source.hpp"

#include "luxel/postfx/grade.hpp"
#include "luxel/postfx/lut_file.hpp"
#include "luxel/postfx/raw_lut_file.hpp"

#include <cctype>
#include <filesystem>

#include <stdexcept>

namespace luxel::postfx {

ColorTransform color_transform_named(const std::string& name) {
  const std::string prefix = "builtin:";
  if (name.rfind(prefix, 0) != 0) {
    std::string extension = std::filesystem::path(name).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".raw" ? raw_lut_transform(read_raw_lut(name), name) : read_lut_file(name);
  }
  const std::string preset = name.substr(prefix.size());
  if (std::optional<Grade> grade = grade_preset(preset)) return grade_transform(std::move(*grade), name);
  std::string known;
  for (const std::string& n : grade_preset_names()) known += (known.empty() ? "" : ", ") + prefix + n;
  throw std::invalid_argument(name + ": unknown built-in LUT '" + preset + "' (known: " + known + ")");
}

Lut resolve_lut(const std::string& name) { return sample_lut(color_transform_named(name)); }

}  // namespace luxel::postfx
