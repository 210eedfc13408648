#pragma once
// What a shader costs on a DX9 shader model, measured by running its real code on the Counted
// lane, and whether it fits the model, as fxc would decide.
//
//   const Cost cost = measure(ShaderModel::ps_2_0, [&](CountedInputs& in) {
//     const float3<Counted> normal = in.vector<3>();       // an interpolated input (t#)
//     return ambient_cube_light<Counted>(normal, cube);     // the shader's outputs
//   });
//   const Verdict v = fits(cost, caps(ShaderModel::ps_2_0));
//   EXPECT_TRUE(v) << v.reason;
//
// The body receives the shader's inputs and returns its outputs (a value, a vector, or a
// std::tuple of them); only what reaches an output is counted.
//
// Approximations (see counted.hpp for how the trace is read):
//  - temps: registers are allocated in program order (the order the C++ code evaluates, which
//    fxc may reschedule) and a value occupies a register from the instruction that writes it to
//    its last read. `temps` packs live values into float4 registers by their widths (two float2,
//    a float3 and a scalar, four scalars share one), as fxc does with write masks; it is a lower
//    bound on what fxc needs for that order. `temps_unpacked` (one register per live value) is an
//    upper bound. Inputs, constants and literals need no temp.
//  - constants: one register per declared constant object (constants.hpp), plus the distinct
//    literals packed four to a `def` register.
//  - slots: the DX9 instruction slot costs (counted.cpp), after dead-code removal, mul+add -> mad
//    fusion and `_sat` folding; algebraic rewrites fxc may do beyond those are not modelled, and
//    neither are the movs ps_2_x needs for swizzles it cannot express (except on texture
//    coordinates, which are modelled).

#include "luxel/shading/counted.hpp"
#include "luxel/shading/shader_model.hpp"
#include "luxel/shading/vector.hpp"

#include <string>
#include <tuple>
#include <type_traits>
#include <span>
#include <vector>

namespace luxel::shading {

/// What one shader variant needs.
struct Cost {
  ShaderModel model = ShaderModel::ps_2_0;
  int arithmetic_slots = 0;      ///< arithmetic instruction slots
  int texture_slots = 0;         ///< texture instruction slots (texld*)
  int temps = 0;                 ///< temporaries alive at once, packed by width (estimate)
  int temps_unpacked = 0;        ///< one register per live value (upper bound)
  int uniform_registers = 0;     ///< constant registers declared by the shader and used
  int literal_registers = 0;     ///< `def` registers holding the literals (4 per register)
  int texture_indirections = 0;  ///< levels of dependent texture reads (0: no fetch)
  int samplers = 0;              ///< distinct sampler registers fetched from
  int inputs = 0;                ///< interpolated input registers read
  std::vector<std::string> unsupported;  ///< operations the model does not have at all

  int total_slots() const { return arithmetic_slots + texture_slots; }
  int constant_registers() const { return uniform_registers + literal_registers; }
};

/// Whether a cost fits a model; `reason` lists every limit broken, in words.
struct Verdict {
  bool ok = true;
  std::string reason;
  explicit operator bool() const { return ok; }
};

Verdict fits(const Cost& cost, const ShaderModelCaps& model);

/// One line: "ps_2_0: 10 arith + 0 tex slots, 4 temps, 7 constants, 0 indirections".
std::string describe(const Cost& cost);

/// The interpolated inputs of a shader being measured; each call is one input register.
class CountedInputs {
 public:
  /// A scalar input register.
  Counted scalar() { return Counted(counted::Ref{counted::input(1), 0, 0}); }
  /// An input register of N components (a float2/float3/float4 interpolant).
  template <int N>
  Vec<Counted, N> vector() {
    return detail::counted_result<N, true>(counted::input(N));
  }
};

namespace detail {
/// Marks each output value (a scalar, a vector, or each element of a tuple) as one output register.
template <class T>
inline void mark_outputs(const T& value, counted::Recording& recording) {
  if constexpr (std::is_same_v<T, Counted>) {
    recording.output(std::span<const counted::Ref>(&value.ref, 1));
  } else if constexpr (Shape<T>::vec) {
    counted::Ref refs[Shape<T>::width];
    for (int i = 0; i < Shape<T>::width; ++i) refs[i] = value[i].ref;
    recording.output(refs);
  } else {
    std::apply([&](const auto&... parts) { (mark_outputs(parts, recording), ...); }, value);
  }
}
}  // namespace detail

/// Runs `body` on the Counted lane for `model` and returns what the shader costs there.
template <class Body>
Cost measure(ShaderModel model, Body&& body) {
  counted::Recording recording(model);
  CountedInputs inputs;
  const auto outputs = body(inputs);
  detail::mark_outputs(outputs, recording);
  return recording.finish();
}

}  // namespace luxel::shading
