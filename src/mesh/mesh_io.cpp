#include "mesh/mesh_io.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

namespace zs {

namespace {

void putFloat(std::ostream& out, float v) { out.write(reinterpret_cast<const char*>(&v), 4); }
void putU32(std::ostream& out, std::uint32_t v) { out.write(reinterpret_cast<const char*>(&v), 4); }

// STL stores one normal per facet: the triangle's own, which agrees with its winding,
// computed from the corners as stored (in float), as readers recompute it.
std::array<float, 3> facetNormal(const Mesh& m, const std::array<std::uint32_t, 3>& t) {
  auto stored = [&](std::uint32_t v) {
    const auto& p = m.positions[v];
    return std::array<double, 3>{double(float(p[0])), double(float(p[1])), double(float(p[2]))};
  };
  const auto a = stored(t[0]), b = stored(t[1]), c = stored(t[2]);
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(len > 0)) return {0, 0, 0};
  return {float(n[0] / len), float(n[1] / len), float(n[2] / len)};
}

void writeStl(const Mesh& m, std::ostream& out) {
  char header[80] = {};
  std::snprintf(header, sizeof header, "zeroset mesh: %zu triangles", m.triangles.size());
  out.write(header, 80);
  putU32(out, std::uint32_t(m.triangles.size()));
  for (const auto& t : m.triangles) {
    for (float f : facetNormal(m, t)) putFloat(out, f);
    for (std::uint32_t v : t)
      for (double c : m.positions[v]) putFloat(out, float(c));
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
}

void writePly(const Mesh& m, std::ostream& out) {
  out << "ply\nformat binary_little_endian 1.0\ncomment zeroset mesh\n"
      << "element vertex " << m.positions.size() << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "property float nx\nproperty float ny\nproperty float nz\n"
      << "element face " << m.triangles.size() << "\n"
      << "property list uchar int vertex_indices\nend_header\n";
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    for (double c : m.positions[v]) putFloat(out, float(c));
    for (float c : m.normals[v]) putFloat(out, c);
  }
  for (const auto& t : m.triangles) {
    const std::uint8_t three = 3;
    out.write(reinterpret_cast<const char*>(&three), 1);
    for (std::uint32_t v : t) putU32(out, v);
  }
}

void writeObj(const Mesh& m, std::ostream& out) {
  out << "# zeroset mesh: " << m.positions.size() << " vertices, " << m.triangles.size()
      << " triangles\n";
  char line[128];
  for (const auto& p : m.positions) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p[0], p[1], p[2]);
    out << line;
  }
  for (const auto& n : m.normals) {
    std::snprintf(line, sizeof line, "vn %.6g %.6g %.6g\n", double(n[0]), double(n[1]), double(n[2]));
    out << line;
  }
  for (const auto& t : m.triangles) {  // OBJ counts from 1
    std::snprintf(line, sizeof line, "f %u//%u %u//%u %u//%u\n", t[0] + 1, t[0] + 1, t[1] + 1,
                  t[1] + 1, t[2] + 1, t[2] + 1);
    out << line;
  }
}

}  // namespace

std::optional<MeshFormat> meshFormatFor(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos) return std::nullopt;
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == "stl") return MeshFormat::Stl;
  if (ext == "ply") return MeshFormat::Ply;
  if (ext == "obj") return MeshFormat::Obj;
  return std::nullopt;
}

std::string writeMesh(const Mesh& mesh, const std::string& path, MeshFormat format) {
  std::ofstream out(path, std::ios::binary);
  if (!out) return "cannot write " + path + ": " + std::strerror(errno);
  switch (format) {
    case MeshFormat::Stl: writeStl(mesh, out); break;
    case MeshFormat::Ply: writePly(mesh, out); break;
    case MeshFormat::Obj: writeObj(mesh, out); break;
  }
  out.close();
  if (!out) return "error while writing " + path + " (disk full?)";
  return {};
}

}  // namespace zs
