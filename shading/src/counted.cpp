// Recording a Counted trace (counted_trace.hpp): each instruction a node with the slots it takes
// on its own, literals folded as fxc folds them; counted_analysis.cpp reads the finished trace.

#include "counted_trace.hpp"

#include "luxel/shading/cost.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace luxel::shading::counted {

namespace {

thread_local Trace* g_active = nullptr;

Trace& active_trace() {
  if (g_active == nullptr) throw std::logic_error("luxel::shading::Counted used outside measure()");
  return *g_active;
}

/// The value of a literal reference (modifiers applied), if it is one.
bool literal_value(const Trace& t, Ref r, float* value) {
  const Node& n = t.nodes[r.node];
  if (n.op != Op::literal) return false;
  float v = t.literal_values[n.literal_first + r.comp];
  if (r.mods & kAbsolute) v = std::fabs(v);
  if (r.mods & kNegate) v = -v;
  *value = v;
  return true;
}

bool all_literal_zero(const Trace& t, std::span<const Ref> refs) {
  for (const Ref r : refs) {
    float v;
    if (!literal_value(t, r, &v) || v != 0.0f) return false;
  }
  return true;
}

/// Distinct components read: a scalar instruction (rcp, rsq, exp, log) runs once per component.
int distinct_components(std::span<const Ref> refs) {
  std::set<std::pair<uint32_t, int>> seen;
  for (const Ref r : refs) seen.insert({r.node, r.comp | (r.mods << 8)});
  return static_cast<int>(seen.size());
}

/// Texture coordinates that are one register read as it is (no mov needed to assemble them).
bool coordinates_in_place(const Trace& t, std::span<const Ref> refs, bool any_swizzle) {
  for (size_t i = 0; i < refs.size(); ++i) {
    if (refs[i].node != refs[0].node || refs[i].mods != 0) return false;
    if (!any_swizzle && refs[i].comp != i) return false;
  }
  return t.nodes[refs[0].node].op != Op::literal;
}

/// Raw input register: the texture read is not dependent ("texld - ps_2_0 and up").
bool raw_input(const Trace& t, std::span<const Ref> refs) {
  return t.nodes[refs[0].node].op == Op::input && coordinates_in_place(t, refs, false);
}

/// The DX9 instruction slots of one node standing on its own, on one model. Sources: the
/// ps_2_0 / ps_3_0 / vs_2_0 instruction tables of the Direct3D 9 assembly reference
/// ("Instruction slots" column), quoted per line.
void set_cost(const Trace& t, Node& n, std::span<const Ref> ops, Comparison comparison) {
  const ShaderModelCaps& m = *t.model;
  const int w = n.group_width;
  int arithmetic = 0;
  int texture = 0;
  switch (n.op) {
    case Op::input:
    case Op::constant:
    case Op::literal:
      n.is_virtual = true;
      break;
    case Op::add:       // add 1
    case Op::mul:       // mul 1 (mad 1 when fused)
    case Op::min:       // min 1
    case Op::max:       // max 1
    case Op::frac:      // frc 1
    case Op::abs:       // abs 1 (ps_2_0, vs_2_0; a free modifier on *_3_0, never emitted there)
    case Op::mask_and:  // mul of two 0/1 masks
    case Op::mask_or:   // max of two 0/1 masks
      arithmetic = 1;
      break;
    case Op::floor:  // x - frc(x): frc + add
      arithmetic = 2;
      break;
    case Op::div: {  // rcp (scalar, one per distinct divisor component) + mul; mul alone by a literal
      const auto divisor = ops.subspan(w, w);
      bool literal = true;
      for (const Ref r : divisor) {
        float v;
        literal = literal && literal_value(t, r, &v);
      }
      arithmetic = literal ? 1 : distinct_components(divisor) + 1;
      break;
    }
    case Op::saturate:  // mov_sat 1 (0 when folded into its producer); vs_2_0 has no _sat: max + min
      arithmetic = m.sat_modifier ? 1 : 2;
      break;
    case Op::rcp:    // rcp 1, scalar
    case Op::rsqrt:  // rsq 1, scalar
    case Op::exp2:   // exp 1, scalar ("full precision")
    case Op::log2:   // log 1, scalar
      arithmetic = distinct_components(ops);
      break;
    case Op::sqrt:  // rsq + rcp per component
      arithmetic = 2 * distinct_components(ops);
      break;
    case Op::select:  // cmp 1 (ps); vertex shaders have no cmp: lrp 2 on the sge/slt mask
      arithmetic = m.cmp ? 1 : 2;
      break;
    case Op::compare: {
      const bool equality = comparison == Comparison::eq || comparison == Comparison::ne;
      if (m.cmp) {
        // cmp tests src0 >= 0 itself: a - b is an add unless one side is literal zero; equality
        // tests -|a - b| >= 0, which needs abs where there is no _abs modifier.
        const bool zero = all_literal_zero(t, ops.subspan(0, w)) || all_literal_zero(t, ops.subspan(w, w));
        arithmetic = (zero ? 0 : 1) + (equality && !m.abs_modifier ? 1 : 0);
      } else {
        arithmetic = equality ? 2 : 1;  // sge / slt (equality: sge both ways + mul)
      }
      n.is_virtual = arithmetic == 0;
      break;
    }
    case Op::dot:  // dp3 1, dp4 1; dp2add 2
      arithmetic = w == 2 ? 2 : 1;
      break;
    case Op::normalize:  // nrm 3; float4: dp4 + rsq + mul; float2: dp2add (2) + rsq + mul
      arithmetic = w == 2 ? 4 : 3;
      break;
    case Op::sincos:  // mad (turns to [-pi, pi)) + sincos 8, a scalar instruction, per component
      arithmetic = 1 + 8 * distinct_components(ops);
      break;
    case Op::texkill:  // texkill 1, counted with the texture instructions
      texture = 1;
      break;
    case Op::tex:       // texld 1
    case Op::tex_bias:  // texldb 1
      texture = 1;
      break;
    case Op::tex_lod:  // texldl 2 (ps_3_0 and vs_3_0 tables)
      texture = 2;
      break;
    case Op::tex_grad:  // texldd 3 (ps_3_0 table)
      texture = 3;
      break;
  }
  if (n.op == Op::tex || n.op == Op::tex_bias || n.op == Op::tex_lod || n.op == Op::tex_grad) {
    // A mov to assemble the coordinates (texldd's derivatives may be swizzled: ps_2_a / ps_3_0).
    if (!coordinates_in_place(t, ops.subspan(0, w), m.arbitrary_swizzle)) arithmetic += 1;
  }
  n.arithmetic = static_cast<int16_t>(arithmetic);
  n.texture = static_cast<int16_t>(texture);
}

/// Folds +, *, / of literals into a literal, as fxc does. Returns false when not all are literal.
bool fold(Trace& t, Op op, int width, std::span<const Ref> ops, uint32_t* folded) {
  if (op != Op::add && op != Op::mul && op != Op::div) return false;
  float values[8];
  for (size_t i = 0; i < ops.size(); ++i) {
    if (!literal_value(t, ops[i], &values[i])) return false;
  }
  Node n;
  n.op = Op::literal;
  n.width = static_cast<uint8_t>(width);
  n.literal_first = static_cast<uint32_t>(t.literal_values.size());
  n.is_virtual = true;
  for (int i = 0; i < width; ++i) {
    const float a = values[i];
    const float b = values[width + i];
    t.literal_values.push_back(op == Op::add ? a + b : op == Op::mul ? a * b : a / b);
  }
  *folded = static_cast<uint32_t>(t.nodes.size());
  t.nodes.push_back(n);
  return true;
}

/// Reading a Counted that was never assigned is a bug in the shader (fxc: "use of uninitialized
/// variable").
void check_assigned(const Trace& t, std::span<const Ref> refs) {
  for (const Ref r : refs) {
    if (r.node >= t.nodes.size()) {
      throw std::logic_error("luxel::shading: a Counted value was read before it was assigned");
    }
  }
}

}  // namespace

