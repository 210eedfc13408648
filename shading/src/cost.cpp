// Checking a measured cost against a shader model's limits, in words.

#include "luxel/shading/cost.hpp"

#include <sstream>

namespace luxel::shading {

namespace {
void check(std::ostringstream& why, bool& ok, int used, int limit, const char* what) {
  if (limit >= kUnlimited || used <= limit) return;
  why << (ok ? "" : "; ") << used << ' ' << what << " > " << limit;
  ok = false;
}
}  // namespace

Verdict fits(const Cost& cost, const ShaderModelCaps& model) {
  std::ostringstream why;
  bool ok = true;
  for (const std::string& u : cost.unsupported) {
    why << (ok ? "" : "; ") << u;
    ok = false;
  }
  check(why, ok, cost.arithmetic_slots, model.arithmetic_slots, "arithmetic slots");
  check(why, ok, cost.texture_slots, model.texture_slots, "texture slots");
  check(why, ok, cost.total_slots(), model.total_slots, "instruction slots");
  check(why, ok, cost.temps, model.temps, "temporaries alive at once (estimate)");
  check(why, ok, cost.constant_registers(), model.constants, "constant registers");
  check(why, ok, cost.texture_indirections, model.texture_indirections, "levels of texture indirection");
  check(why, ok, cost.samplers, model.samplers, "samplers");
  check(why, ok, cost.inputs, model.inputs, "input registers");
  Verdict v;
  v.ok = ok;
  if (!ok) v.reason = std::string(model.name) + ": " + why.str();
  return v;
}

std::string describe(const Cost& cost) {
  std::ostringstream s;
  s << caps(cost.model).name << ": " << cost.arithmetic_slots << " arith + " << cost.texture_slots
    << " tex slots, " << cost.temps << " temps (" << cost.temps_unpacked << " unpacked), "
    << cost.constant_registers() << " constants (" << cost.uniform_registers << " declared + "
    << cost.literal_registers << " literal), " << cost.texture_indirections << " indirections, "
    << cost.samplers << " samplers, " << cost.inputs << " inputs";
  return s.str();
}

}  // namespace luxel::shading
