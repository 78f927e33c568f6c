#pragma once
// Writes a Mesh to a file: binary STL (facet normals from the triangles), binary PLY and
// OBJ (both with the per-vertex normals of the symbolic gradient). The format follows the
// file name's extension.
#include <optional>
#include <string>

#include "mesh/mesh.hpp"

namespace zs {

enum class MeshFormat { Stl, Ply, Obj };

// The format for ".stl", ".ply" or ".obj" (any letter case); nothing for other names.
std::optional<MeshFormat> meshFormatFor(const std::string& path);

// "" on success, else a message naming the file.
std::string writeMesh(const Mesh& mesh, const std::string& path, MeshFormat format);

}  // namespace zs