void emit_lanewise(Op op, int width, std::span<const Ref> operands, Ref* out) {
  Trace& t = active_trace();
  check_assigned(t, operands);
  if (uint32_t folded; operands.size() <= 8 && fold(t, op, width, operands, &folded)) {
    for (int i = 0; i < width; ++i) out[i] = Ref{folded, static_cast<uint8_t>(i), 0};
    return;
  }
  // The identities fxc applies: x + 0, x * 1, x / 1 are x.
  if (op == Op::add || op == Op::mul || op == Op::div) {
    const float unit = op == Op::add ? 0.0f : 1.0f;
    auto all_unit = [&](std::span<const Ref> group) {
      return std::all_of(group.begin(), group.end(), [&](const Ref r) {
        float v;
        return literal_value(t, r, &v) && v == unit;
      });
    };
    const auto a = operands.subspan(0, width);
    const auto b = operands.subspan(width, width);
    const std::span<const Ref> kept = all_unit(b) ? a : (op != Op::div && all_unit(a)) ? b : std::span<const Ref>{};
    if (!kept.empty()) {
      std::copy(kept.begin(), kept.end(), out);
      return;
    }
  }
  const uint32_t node = emit(op, width, width, operands);
  for (int i = 0; i < width; ++i) out[i] = Ref{node, static_cast<uint8_t>(i), 0};
}

