#include "mesh_indices.hpp"

#include <type_traits>
#include <variant>

namespace luxel::llvmpipe {

MeshIndices upload_indices(const scenes::Mesh& mesh) {
  MeshIndices out;
  if (!mesh.indexed()) {
    out.count = GLsizei(mesh.vertex_count());
    return out;
  }
  glGenBuffers(1, &out.buffer);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, out.buffer);
  std::visit(
      [&](const auto& indices) {
        using Index = typename std::decay_t<decltype(indices)>::value_type;
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(Index)), indices.data(), GL_STATIC_DRAW);
        out.type = sizeof(Index) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT;
        out.count = GLsizei(indices.size());
      },
      mesh.indices);
  return out;
}

void draw_triangles(const MeshIndices& indices) {
  if (indices.type)
    glDrawElements(GL_TRIANGLES, indices.count, indices.type, nullptr);
  else
    glDrawArrays(GL_TRIANGLES, 0, indices.count);
}

}  // namespace luxel::llvmpipe
