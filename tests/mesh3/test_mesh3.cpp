// Meshes as shapes (issue 17 items 1–2): readers with faces, exact validation, convexity, exact
// convex decomposition. Oracles: CGAL's Polygon_mesh_processing self-intersection test and
// Side_of_triangle_mesh (oracle_cgal.cpp), exact rational volumes (GMP), voxel membership for
// polycubes, hull volumes for convexity.
#include <pendepth/io.hpp>
#include <pendepth/mesh3.hpp>
#include <pendepth/pendepth.hpp>

#include "mesh_gen.hpp"
#include "oracle_cgal.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

using namespace pendepth;
using namespace mesh3_test;

namespace {

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "(no error)";
}

mpq_class hull_six_volume(const ConvexPolytope& P) {
  std::vector<Vec3> v(P.vertices().begin(), P.vertices().end());
  return six_volume(v, P.triangles());
}

bool in_hull(const ConvexPolytope& P, const Vec3& q) {
  for (const auto& t : P.triangles())
    if (predicates::orient3d(P[t[0]], P[t[1]], P[t[2]], q) > 0) return false;
  return true;
}

std::vector<std::array<std::size_t, 3>> tris_of(const Mesh3& m) {
  return {m.triangles().begin(), m.triangles().end()};
}

Gen reversed(Gen g) {
  for (auto& f : g.faces) std::reverse(f.begin(), f.end());
  return g;
}

}  // namespace

// ---- readers ----

TEST(MeshReaders, EveryFormatGivesTheSameSolid) {
  const Gen g = polycube(l_block());
  const mpq_class six = six_volume(g.points, fan(g));
  ASSERT_EQ(six, 30);  // 5 voxels
  const std::vector<std::pair<std::string, std::pair<io::MeshFormat, std::string>>> files = {
      {"obj", {io::MeshFormat::Obj, write_obj(g)}},
      {"off", {io::MeshFormat::Off, write_off(g)}},
      {"stl ascii", {io::MeshFormat::Stl, write_stl_ascii(g)}},
      {"stl binary", {io::MeshFormat::Stl, write_stl_binary(g)}},
      {"ply ascii", {io::MeshFormat::Ply, write_ply(g, "ascii")}},
      {"ply le", {io::MeshFormat::Ply, write_ply(g, "binary_little_endian")}},
      {"ply be", {io::MeshFormat::Ply, write_ply(g, "binary_big_endian")}}};
  for (const auto& [what, f] : files) {
    SCOPED_TRACE(what);
    const io::MeshFile file = io::parse_mesh(f.second, f.first, "m");
    const bool stl = f.first == io::MeshFormat::Stl;
    EXPECT_EQ(file.faces(), stl ? 2 * g.faces.size() : g.faces.size());
    EXPECT_EQ(file.points.size(), g.points.size());  // STL: repeated corners merged exactly
    const Mesh3 m = Mesh3::validate(file, "L");
    EXPECT_FALSE(m.flipped());
    EXPECT_FALSE(m.convex());
    EXPECT_EQ(six_volume(file.points, tris_of(m)), six);
    EXPECT_EQ(m.triangles().size(), 2 * g.faces.size());
  }
}