uint32_t emit(Op op, int width, int group_width, std::span<const Ref> operands, const Extra& extra) {
  Trace& t = active_trace();
  check_assigned(t, operands);

  Node n;
  n.op = op;
  n.width = static_cast<uint8_t>(width);
  n.group_width = static_cast<uint8_t>(group_width);
  n.groups = static_cast<uint8_t>(group_width ? operands.size() / group_width : 0);
  n.first = static_cast<uint32_t>(t.operands.size());
  n.sampler = extra.sampler;
  n.key = extra.key;
  n.key_row = extra.key_row;
  t.operands.insert(t.operands.end(), operands.begin(), operands.end());

  int level = 0;
  for (const Ref r : operands) level = std::max<int>(level, t.nodes[r.node].level);
  if (op == Op::tex || op == Op::tex_bias || op == Op::tex_lod || op == Op::tex_grad) {
    // A read from an unmodified input register is order 0; from anything computed, order >= 1;
    // from a value depending on a read of level k, order k. Its result has level order + 1.
    const int order = raw_input(t, operands.subspan(0, group_width)) ? 0 : std::max(1, level);
    level = order + 1;
  }
  n.level = static_cast<uint8_t>(std::min(level, 255));
  set_cost(t, n, operands, extra.comparison);
  t.nodes.push_back(n);
  return static_cast<uint32_t>(t.nodes.size() - 1);
}

Ref literal(float value) {
  Trace& t = active_trace();
  Node n;
  n.op = Op::literal;
  n.is_virtual = true;
  n.literal_first = static_cast<uint32_t>(t.literal_values.size());
  t.literal_values.push_back(value);
  t.nodes.push_back(n);
  return Ref{static_cast<uint32_t>(t.nodes.size() - 1), 0, 0};
}

uint32_t input(int width) {
  Trace& t = active_trace();
  Node n;
  n.op = Op::input;
  n.width = static_cast<uint8_t>(width);
  n.is_virtual = true;
  t.nodes.push_back(n);
  return static_cast<uint32_t>(t.nodes.size() - 1);
}

uint32_t constant(const void* key, int row, int width) {
  Trace& t = active_trace();
  Node n;
  n.op = Op::constant;
  n.width = static_cast<uint8_t>(width);
  n.is_virtual = true;
  n.key = key;
  n.key_row = row;
  t.nodes.push_back(n);
  return static_cast<uint32_t>(t.nodes.size() - 1);
}

Ref absolute(Ref r) {
  Trace& t = active_trace();
  if (t.model->abs_modifier) {
    r.mods = kAbsolute;  // |-x| = |x|: the negation goes
    return r;
  }
  const Ref ops[] = {r};
  return Ref{emit(Op::abs, 1, 1, ops), 0, 0};
}

void side_effect(uint32_t node) { active_trace().effects.push_back(node); }

void unsupported(std::string what) {
  Trace& t = active_trace();
  if (std::find(t.unsupported.begin(), t.unsupported.end(), what) == t.unsupported.end()) {
    t.unsupported.push_back(std::move(what));
  }
}

const ShaderModelCaps& active_model() { return *active_trace().model; }

Recording::Recording(ShaderModel model) : trace_(std::make_unique<Trace>()), previous_(g_active) {
  trace_->model = &caps(model);
  g_active = trace_.get();
}

Recording::~Recording() { g_active = previous_; }

void Recording::output(std::span<const Ref> refs) {
  check_assigned(*trace_, refs);
  trace_->outputs.emplace_back(refs.begin(), refs.end());
}

}  // namespace luxel::shading::counted
