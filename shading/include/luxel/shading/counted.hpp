#pragma once
// Counted: the lane that computes no numbers but records what the shader would compile to.
//
// Every Counted value is a reference to one component of a node in a trace: an instruction the
// DX9 compiler would emit (add, dp3, nrm, texld...), or a leaf that costs nothing (an interpolated
// input, a constant register, a literal). A float3 operation is one node of width 3, one slot, as
// on the hardware; swizzles and write masks only rearrange references and cost nothing; negation
// (and |x| on *_3_0) is a flag on the reference, a free source modifier.
//
// The trace is analysed only when the measurement ends (cost.hpp: measure), because what fxc emits
// depends on how values are used, which is known only then:
//  - dead code is dropped (only nodes reaching an output count);
//  - a mul whose only use is an add becomes a mad with it (one slot, not two);
//  - saturate() of a result used nowhere else is the free `_sat` modifier of the instruction that
//    produced it; otherwise it is a `mov_sat` (one slot), and on vs_2_0, which has no `_sat`,
//    max + min (two slots);
//  - a comparison with literal zero is free: `cmp` compares its first source with 0 itself.
// Two simplifications happen as the trace is recorded: operations on literals only fold into a
// literal, and x + 0, x * 1, x / 1 are x. Nothing else fxc does is modelled (no common
// subexpressions merged, no algebra): write the shader the way it should compile.
//
// Counted values record into the trace of the measurement running on this thread (a scoped,
// thread-local recorder, installed by measure() and removed when it returns). It is the only
// thread-local state in luxel and production lanes never touch it. Using Counted outside a
// measurement throws std::logic_error.

#include "luxel/shading/lane.hpp"
#include "luxel/shading/shader_model.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <string>

namespace luxel::shading {

struct Cost;

namespace counted {

/// What a node computes. Costs per shader model live in counted.cpp (set_cost), next to the DX9
/// instruction tables they come from.
enum class Op : uint8_t {
  // Leaves: no instruction, no temporary register.
  input,     ///< an interpolated input register (t#/v#), raw as the rasterizer delivers it
  constant,  ///< a constant register c# declared by the shader (shading::constant)
  literal,   ///< a literal; fxc packs distinct literals four to a `def` constant register
  // Lane-wise arithmetic: `groups` operand groups of `width` references each.
  add,       ///< add (a - b is add with a negated source)
  mul,       ///< mul; fused into a following add as mad when that add is its only use
  div,       ///< rcp per distinct divisor component + mul (mul alone for a literal divisor)
  min, max, frac, floor, saturate, abs, rcp, rsqrt, sqrt, exp2, log2,
  select,    ///< cmp (pixel shaders) / sge + lrp (vertex shaders); group 0 is the mask
  compare,   ///< the add that feeds cmp; free against literal zero
  mask_and, mask_or,
  // Reductions: two groups of `group_width`, result width 1.
  dot,
  normalize,  ///< nrm (one group, result of the same width)
  sincos,     ///< mad to radians + sincos (8, scalar); result: N sines then N cosines
  texkill,    ///< discard where any component < 0: a texture instruction, and a side effect
  // Texture fetches: one group of coordinates, result width 4.
  tex, tex_bias, tex_lod,
  tex_grad,  ///< coordinates, then their x and y derivatives: three groups
};

enum class Comparison : uint8_t { ge, lt, gt, le, eq, ne };

/// Modifiers on a reference: free source modifiers of the instruction that reads it.
inline constexpr uint8_t kNegate = 1;
inline constexpr uint8_t kAbsolute = 2;

/// The node of a reference that was never assigned (a default-constructed Counted).
inline constexpr uint32_t kUnassigned = 0xffffffffu;

/// One component of one node, as read by an instruction.
struct Ref {
  uint32_t node = kUnassigned;
  uint8_t comp = 0;
  uint8_t mods = 0;
};

/// What some instructions carry besides their operands.
struct Extra {
  int sampler = -1;                       ///< tex*: the sampler register s#
  Comparison comparison = Comparison::ge;  ///< compare
  const void* key = nullptr;              ///< constant: identity of the register
  int key_row = 0;                        ///< constant: row of a matrix constant
};

/// Appends a node to the active trace and returns its index. `operands` holds groups of
/// `group_width` references (the width the instruction reads); the result has `width` components.
uint32_t emit(Op op, int width, int group_width, std::span<const Ref> operands, const Extra& extra = {});

/// A lane-wise instruction of `width` components (operand groups of `width`), writing the
/// references to its result to out[0, width). Simplified first as fxc does: operations on
/// literals only fold into a literal, and x + 0, x * 1, x / 1 are x.
void emit_lanewise(Op op, int width, std::span<const Ref> operands, Ref* out);

/// A literal node of one component.
Ref literal(float value);
/// A fresh input register of `width` components.
uint32_t input(int width);
/// The constant register identified by (key, row), `width` components wide.
uint32_t constant(const void* key, int row, int width);
/// |r|: a free modifier on models that have `_abs`, else an abs instruction.
Ref absolute(Ref r);
/// -r: always a free modifier.
inline Ref negate(Ref r) {
  r.mods ^= kNegate;
  return r;
}
/// Keeps a node alive although no output reads it (texkill: its effect is the discard).
void side_effect(uint32_t node);
/// Records something the shader model cannot do at all (e.g. tex2Dlod on ps_2_0); fits() reports it.
void unsupported(std::string what);
/// The shader model of the active trace.
const ShaderModelCaps& active_model();

struct Trace;

/// Installs a fresh trace for the current thread for its lifetime (measure() uses it).
class Recording {
 public:
  explicit Recording(ShaderModel model);
  ~Recording();
  Recording(const Recording&) = delete;
  Recording& operator=(const Recording&) = delete;