TEST(MeshReaders, FaceLocationsAndErrors) {
  const Gen g = cube();
  const io::MeshFile obj = io::parse_mesh(write_obj(g), io::MeshFormat::Obj, "c.obj");
  EXPECT_EQ(obj.face_where(0), "c.obj:10: face 0");  // comment + 8 vertices, then the faces
  EXPECT_EQ(obj.vertex_name(0), "1");
  const io::MeshFile stl = io::parse_mesh(write_stl_binary(g), io::MeshFormat::Stl, "c.stl");
  EXPECT_EQ(stl.face_where(1), "c.stl: face 1 (byte offset 134)");
  const io::MeshFile ply = io::parse_mesh(write_ply(g, "binary_little_endian"), io::MeshFormat::Ply, "c.ply");
  EXPECT_TRUE(ply.byte_offsets);
  // OBJ relative indices and v/vt/vn references.
  const io::MeshFile rel = io::parse_mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf -3/1/1 -2//1 -1\n", io::MeshFormat::Obj, "r.obj");
  ASSERT_EQ(rel.faces(), 1u);
  EXPECT_EQ(rel.indices, (std::vector<std::size_t>{0, 1, 2}));
  // The point readers' messages are kept by parse_mesh.
  EXPECT_EQ(error_of([] { io::parse_mesh("v 0 0 0\nf 1 2 3\n", io::MeshFormat::Obj, "m.obj"); }),
            "m.obj:2: reference to vertex 3, but the file has 1 vertices");
  EXPECT_EQ(error_of([] { io::parse_mesh("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n", io::MeshFormat::Off, "m.off"); }),
            "m.off:6: face 0: vertex index 5 is out of range (the file has 3 vertices) (the header at line 2 declares 3 vertices and 1 face)");
  // PLY errors: header, ASCII body lines, binary byte offsets.
  auto ply_error = [](const std::string& s) { return error_of([&] { io::parse_ply(s, "m.ply"); }); };
  EXPECT_EQ(ply_error("plx\n"), "m.ply:1: not a PLY file: the first line must be 'ply'");
  EXPECT_EQ(ply_error("ply\nformat ascii 2.0\n"), "m.ply:2: expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
  EXPECT_EQ(ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n"),
            "m.ply:3: the vertex element has no 'z' property");
  EXPECT_EQ(ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"),
            "m.ply:6: the file ends inside the PLY header (no 'end_header')");
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                           "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_EQ(ply_error(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"), "m.ply:13: face 0: vertex index 3 is out of range (the file has 3 vertices)");
  EXPECT_EQ(ply_error(head + "0 0 0\n1 0 nan\n"), "m.ply:11: vertex 1 has a non-finite z: 'nan'");
  EXPECT_EQ(ply_error(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n7\n"), "m.ply:14: unexpected '7' after the last element");
  EXPECT_EQ(ply_error(head + "0 0 0\n1 0 0\n0 1 0\n"), "m.ply:12: the file ends before face 0 (the header declares 1 face elements)");
  EXPECT_EQ(ply_error(head + "0 0 0 1\n"), "m.ply:10: malformed vertex 0: 1 values more than its properties");
  std::string bin = write_ply(cube(), "binary_little_endian");
  EXPECT_NE(ply_error(bin.substr(0, bin.size() - 3)).find("the file ends inside face 5 (the header declares 6 face elements) (byte offset"),
            std::string::npos);
  EXPECT_NE(ply_error(bin + "xx").find("2 bytes after the last element (byte offset"), std::string::npos);
  EXPECT_EQ(error_of([] { io::read_mesh("a.xyz"); }), "a.xyz: unknown 3D shape format '.xyz' (expected .obj, .off, .stl or .ply)");
}

TEST(MeshReaders, StlMergesExactlyEqualCornersAndPlyTakesItsVariants) {
  // -0 and 0 are one vertex; 1 and the next float up are two.
  const std::string stl = "solid s\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
                          "facet normal 0 0 0\nouter loop\nvertex -0 0 0\nvertex 0 1 0\nvertex 1.0000001 0 0\nendloop\nendfacet\nendsolid s\n";
  const io::MeshFile f = io::parse_mesh(stl, io::MeshFormat::Stl, "s.stl");
  EXPECT_EQ(f.points.size(), 4u);
  EXPECT_EQ(f.indices, (std::vector<std::size_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(f.face_where(1), "s.stl:9: face 1");  // its facet line
  // PLY: float coordinates, the index list named vertex_index with other types, an extra element
  // and properties to skip, binary big endian.
  std::string ply = "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty short id\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 4\nproperty uchar flags\nproperty list ushort uint vertex_index\n"
                    "element edge 1\nproperty list uchar int ends\nend_header\n";
  const Gen tet{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
  for (std::size_t i = 0; i < 4; ++i) {
    put<std::int16_t>(ply, static_cast<std::int16_t>(i), true);
    for (int a = 0; a < 3; ++a) put<float>(ply, static_cast<float>(tet.points[i][a]), true);
  }
  for (const auto& face : tet.faces) {
    put<std::uint8_t>(ply, 1, true);
    put<std::uint16_t>(ply, 3, true);
    for (std::size_t v : face) put<std::uint32_t>(ply, static_cast<std::uint32_t>(v), true);
  }
  put<std::uint8_t>(ply, 2, true);
  put<std::int32_t>(ply, 0, true);
  put<std::int32_t>(ply, 1, true);
  const io::MeshFile p = io::parse_mesh(ply, io::MeshFormat::Ply, "t.ply");
  EXPECT_EQ(p.points, tet.points);
  const Mesh3 m = Mesh3::validate(p, "tet");
  EXPECT_TRUE(m.convex());
  EXPECT_EQ(six_volume(p.points, tris_of(m)), 1);
}

// ---- validation: every defect class, the error text ----

TEST(MeshValidate, DefectsAreNamed) {
  auto err = [](const Gen& g) { return error_of([&] { Mesh3::validate(to_file(g, "g.off"), "M"); }); };
  Gen open = cube();
  open.faces.pop_back();
  EXPECT_NE(err(open).find(": M: the mesh is not closed: edge "), std::string::npos) << err(open);
  EXPECT_NE(err(open).find("belongs to this face only"), std::string::npos);

  Gen flipped_face = cube();
  std::reverse(flipped_face.faces[2].begin(), flipped_face.faces[2].end());
  EXPECT_NE(err(flipped_face).find("inconsistent orientation: this face and g.off:"), std::string::npos) << err(flipped_face);

  // Two voxels sharing only an edge: that edge has 4 faces.
  EXPECT_NE(err(polycube({{0, 0, 0}, {1, 1, 0}})).find("non-manifold edge "), std::string::npos);
  EXPECT_NE(err(polycube({{0, 0, 0}, {1, 1, 0}})).find("shared by 4 faces"), std::string::npos);
  // Two voxels sharing only a corner: a vertex with two fans.
  EXPECT_NE(err(polycube({{0, 0, 0}, {1, 1, 1}})).find("non-manifold vertex "), std::string::npos)
      << err(polycube({{0, 0, 0}, {1, 1, 1}}));
  // Two separate cubes.
  EXPECT_NE(err(polycube({{0, 0, 0}, {2, 0, 0}})).find("more than one closed surface"), std::string::npos);

  // A corner pushed through the opposite face.
  Gen poked = cube();
  poked.faces.clear();
  for (const auto& t : fan(cube())) poked.faces.push_back({t[0], t[1], t[2]});
  for (auto& p : poked.points)
    if (p == Vec3(1, 1, 1)) p = Vec3(0.25, 0.25, -1);
  EXPECT_NE(err(poked).find("self-intersection: this face and "), std::string::npos) << err(poked);

  Gen degenerate;
  degenerate.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
  degenerate.faces = {{0, 1, 2}, {0, 3, 1}};
  EXPECT_EQ(err(degenerate), "g.off:1: face 0: M: zero-area face (its three vertices are collinear)");
  Gen repeated = degenerate;
  repeated.faces = {{0, 1, 0}};
  EXPECT_EQ(err(repeated), "g.off:1: face 0: M: the face repeats vertex 0");
  Gen bent = cube();
  bent.points[bent.faces[0][0]] += Vec3(1e-9, 1e-9, 1e-9);
  EXPECT_NE(err(bent).find("is not planar"), std::string::npos) << err(bent);
  Gen star;  // a pentagon with a reflex corner as one face
  star.points = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 0.5, 0}, {0, 2, 0}};
  star.faces = {{0, 1, 2, 3, 4}};
  EXPECT_NE(err(star).find("is not a strictly convex polygon"), std::string::npos) << err(star);
  Gen pentagram;  // every corner turns left, but the boundary winds twice
  for (int i = 0; i < 5; ++i)
    pentagram.points.emplace_back(std::cos(2 * 3.14159 * i / 5), std::sin(2 * 3.14159 * i / 5), 0);
  pentagram.faces = {{0, 2, 4, 1, 3}};
  EXPECT_EQ(err(pentagram), "g.off:1: face 0: M: a face of 5 vertices winds 2 times around its interior (a star polygon): give triangles");
  Gen pillow = pentagram;  // two triangles back to back: closed, manifold, oriented, but flat
  pillow.faces = {{0, 1, 2}, {0, 2, 1}};
  EXPECT_EQ(err(pillow), "g.off:1: face 0: M: self-intersection: this face and g.off:2: face 1 coincide (same three vertices)");
  EXPECT_EQ(error_of([] { Mesh3::validate(io::parse_mesh("v 0 0 0\n", io::MeshFormat::Obj, "p.obj"), "M"); }),
            "p.obj: M: no faces");
  // Hand-built MeshFiles are checked, not trusted.
  io::MeshFile hand = to_file(cube(), "h");
  hand.indices[5] = 99;
  EXPECT_EQ(error_of([&] { Mesh3::validate(hand, "M"); }), "h:2: face 1: M: vertex index 99 is out of range (8 vertices)");
  hand = to_file(cube(), "h");
  hand.points[0].x() = std::numeric_limits<double>::infinity();
  EXPECT_NE(error_of([&] { Mesh3::validate(hand, "M"); }).find("is not finite"), std::string::npos);
  hand = to_file(cube(), "h");
  hand.face_start.back() -= 1;
  EXPECT_EQ(error_of([&] { Mesh3::validate(hand, "M"); }), "h: M: face_start does not span the indices");
}

TEST(MeshValidate, InwardMeshesAreFlipped) {
  for (const Gen& g : {cube(), polycube(cup(2)), torus(12, 8)}) {
    const Mesh3 out = Mesh3::validate(to_file(g), "M"), in = Mesh3::validate(to_file(reversed(g)), "M");
    EXPECT_FALSE(out.flipped());
    EXPECT_TRUE(in.flipped());
    EXPECT_GT(six_volume(g.points, tris_of(in)), 0);
    EXPECT_EQ(six_volume(g.points, tris_of(in)), six_volume(g.points, tris_of(out)));
    EXPECT_EQ(in.convex(), out.convex());
  }
}

// Self-intersection verdicts against CGAL's PMP::does_self_intersect on crumpled spheres and tori
// (random radii: folds, pokes through neighbours, shared-vertex and shared-edge overlaps).
TEST(MeshValidate, SelfIntersectionMatchesCgal) {
  std::mt19937_64 rng(17);
  int bad = 0, good = 0;
  for (int trial = 0; trial < 120; ++trial) {
    Gen g = trial % 3 == 2 ? torus(10, 6, 2.0, 1.0) : bumpy_sphere(rng, 6 + trial % 5, 7 + trial % 4, 0.1 * (trial % 12));
    if (trial % 3 == 2) {
      std::uniform_real_distribution<double> U(-0.9, 0.9);
      for (auto& p : g.points) p += Vec3(U(rng), U(rng), U(rng)) * (0.1 * (trial % 10));
    }
    const bool oracle = cgal_self_intersects(g.points, fan(g));
    const std::string e = error_of([&] { Mesh3::validate(to_file(g), "M"); });
    const bool ours = e.find("self-intersection") != std::string::npos;
    if (!ours) EXPECT_TRUE(e == "(no error)" || e.find("zero-area") != std::string::npos) << e;
    if (e.find("zero-area") != std::string::npos) continue;
    EXPECT_EQ(ours, oracle) << "trial " << trial << ": " << e;
    (oracle ? bad : good)++;
  }
  EXPECT_GT(bad, 10);
  EXPECT_GT(good, 10);
}

// ---- convexity ----

// Exact oracle: a valid closed mesh is convex iff its volume equals its vertices' hull volume.
TEST(MeshConvexity, MatchesTheHullVolume) {
  std::mt19937_64 rng(5);
  int convex = 0, not_convex = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const double amp = trial % 4 == 0 ? 0.0 : 0.02 * (trial % 7);
    Gen g = trial % 10 == 9 ? polycube(random_polycube(rng, 1 + trial % 4)) : bumpy_sphere(rng, 5, 6, amp);
    if (trial % 4 == 0) {  // the hull of random points, as a mesh: convex
      std::normal_distribution<double> N(0, 1);
      std::vector<Vec3> pts;
      for (int i = 0; i < 30; ++i) pts.emplace_back(N(rng), N(rng), N(rng));
      const ConvexPolytope H = ConvexPolytope::hull(pts);
      g = Gen{};
      g.points.assign(H.vertices().begin(), H.vertices().end());
      for (const auto& t : H.triangles()) g.faces.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
    }
    Mesh3 m;
    try {
      m = Mesh3::validate(to_file(g), "M");
    } catch (const InvalidInput&) {
      continue;  // a random polycube with a non-manifold contact
    }
    const mpq_class mesh6 = six_volume(g.points, tris_of(m));
    const mpq_class hull6 = hull_six_volume(ConvexPolytope::hull(m.used_points()));
    EXPECT_EQ(m.convex(), mesh6 == hull6) << trial;
    EXPECT_EQ(m.convex(), m.reflex_edges() == 0);
    (m.convex() ? convex : not_convex)++;
  }
  EXPECT_GT(convex, 5);
  EXPECT_GT(not_convex, 5);
  EXPECT_TRUE(Mesh3::validate(to_file(cube()), "c").convex());
  EXPECT_TRUE(Mesh3::validate(to_file(polycube({{0, 0, 0}, {1, 0, 0}})), "box").convex());  // coplanar faces: flat edges
  EXPECT_FALSE(Mesh3::validate(to_file(torus(8, 6)), "t").convex());
}

// ---- decomposition ----

// Polycubes: every cut is axis-aligned through integer coordinates, so the pieces are exact; their
// hull volumes sum exactly to the voxel count (so each piece is convex and they do not overlap)
// and every voxel centre and random point is in a piece iff it is in a voxel.
TEST(MeshDecomposition, PolycubesExactly) {
  std::mt19937_64 rng(3);
  std::vector<std::set<Voxel>> shapes = {l_block(), comb(3), cup(2), {{0, 0, 0}, {1, 0, 0}}};
  for (int k = 0; k < 6; ++k) shapes.push_back(random_polycube(rng, 4 + 2 * k));
  int done = 0;
  for (const auto& vox : shapes) {
    const Gen g = polycube(vox);
    Mesh3 m;
    try {
      m = Mesh3::validate(to_file(g), "P");
    } catch (const InvalidInput&) {
      continue;
    }
    ++done;
    const ConvexDecomposition3& d = m.decomposition();
    EXPECT_EQ(d.rounded_pieces, 0u);
    mpq_class sum = 0;
    for (const auto& P : d.pieces) sum += hull_six_volume(P);
    EXPECT_EQ(sum, 6 * static_cast<long>(vox.size()));
    if (m.convex()) EXPECT_EQ(d.pieces.size(), 1u);
    std::uniform_real_distribution<double> U(-1.5, 6.5);
    for (int i = 0; i < 400; ++i) {
      const Vec3 q(U(rng), U(rng), U(rng));
      const bool inside = vox.count({static_cast<int>(std::floor(q.x())), static_cast<int>(std::floor(q.y())),
                                     static_cast<int>(std::floor(q.z()))}) > 0;
      bool in_piece = false;
      for (const auto& P : d.pieces) in_piece = in_piece || in_hull(P, q);
      EXPECT_EQ(in_piece, inside) << q.transpose();
    }
  }
  EXPECT_GE(done, 6);
}

// A torus: cut vertices are rationals, rounded; the volume sum is within rounding of the mesh's
// and random points inside the mesh (CGAL's Side_of_triangle_mesh) are in some piece.
TEST(MeshDecomposition, TorusCoversTheSolid) {
  const Gen g = torus(8, 5);
  const Mesh3 m = Mesh3::validate(to_file(g), "torus");
  const ConvexDecomposition3& d = m.decomposition();
  EXPECT_GT(d.pieces.size(), 4u);
  EXPECT_EQ(&d, &m.decomposition());  // computed once
  double sum = 0;
  for (const auto& P : d.pieces) sum += hull_six_volume(P).get_d() / 6;
  EXPECT_NEAR(sum, m.volume(), 1e-9 * m.volume());
  const CgalInside oracle(g.points, fan(g));
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> U(-4.2, 4.2), Z(-1.1, 1.1);
  int inside = 0;
  for (int i = 0; i < 600; ++i) {
    const Vec3 q(U(rng), U(rng), Z(rng));
    const int s = oracle.side(q);
    bool in_piece = false;
    for (const auto& P : d.pieces) in_piece = in_piece || in_hull(P, q);
    if (s != 0) EXPECT_EQ(in_piece, s > 0) << q.transpose();
    inside += s > 0;
  }
  EXPECT_GT(inside, 50);
}

// ---- the front door ----

TEST(MeshShape, FromFileChoosesThePath) {
  const auto dir = std::filesystem::temp_directory_path() / "pendepth_test_mesh3";
  std::filesystem::create_directories(dir);
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name, std::ios::binary) << text;
    return (dir / name).string();
  };
  const std::string cube_ply = write("cube.ply", write_ply(cube(), "ascii"));
  const std::string l_obj = write("l.obj", write_obj(polycube(l_block())));
  const std::string pts = write("pts.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0.1 0.1 0.1\n");
  const Shape3 c = Shape3::from_file(cube_ply, "cube");
  EXPECT_TRUE(c.is_convex());
  ASSERT_NE(c.mesh(), nullptr);
  EXPECT_EQ(c.size(), 8u);
  const Shape3 l = Shape3::from_file(l_obj, "L");
  EXPECT_FALSE(l.is_convex());
  EXPECT_TRUE(Pair3(c, l).overlapping(Pose3(), Pose3()));  // a mesh pair (tests/mesh3/test_mesh_pair.cpp)
  const Shape3 lh = Shape3::from_file(l_obj, "L", true);
  EXPECT_TRUE(lh.is_convex());
  EXPECT_EQ(lh.mesh(), nullptr);
  EXPECT_GT(Pair3(c, lh).minimum(Pose3(), Pose3()).depth, 0);
  const Shape3 p = Shape3::from_file(pts, "pts");
  EXPECT_EQ(p.mesh(), nullptr);
  EXPECT_EQ(p.size(), 4u);
  const std::string open = write("open.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n");
  EXPECT_EQ(error_of([&] { Shape3::from_file(open, "O"); }),
            open + ":7: face 0: O: the mesh is not closed: edge 0-2 belongs to this face only");
  std::filesystem::remove_all(dir);
}

