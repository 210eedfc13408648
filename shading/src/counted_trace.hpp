#pragma once
// The Counted trace (counted.hpp): the instructions a shader recorded through its Counted lane,
// as counted.cpp writes them and counted_analysis.cpp reads them.

#include "luxel/shading/counted.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace luxel::shading::counted {

struct Node {
  Op op = Op::literal;
  uint8_t width = 1;        ///< result components
  uint8_t group_width = 1;  ///< references per operand group
  uint8_t groups = 0;       ///< operand groups
  uint8_t level = 0;        ///< texture-indirection level of the value
  bool is_virtual = false;  ///< no instruction and no register of its own (compare against zero)
  int16_t arithmetic = 0;   ///< slots when it stands as its own instruction(s)
  int16_t texture = 0;
  uint32_t first = 0;       ///< operands: Trace::operands[first, first + groups * group_width)
  int sampler = -1;
  const void* key = nullptr;
  int key_row = 0;
  uint32_t literal_first = 0;  ///< Op::literal: Trace::literal_values[literal_first, + width)
};

struct Trace {
  const ShaderModelCaps* model = nullptr;
  std::vector<Node> nodes;
  std::vector<Ref> operands;
  std::vector<float> literal_values;
  std::vector<std::vector<Ref>> outputs;
  std::vector<uint32_t> effects;  ///< nodes kept for their side effect (texkill)
  std::vector<std::string> unsupported;

  std::span<const Ref> operands_of(const Node& n) const {
    return {operands.data() + n.first, static_cast<size_t>(n.groups) * n.group_width};
  }
  bool is_leaf(const Node& n) const { return n.op == Op::input || n.op == Op::constant || n.op == Op::literal; }
};

/// Whether `op` reads a texture.
inline bool is_texture(Op op) { return op == Op::tex || op == Op::tex_bias || op == Op::tex_lod || op == Op::tex_grad; }

}  // namespace luxel::shading::counted