  /// Marks one output register's value (oC#/oDepth or a vertex output): what is live. On shader
  /// model 2 pixel shaders each output costs the mov that writes it.
  void output(std::span<const Ref> refs);
  /// Analyses the trace: the shader's cost.
  Cost finish() const;

 private:
  std::unique_ptr<Trace> trace_;
  Trace* previous_;
};

}  // namespace counted

/// A scalar Counted value: one component of a traced node.
class Counted {
 public:
  /// No value yet: assign before use, like an HLSL local (reading it throws std::logic_error).
  Counted() = default;
  /// A literal of the shader code.
  Counted(float value) : ref(counted::literal(value)) {}  // NOLINT: literals convert implicitly
  explicit Counted(counted::Ref r) : ref(r) {}

  counted::Ref ref{};
};

/// The mask of a Counted comparison (a reference to the compare node); `!` is free (cmp with its
/// sources swapped).
class CountedMask {
 public:
  CountedMask() = default;
  explicit CountedMask(counted::Ref r) : ref(r) {}
  counted::Ref ref{};
};

template <>
struct LaneTraits<Counted> {
  using Mask = CountedMask;
};

namespace counted {
inline Counted binary(Op op, const Counted& a, const Counted& b) {
  const Ref ops[] = {a.ref, b.ref};
  Counted r;
  emit_lanewise(op, 1, ops, &r.ref);
  return r;
}
inline CountedMask compare(Comparison c, const Counted& a, const Counted& b) {
  const Ref ops[] = {a.ref, b.ref};
  Extra extra;
  extra.comparison = c;
  return CountedMask(Ref{emit(Op::compare, 1, 1, ops, extra), 0, 0});
}
}  // namespace counted

inline Counted operator+(const Counted& a, const Counted& b) { return counted::binary(counted::Op::add, a, b); }
inline Counted operator-(const Counted& a) { return Counted(counted::negate(a.ref)); }
inline Counted operator-(const Counted& a, const Counted& b) { return a + (-b); }
inline Counted operator*(const Counted& a, const Counted& b) { return counted::binary(counted::Op::mul, a, b); }
inline Counted operator/(const Counted& a, const Counted& b) { return counted::binary(counted::Op::div, a, b); }
inline Counted& operator+=(Counted& a, const Counted& b) { return a = a + b; }
inline Counted& operator-=(Counted& a, const Counted& b) { return a = a - b; }
inline Counted& operator*=(Counted& a, const Counted& b) { return a = a * b; }
inline Counted& operator/=(Counted& a, const Counted& b) { return a = a / b; }

inline CountedMask operator>=(const Counted& a, const Counted& b) { return counted::compare(counted::Comparison::ge, a, b); }
inline CountedMask operator<(const Counted& a, const Counted& b) { return counted::compare(counted::Comparison::lt, a, b); }
inline CountedMask operator>(const Counted& a, const Counted& b) { return counted::compare(counted::Comparison::gt, a, b); }
inline CountedMask operator<=(const Counted& a, const Counted& b) { return counted::compare(counted::Comparison::le, a, b); }
inline CountedMask operator==(const Counted& a, const Counted& b) { return counted::compare(counted::Comparison::eq, a, b); }
inline CountedMask operator!=(const Counted& a, const Counted& b) { return counted::compare(counted::Comparison::ne, a, b); }

inline CountedMask operator!(const CountedMask& m) { return CountedMask(counted::negate(m.ref)); }
inline CountedMask operator&&(const CountedMask& a, const CountedMask& b) {
  const counted::Ref ops[] = {a.ref, b.ref};
  return CountedMask(counted::Ref{counted::emit(counted::Op::mask_and, 1, 1, ops), 0, 0});
}
inline CountedMask operator||(const CountedMask& a, const CountedMask& b) {
  const counted::Ref ops[] = {a.ref, b.ref};
  return CountedMask(counted::Ref{counted::emit(counted::Op::mask_or, 1, 1, ops), 0, 0});
}

}  // namespace luxel::shading