// ---- real meshes nobody here drew (libcgal-demo's data/meshes) ----
#ifdef PENDEPTH_CGAL_MESHES
TEST(MeshReal, CgalSampleMeshesValidateOrAreRejectedClearly) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(PENDEPTH_CGAL_MESHES)) {
    const auto ext = e.path().extension();
    if ((ext == ".off" || ext == ".ply" || ext == ".obj" || ext == ".stl") && e.file_size() < 400000)
      files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_GT(files.size(), 50u);
  int valid = 0, rejected = 0;
  for (const auto& f : files) {
    try {
      const Mesh3 m = Mesh3::validate(io::read_mesh(f), "M");
      ++valid;
      EXPECT_GT(m.volume(), 0) << f;
      const mpq_class six = six_volume(std::vector<Vec3>(m.points().begin(), m.points().end()), tris_of(m));
      EXPECT_GT(six, 0) << f;
      if (m.convex()) EXPECT_EQ(six, hull_six_volume(ConvexPolytope::hull(m.used_points()))) << f;
    } catch (const InvalidInput& e) {
      ++rejected;
      EXPECT_EQ(std::string(e.what()).rfind(f.string(), 0), 0u) << e.what();  // names the file
    }
  }
  EXPECT_GT(valid, 10);
  EXPECT_GT(rejected, 10);
  // Known cases: an open cube, a closed cube, a knot.
  const std::string dir = PENDEPTH_CGAL_MESHES;
  EXPECT_NE(error_of([&] { Mesh3::validate(io::read_mesh(dir + "/cube-ouvert.off"), "M"); }).find("not closed"), std::string::npos);
  EXPECT_TRUE(Mesh3::validate(io::read_mesh(dir + "/cube.off"), "M").convex());
}

