#pragma once
// A mesh's indices in an element buffer, as W3 and W4 upload them: the index type the mesh keeps
// (16 or 32 bits), so that llvmpipe reads what luxel's draws read.

#include "luxel/scenes/scene.hpp"

#include <GL/glcorearb.h>

namespace luxel::llvmpipe {

struct MeshIndices {
  GLuint buffer = 0;  ///< 0: the mesh is not indexed
  GLenum type = 0;    ///< GL_UNSIGNED_SHORT or GL_UNSIGNED_INT; 0: draw with glDrawArrays
  GLsizei count = 0;  ///< indices, or vertices when not indexed
};

/// Uploads `mesh`'s indices into an element buffer bound to the vertex array bound now (the caller
/// deletes `buffer`).
MeshIndices upload_indices(const scenes::Mesh& mesh);

/// Draws the bound vertex array's triangles through `indices` (glDrawArrays when not indexed).
void draw_triangles(const MeshIndices& indices);

}  // namespace luxel::llvmpipe
