#include "json_mutator.hpp"

#include <nlohmann/json.hpp>

#include <cstring>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);

namespace luxel::fuzz {

namespace {

/// Numbers where readers go wrong: around zero, type limits, glTF's component types and targets.
constexpr double kBoundaryNumbers[] = {0, -0.0, 1, -1, 2, 3, 4, 7, 255, 256, 65535, 65536, 2147483647.0, 2147483648.0,
                                       4294967295.0, 4294967296.0, 9007199254740993.0, -2147483649.0, 1e30, -1e30,
                                       1e308, 1e-45, 0.5, 5120, 5121, 5122, 5123, 5125, 5126, 34962, 34963};

/// Every value in the document, containers included, in document order.
void collect(nlohmann::json& j, std::vector<nlohmann::json*>& out) {
  out.push_back(&j);
  if (j.is_structured())
    for (auto& child : j) collect(child, out);
}

}  // namespace

size_t mutate_json(uint8_t* data, size_t size, size_t max_size, unsigned seed) {
  nlohmann::json doc = nlohmann::json::parse(data, data + size, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded()) return 0;
  std::minstd_rand rng(seed);
  std::vector<nlohmann::json*> values;
  collect(doc, values);
  nlohmann::json& v = *values[rng() % values.size()];
  switch (rng() % 8) {
    case 0: v = kBoundaryNumbers[rng() % std::size(kBoundaryNumbers)]; break;
    case 1: v = v.is_number() ? nlohmann::json(-v.get<double>()) : nlohmann::json(int(rng() % 4)); break;
    case 2: {
      static const nlohmann::json kinds[] = {nullptr, true, "", nlohmann::json::array(), nlohmann::json::object(), "data:,"};
      v = kinds[rng() % std::size(kinds)];
      break;
    }
    case 3: v = nlohmann::json(*values[rng() % values.size()]); break;  // a copy first: it may be v's own parent
    case 4:
      if (v.is_array() && !v.empty()) v.erase(v.begin() + std::ptrdiff_t(rng() % v.size()));
      else if (v.is_object() && !v.empty()) v.erase(std::next(v.begin(), std::ptrdiff_t(rng() % v.size())));
      break;
    case 5:
      if (v.is_array() && !v.empty() && v.size() < 4096) v.push_back(nlohmann::json(v[rng() % v.size()]));
      break;
    case 6:
      if (v.is_string()) {
        std::string s = v.get<std::string>();
        const size_t length = s.size();
        s.resize(length + 64);
        s.resize(LLVMFuzzerMutate(reinterpret_cast<uint8_t*>(s.data()), length, s.size()));
        v = s;
      }
      break;
    default:
      if (v.is_number()) v = v.get<double>() + double(int(rng() % 7) - 3);
      break;
  }
  const std::string text = doc.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (text.size() > max_size) return 0;
  std::memcpy(data, text.data(), text.size());
  return text.size();
}

}  // namespace luxel::fuzz
