// Reading a finished Counted trace (counted_trace.hpp) the way fxc would compile it, one pass per
// function: dead code, uses, mad fusion, _sat folding, register lifetimes, then the slots,
// dependent-read levels and registers a ps_2_0 / ps_2_b / ps_3_0 compile would report.

#include "counted_trace.hpp"

#include "luxel/shading/cost.hpp"

#include <algorithm>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

namespace luxel::shading::counted {

namespace {

/// Registers needed to hold live values of widths 1..4 when packed with write masks: a float4 or
/// float3 takes a register (a float3 leaves one scalar slot), two float2 share one, scalars fill
/// the gaps and then share registers four at a time.
int packed_registers(const int (&count)[5]) {
  int registers = count[4] + count[3] + (count[2] + 1) / 2;
  const int free_scalar_slots = count[3] + (count[2] % 2 ? 2 : 0);
  const int scalars_left = std::max(0, count[1] - free_scalar_slots);
  return registers + (scalars_left + 3) / 4;
}

/// What reaches an output or a side effect: everything else is dead code, which fxc drops.
std::vector<char> live_nodes(const Trace& t) {
  std::vector<char> live(t.nodes.size(), 0);
  for (const auto& out : t.outputs)
    for (const Ref r : out) live[r.node] = 1;
  for (const uint32_t e : t.effects) live[e] = 1;
  for (size_t i = t.nodes.size(); i-- > 0;) {
    if (!live[i]) continue;
    for (const Ref r : t.operands_of(t.nodes[i])) live[r.node] = 1;
  }
  return live;
}

/// How many instructions (operand groups) and outputs read each node.
std::vector<int> count_uses(const Trace& t, const std::vector<char>& live) {
  std::vector<int> uses(t.nodes.size(), 0);
  for (size_t i = 0; i < t.nodes.size(); ++i) {
    if (!live[i]) continue;
    const Node& n = t.nodes[i];
    const auto ops = t.operands_of(n);
    for (int g = 0; g < n.groups; ++g) {
      std::set<uint32_t> read;
      for (const Ref r : ops.subspan(static_cast<size_t>(g) * n.group_width, n.group_width)) read.insert(r.node);
      for (const uint32_t node : read) ++uses[node];
    }
  }
  for (const auto& out : t.outputs) {
    std::set<uint32_t> read;
    for (const Ref r : out) read.insert(r.node);
    for (const uint32_t node : read) ++uses[node];
  }
  return uses;
}

/// Instructions merged into others: a mul into the add that became a mad, a saturate into its
/// producer's _sat; and each node's arithmetic slots after the merging.
struct Merged {
  std::vector<int64_t> fused_into;  ///< mul -> the add it became part of
  std::vector<int64_t> alias_of;    ///< folded saturate -> its producer
  std::vector<int> slots;
};

/// mad: an add one of whose operands is a mul read nowhere else takes that mul's place.
void fuse_mads(const Trace& t, const std::vector<char>& live, const std::vector<int>& uses, Merged& m) {
  for (size_t i = 0; i < t.nodes.size(); ++i) {
    const Node& n = t.nodes[i];
    if (!live[i] || n.op != Op::add) continue;
    const auto ops = t.operands_of(n);
    for (int g = 0; g < 2; ++g) {
      const auto group = ops.subspan(static_cast<size_t>(g) * n.group_width, n.group_width);
      const uint32_t mul = group[0].node;
      const bool one_node = std::all_of(group.begin(), group.end(), [&](const Ref r) { return r.node == mul; });
      if (one_node && t.nodes[mul].op == Op::mul && uses[mul] == 1 && m.fused_into[mul] < 0) {
        m.fused_into[mul] = static_cast<int64_t>(i);
        m.slots[i] = 0;  // the mul's slot is now the mad
        break;
      }
    }
  }
}

/// _sat: saturate of a result read nowhere else is a modifier on the instruction producing it.
void fold_saturates(const Trace& t, const std::vector<char>& live, const std::vector<int>& uses, Merged& m) {
  if (!t.model->sat_modifier) return;
  for (size_t i = 0; i < t.nodes.size(); ++i) {
    const Node& n = t.nodes[i];
    if (!live[i] || n.op != Op::saturate) continue;
    const auto ops = t.operands_of(n);
    const uint32_t p = ops[0].node;
    const Node& producer = t.nodes[p];
    const bool plain = std::all_of(ops.begin(), ops.end(), [&](const Ref r) { return r.node == p && r.mods == 0; });
    const bool takes_sat = !t.is_leaf(producer) && !producer.is_virtual && producer.op != Op::frac && !is_texture(producer.op) &&
                           m.fused_into[p] < 0 && m.alias_of[p] < 0;
    if (plain && takes_sat && uses[p] == 1) {
      m.alias_of[i] = p;
      m.slots[i] = 0;
    }
  }
}

/// Register lifetimes: a value lives from its instruction to its last read. Fused muls and
/// comparisons against zero have no register (their operands are read where they are used); a
/// folded saturate is its producer's register. Sets the cost's temporaries, packed and not.
void count_temporaries(const Trace& t, const std::vector<char>& live, const Merged& m, Cost& cost) {
  const size_t count = t.nodes.size();
  std::vector<int64_t> last_read(count, -1);
  auto read = [&](auto&& self, uint32_t node, int64_t time) -> void {
    const Node& n = t.nodes[node];
    if (t.is_leaf(n)) return;
    if (m.alias_of[node] >= 0) return self(self, static_cast<uint32_t>(m.alias_of[node]), time);
    if (m.fused_into[node] >= 0 || n.is_virtual) {
      for (const Ref r : t.operands_of(n)) self(self, r.node, time);
      return;
    }
    last_read[node] = std::max(last_read[node], time);
  };
  auto has_register = [&](size_t i) {
    const Node& n = t.nodes[i];
    return live[i] && !t.is_leaf(n) && !n.is_virtual && m.fused_into[i] < 0 && m.alias_of[i] < 0;
  };
  for (size_t i = 0; i < count; ++i) {
    if (!has_register(i)) continue;
    for (const Ref r : t.operands_of(t.nodes[i])) read(read, r.node, static_cast<int64_t>(i));
  }
  const auto end = static_cast<int64_t>(count);
  for (const auto& out : t.outputs)
    for (const Ref r : out) read(read, r.node, end);

  std::vector<std::vector<uint32_t>> dies_at(count + 1);
  for (size_t i = 0; i < count; ++i) {
    if (has_register(i) && last_read[i] >= 0) dies_at[static_cast<size_t>(last_read[i])].push_back(static_cast<uint32_t>(i));
  }
  int by_width[5] = {0, 0, 0, 0, 0};
  for (size_t i = 0; i < count; ++i) {
    if (has_register(i) && last_read[i] > static_cast<int64_t>(i)) ++by_width[std::clamp<int>(t.nodes[i].width, 1, 4)];
    for (const uint32_t d : dies_at[i]) {
      if (d != i) --by_width[std::clamp<int>(t.nodes[d].width, 1, 4)];
    }
    cost.temps_unpacked = std::max(cost.temps_unpacked, by_width[1] + by_width[2] + by_width[3] + by_width[4]);
    cost.temps = std::max(cost.temps, packed_registers(by_width));
  }
}

/// Slots, dependent-read levels, samplers, inputs and constant registers (uniforms and the
/// literals fxc puts in def registers).
void count_slots_and_constants(const Trace& t, const std::vector<char>& live, const Merged& m, Cost& cost) {
  const ShaderModelCaps& model = *t.model;
  std::set<int> samplers;
  std::set<std::pair<const void*, int>> uniforms;
  std::set<float> literals;
  auto note_literal = [&](const Ref r) {
    const Node& target = t.nodes[r.node];
    if (target.op == Op::literal) literals.insert(t.literal_values[target.literal_first + r.comp]);
  };
  for (size_t i = 0; i < t.nodes.size(); ++i) {
    if (!live[i]) continue;
    const Node& n = t.nodes[i];
    if (n.op == Op::input) ++cost.inputs;
    if (n.op == Op::constant) uniforms.insert({n.key, n.key_row});
    if (t.is_leaf(n)) continue;
    cost.arithmetic_slots += m.slots[i];
    cost.texture_slots += n.texture;
    if (is_texture(n.op)) {
      cost.texture_indirections = std::max<int>(cost.texture_indirections, n.level);
      samplers.insert(n.sampler);
    }
    // A comparison against zero needs no zero register: cmp compares with 0 itself.
    if (!(n.op == Op::compare && n.is_virtual)) {
      for (const Ref r : t.operands_of(n)) note_literal(r);
    }
  }
  for (const auto& out : t.outputs) {
    for (const Ref r : out) note_literal(r);
    if (model.output_by_mov_only) cost.arithmetic_slots += 1;  // mov oC#, r#
  }
  // Before shader model 3, sincos reads its series coefficients from two constant registers
  // (D3DSINCOSCONST1/2, which fxc defines as literals).
  const bool sincos_constants = model.model != ShaderModel::ps_3_0 && model.model != ShaderModel::vs_3_0;
  for (size_t i = 0; i < t.nodes.size(); ++i) {
    if (!live[i] || t.nodes[i].op != Op::sincos || !sincos_constants) continue;
    for (const float k : {-1.5500992e-6f, -2.1701389e-5f, 0.0026041667f, 0.00026041668f, -0.020833334f, -0.125f, 1.0f, 0.5f})
      literals.insert(k);
  }
  cost.samplers = static_cast<int>(samplers.size());
  cost.uniform_registers = static_cast<int>(uniforms.size());
  cost.literal_registers = (static_cast<int>(literals.size()) + 3) / 4;
}

}  // namespace

Cost Recording::finish() const {
  const Trace& t = *trace_;
  Cost cost;
  cost.model = t.model->model;
  cost.unsupported = t.unsupported;
  const std::vector<char> live = live_nodes(t);
  const std::vector<int> uses = count_uses(t, live);
  Merged merged{std::vector<int64_t>(t.nodes.size(), -1), std::vector<int64_t>(t.nodes.size(), -1), {}};
  for (const Node& n : t.nodes) merged.slots.push_back(n.arithmetic);
  fuse_mads(t, live, uses, merged);
  fold_saturates(t, live, uses, merged);
  count_temporaries(t, live, merged, cost);
  count_slots_and_constants(t, live, merged, cost);
  return cost;
}

}  // namespace luxel::shading::counted
