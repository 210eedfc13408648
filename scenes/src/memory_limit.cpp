#include "luxel/scenes/memory_limit.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <variant>

namespace luxel::scenes {

void check_memory(const std::string& name, uint64_t needed, const std::string& what, uint64_t limit) {
  if (needed <= limit) return;
  throw MemoryLimitError(name + ": needs about " + format_bytes(needed) + " (" + what + "), beyond the memory limit of " +
                         format_bytes(limit) + " (raise it with --memory-limit or " + kMemoryLimitVariable + ")");
}

std::string format_bytes(uint64_t bytes) {
  static const char* kUnits[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double value = double(bytes);
  int unit = 0;
  while (value >= 1024.0 && unit < 6) value /= 1024.0, ++unit;
  char text[32];
  if (unit == 0) std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
  else if (value < 10.0 && value != std::floor(value)) std::snprintf(text, sizeof text, "%.1f %s", value, kUnits[unit]);
  else std::snprintf(text, sizeof text, "%.0f %s", value, kUnits[unit]);
  return text;
}

uint64_t parse_memory_size(const std::string& text) {
  auto refuse = [&]() -> uint64_t {
    throw std::invalid_argument("'" + text + "' is not a size (bytes, or a number with K, M, G or T: 512M, 8G)");
  };
  size_t end = 0;
  while (end < text.size() && (std::isdigit(static_cast<unsigned char>(text[end])) || text[end] == '.')) ++end;
  if (end == 0) return refuse();
  char* parsed = nullptr;
  const std::string number = text.substr(0, end);
  const double value = std::strtod(number.c_str(), &parsed);
  if (parsed != number.c_str() + number.size()) return refuse();
  std::string unit = text.substr(end);
  for (char& c : unit) c = char(std::toupper(static_cast<unsigned char>(c)));
  if (unit.size() == 3 && unit.substr(1) == "IB") unit.resize(1);
  else if (unit.size() == 2 && unit[1] == 'B') unit.resize(1);
  const std::string kUnits = "KMGT";
  double scale = 1.0;
  if (unit == "B") unit.clear();
  if (!unit.empty()) {
    const size_t at = kUnits.find(unit);
    if (unit.size() != 1 || at == std::string::npos) return refuse();
    scale = std::ldexp(1.0, 10 * int(at + 1));
  }
  const double bytes = std::floor(value * scale);
  if (!(bytes >= 1.0) || bytes > std::ldexp(1.0, 63)) return refuse();
  return uint64_t(bytes);
}

uint64_t memory_limit_from_environment() {
  const char* text = std::getenv(kMemoryLimitVariable);
  if (!text || !*text) return kDefaultMemoryLimit;
  try {
    return parse_memory_size(text);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(kMemoryLimitVariable) + ": " + e.what());
  }
}

uint64_t image_bytes(uint64_t width, uint64_t height, bool hdr) { return width * height * 4 * (hdr ? 4 : 1); }

uint64_t scene_bytes(const Scene& scene) {
  uint64_t bytes = 0;
  for (const Texture& t : scene.textures)
    for (const PixelImage& face : t.faces) bytes += face.rgba8.size() + face.rgba32f.size() * sizeof(float);
  for (const Mesh& m : scene.meshes) {
    bytes += m.positions.size() * sizeof(glm::vec3) + m.normals.size() * sizeof(glm::vec3) +
             m.tangents.size() * sizeof(glm::vec4) + m.uv0.size() * sizeof(glm::vec2) + m.uv1.size() * sizeof(glm::vec2) +
             m.colors.size() * sizeof(glm::vec4);
    bytes += std::visit([](const auto& indices) { return indices.size() * sizeof(indices[0]); }, m.indices);
  }
  return bytes;
}

}  // namespace luxel::scenes
