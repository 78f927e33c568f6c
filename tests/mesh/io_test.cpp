// The files as written: binary STL of the right size with facet normals that agree with the
// winding, PLY's header and size, OBJ's counts, and the format chosen by extension.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "mesh/mesh_io.hpp"
#include "mesh_fixture.hpp"

namespace zs {
namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(MeshIo, FormatFollowsTheExtension) {
  EXPECT_EQ(meshFormatFor("a.stl"), MeshFormat::Stl);
  EXPECT_EQ(meshFormatFor("dir.x/a.STL"), MeshFormat::Stl);
  EXPECT_EQ(meshFormatFor("a.ply"), MeshFormat::Ply);
  EXPECT_EQ(meshFormatFor("a.Obj"), MeshFormat::Obj);
  EXPECT_EQ(meshFormatFor("a.png"), std::nullopt);
  EXPECT_EQ(meshFormatFor("stl"), std::nullopt);
}

TEST(MeshIo, WritesStlPlyAndObj) {
  const MeshResult r = testing::meshOf("x^2 + y^2 + z^2 - 1", testing::cube(1.5), 4);
  const Mesh& m = r.mesh;
  ASSERT_GT(m.triangles.size(), 0u);
  const auto dir =
      std::filesystem::temp_directory_path() / ("zs_mesh_io_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);

  ASSERT_EQ(writeMesh(m, (dir / "s.stl").string(), MeshFormat::Stl), "");
  const std::string stl = slurp(dir / "s.stl");
  ASSERT_EQ(stl.size(), 84 + 50 * m.triangles.size());
  std::uint32_t count;
  std::memcpy(&count, stl.data() + 80, 4);
  EXPECT_EQ(count, m.triangles.size());
  // The first facet's normal points away from the origin, as the sphere's outward normal.
  float f[12];
  std::memcpy(f, stl.data() + 84, sizeof f);
  const float dotOut = f[0] * f[3] + f[1] * f[4] + f[2] * f[5];
  EXPECT_GT(dotOut, 0.0f);

  ASSERT_EQ(writeMesh(m, (dir / "s.ply").string(), MeshFormat::Ply), "");
  const std::string ply = slurp(dir / "s.ply");
  const auto end = ply.find("end_header\n");
  ASSERT_NE(end, std::string::npos);
  EXPECT_NE(ply.find("element vertex " + std::to_string(m.positions.size())), std::string::npos);
  EXPECT_NE(ply.find("property float nx"), std::string::npos);
  EXPECT_EQ(ply.size(), end + 11 + 24 * m.positions.size() + 13 * m.triangles.size());

  ASSERT_EQ(writeMesh(m, (dir / "s.obj").string(), MeshFormat::Obj), "");
  std::istringstream obj(slurp(dir / "s.obj"));
  std::size_t v = 0, vn = 0, faces = 0;
  for (std::string line; std::getline(obj, line);) {
    v += line.rfind("v ", 0) == 0;
    vn += line.rfind("vn ", 0) == 0;
    faces += line.rfind("f ", 0) == 0;
  }
  EXPECT_EQ(v, m.positions.size());
  EXPECT_EQ(vn, m.positions.size());
  EXPECT_EQ(faces, m.triangles.size());

  EXPECT_NE(writeMesh(m, (dir / "no/such/dir/s.stl").string(), MeshFormat::Stl), "");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace zs
