#include "luxel/rasterizer/fast_paths.hpp"

#include <stdexcept>

namespace luxel::rasterizer {

FastPaths parse_fast_paths_off(std::string_view list) {
  FastPaths paths;
  while (!list.empty()) {
    const size_t comma = list.find(',');
    const std::string_view word = list.substr(0, comma);
    list = comma == std::string_view::npos ? std::string_view() : list.substr(comma + 1);
    if (word == "all") {
      paths = FastPaths::none();
      continue;
    }
    bool known = false;
    for (const FastPathName& n : kFastPathNames) {
      if (word == n.name) {
        paths = paths.without(n.path);
        known = true;
      }
    }
    if (!known) {
      std::string names;
      for (const FastPathName& n : kFastPathNames) names += std::string(n.name) + ", ";
      throw std::invalid_argument("unknown fast path '" + std::string(word) + "' (known: " + names + "all)");
    }
  }
  return paths;
}

std::string fast_paths_off_names(FastPaths paths) {
  std::string names;
  for (const FastPathName& n : kFastPathNames)
    if (!paths.on(n.path)) {
      if (!names.empty()) names += ',';
      names += n.name;
    }
  return names.empty() ? "none" : names;
}

}  // namespace luxel::rasterizer