// Real meshes: exact pieces (cross, star: axis-aligned cuts) sum exactly to the mesh volume;
// rounded ones (hole, tripod) within rounding; random points inside the mesh (CGAL's
// Side_of_triangle_mesh) are in some piece and points outside in none.
TEST(MeshReal, DecompositionOfRealMeshes) {
  std::mt19937_64 rng(21);
  int exact = 0, rounded = 0;
  for (const char* name : {"cross.off", "star.off", "hole.off", "tripod.off", "corner.off"}) {
    SCOPED_TRACE(name);
    const Mesh3 m = Mesh3::validate(io::read_mesh(std::string(PENDEPTH_CGAL_MESHES) + "/" + name), name);
    const ConvexDecomposition3& d = m.decomposition();
    EXPECT_GE(d.pieces.size(), 2u);
    const std::vector<Vec3> pts(m.points().begin(), m.points().end());
    const auto tris = tris_of(m);
    mpq_class s6 = 0;
    for (const auto& P : d.pieces) s6 += hull_six_volume(P);
    if (d.rounded_pieces == 0 && d.dropped_slivers == 0) {
      ++exact;
      EXPECT_EQ(s6, six_volume(pts, tris));
    } else {
      ++rounded;
      EXPECT_NEAR(s6.get_d() / 6, m.volume(), 1e-9 * m.volume());
    }
    const CgalInside oracle(pts, tris);
    Vec3 lo = pts[tris[0][0]], hi = lo;
    for (const auto& t : tris)
      for (std::size_t v : t) lo = lo.cwiseMin(pts[v]), hi = hi.cwiseMax(pts[v]);
    std::uniform_real_distribution<double> U(0, 1);
    int inside = 0;
    for (int i = 0; i < 300; ++i) {
      const Vec3 q = lo + (hi - lo).cwiseProduct(Vec3(U(rng), U(rng), U(rng)));
      const int s = oracle.side(q);
      bool in_piece = false;
      for (const auto& P : d.pieces) in_piece = in_piece || in_hull(P, q);
      if (s != 0) EXPECT_EQ(in_piece, s > 0) << q.transpose();
      inside += s > 0;
    }
    EXPECT_GT(inside, 5);
  }
  EXPECT_GE(exact, 2);
  EXPECT_GE(rounded, 2);
}
#endif
