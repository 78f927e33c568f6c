#include "mesh/mesh_io.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace zs {

namespace {

// Binary records gathered in a buffer of a few hundred kilobytes before they reach the
// stream: a stream write per float costs more than formatting the whole record.
class Bytes {
 public:
  explicit Bytes(std::ostream& out) : out_(out) { buf_.reserve(kFlushAt + 64); }
  ~Bytes() { flush(); }
  Bytes(const Bytes&) = delete;
  Bytes& operator=(const Bytes&) = delete;

  void put(const void* data, std::size_t n) {
    const char* c = static_cast<const char*>(data);
    buf_.insert(buf_.end(), c, c + n);
    if (buf_.size() >= kFlushAt) flush();
  }
  void putFloat(float v) { put(&v, 4); }
  void putU32(std::uint32_t v) { put(&v, 4); }
  void flush() {
    out_.write(buf_.data(), std::streamsize(buf_.size()));
    buf_.clear();
  }

 private:
  static constexpr std::size_t kFlushAt = 1 << 18;
  std::ostream& out_;
  std::vector<char> buf_;
};

// STL stores one normal per facet: the triangle's own, which agrees with its winding,
// computed from the corners as stored (in float), as readers recompute it.
std::array<float, 3> facetNormal(const Mesh& m, const std::array<std::uint32_t, 3>& t) {
  auto stored = [&](std::uint32_t v) {
    const auto& p = m.positions[v];
    return std::array<double, 3>{double(float(p[0])), double(float(p[1])), double(float(p[2]))};
  };
  const auto a = stored(t[0]), b = stored(t[1]), c = stored(t[2]);
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]},
               v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                       u[0] * v[1] - u[1] * v[0]};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(len > 0)) return {0, 0, 0};
  return {float(n[0] / len), float(n[1] / len), float(n[2] / len)};
}

void writeStl(const Mesh& m, std::ostream& out) {
  char header[80] = {};
  std::snprintf(header, sizeof header, "zeroset mesh: %zu triangles", m.triangles.size());
  Bytes bytes(out);
  bytes.put(header, 80);
  bytes.putU32(std::uint32_t(m.triangles.size()));
  for (const auto& t : m.triangles) {
    float record[12];
    const std::array<float, 3> n = facetNormal(m, t);
    std::copy(n.begin(), n.end(), record);
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t c = 0; c < 3; ++c) record[3 + 3 * k + c] = float(m.positions[t[k]][c]);
    bytes.put(record, sizeof record);
    const std::uint16_t attributes = 0;
    bytes.put(&attributes, 2);
  }
}

void writePly(const Mesh& m, std::ostream& out) {
  out << "ply\nformat binary_little_endian 1.0\ncomment zeroset mesh\n"
      << "element vertex " << m.positions.size() << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "property float nx\nproperty float ny\nproperty float nz\n"
      << "element face " << m.triangles.size() << "\n"
      << "property list uchar int vertex_indices\nend_header\n";
  Bytes bytes(out);
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    for (double c : m.positions[v]) bytes.putFloat(float(c));
    for (float c : m.normals[v]) bytes.putFloat(c);
  }
  for (const auto& t : m.triangles) {
    const std::uint8_t three = 3;
    bytes.put(&three, 1);
    for (std::uint32_t v : t) bytes.putU32(v);
  }
}

void writeObj(const Mesh& m, std::ostream& out) {
  out << "# zeroset mesh: " << m.positions.size() << " vertices, " << m.triangles.size()
      << " triangles\n";
  Bytes bytes(out);
  char line[128];
  auto put = [&](int length) {
    bytes.put(line, std::size_t(std::clamp(length, 0, int(sizeof line) - 1)));
  };
  for (const auto& p : m.positions)
    put(std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p[0], p[1], p[2]));
  for (const auto& n : m.normals)
    put(std::snprintf(line, sizeof line, "vn %.6g %.6g %.6g\n", double(n[0]), double(n[1]),
                      double(n[2])));
  for (const auto& t : m.triangles)  // OBJ counts from 1
    put(std::snprintf(line, sizeof line, "f %u//%u %u//%u %u//%u\n", t[0] + 1, t[0] + 1, t[1] + 1,
                      t[1] + 1, t[2] + 1, t[2] + 1));
}

}  // namespace

std::optional<MeshFormat> meshFormatFor(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos) return std::nullopt;
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == "stl") return MeshFormat::Stl;
  if (ext == "ply") return MeshFormat::Ply;
  if (ext == "obj") return MeshFormat::Obj;
  return std::nullopt;
}

std::string writeMesh(const Mesh& mesh, const std::string& path, MeshFormat format) {
  std::ofstream out(path, std::ios::binary);
  if (!out) return "cannot write " + path + ": " + std::strerror(errno);
  switch (format) {
    case MeshFormat::Stl:
      writeStl(mesh, out);
      break;
    case MeshFormat::Ply:
      writePly(mesh, out);
      break;
    case MeshFormat::Obj:
      writeObj(mesh, out);
      break;
  }
  out.close();
  if (!out) return "error while writing " + path + " (disk full?)";
  return {};
}

}  // namespace zs
