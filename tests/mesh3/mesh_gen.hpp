// Generated meshes for test_mesh3: polycubes (unions of unit voxels: L-blocks, combs, cups),
// tori, random star-shaped spheres, and writers to OBJ / OFF / STL / PLY bytes.
#pragma once

#include <pendepth/io.hpp>

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace mesh3_test {

using pendepth::Vec3;
namespace io = pendepth::io;

struct Gen {
  std::vector<Vec3> points;
  std::vector<std::vector<std::size_t>> faces;
};

inline io::MeshFile to_file(const Gen& g, const std::string& source = "gen") {
  io::MeshFile f;
  f.source = source;
  f.points = g.points;
  for (std::size_t i = 0; i < g.faces.size(); ++i) {
    f.begin_face(i + 1);
    for (std::size_t v : g.faces[i]) f.indices.push_back(v);
  }
  f.face_start.push_back(f.indices.size());
  return f;
}

using Voxel = std::array<int, 3>;

/// The boundary of a union of unit voxels [x, x+1]×[y, y+1]×[z, z+1], as outward quads.
inline Gen polycube(const std::set<Voxel>& vox) {
  Gen g;
  std::map<std::array<int, 3>, std::size_t> id;
  auto vid = [&](int x, int y, int z) {
    auto [it, fresh] = id.emplace(std::array<int, 3>{x, y, z}, g.points.size());
    if (fresh) g.points.emplace_back(x, y, z);
    return it->second;
  };
  for (const Voxel& v : vox)
    for (int a = 0; a < 3; ++a)
      for (int s : {-1, 1}) {
        Voxel n = v;
        n[a] += s;
        if (vox.count(n)) continue;
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        std::array<std::array<int, 3>, 4> q;
        for (int k = 0; k < 4; ++k) {
          q[k] = v;
          q[k][a] += s > 0 ? 1 : 0;
        }
        // (b, c) corners CCW seen from +a: (0,0) (1,0) (1,1) (0,1); reversed for −a.
        const int cb[4] = {0, 1, 1, 0}, cc[4] = {0, 0, 1, 1};
        std::vector<std::size_t> f;
        for (int k = 0; k < 4; ++k) {
          const int j = s > 0 ? k : 3 - k;
          auto p = q[j];
          p[b] += cb[j];
          p[c] += cc[j];
          f.push_back(vid(p[0], p[1], p[2]));
        }
        g.faces.push_back(f);
      }
  return g;
}

inline Gen cube() { return polycube({{0, 0, 0}}); }
inline std::set<Voxel> l_block() { return {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 2, 0}}; }
inline std::set<Voxel> comb(int teeth) {
  std::set<Voxel> v;
  for (int x = 0; x < 2 * teeth - 1; ++x) v.insert({x, 0, 0});
  for (int x = 0; x < 2 * teeth - 1; x += 2) v.insert({x, 1, 0}), v.insert({x, 2, 0});
  return v;
}
/// A cup: a 3×3 floor and walls of height h around the middle cell.
inline std::set<Voxel> cup(int h) {
  std::set<Voxel> v;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y) {
      v.insert({x, y, 0});
      if (x != 1 || y != 1)
        for (int z = 1; z <= h; ++z) v.insert({x, y, z});
    }
  return v;
}
/// Random connected polycube grown from the origin (face-adjacent growth), then kept only if its
/// boundary is a manifold (checked by the caller through validation).
inline std::set<Voxel> random_polycube(std::mt19937_64& rng, int n) {
  std::set<Voxel> v{{0, 0, 0}};
  std::uniform_int_distribution<int> dir(0, 5);
  while (static_cast<int>(v.size()) < n) {
    auto it = v.begin();
    std::advance(it, std::uniform_int_distribution<std::size_t>(0, v.size() - 1)(rng));
    Voxel w = *it;
    const int d = dir(rng);
    w[d / 2] += d % 2 ? 1 : -1;
    v.insert(w);
  }
  return v;
}

/// Torus, major radius R, minor r, n × m quads split into triangles, outward.
inline Gen torus(int n, int m, double R = 3, double r = 1) {
  Gen g;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * pi * i / n, w = 2 * pi * j / m;
      g.points.emplace_back((R + r * std::cos(w)) * std::cos(u), (R + r * std::cos(w)) * std::sin(u), r * std::sin(w));
    }
  auto id = [&](int i, int j) { return static_cast<std::size_t>(((i + n) % n) * m + (j + m) % m); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      g.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      g.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return g;
}

/// A UV sphere with radii scaled by 1 + amp·random (star-shaped, non-convex for amp > 0), outward.
inline Gen bumpy_sphere(std::mt19937_64& rng, int n, int m, double amp) {
  Gen g;
  const double pi = std::acos(-1.0);
  std::uniform_real_distribution<double> U(-1, 1);
  g.points.emplace_back(0, 0, 1 + amp * U(rng));
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double th = pi * i / n, ph = 2 * pi * j / m, rad = 1 + amp * U(rng);
      g.points.emplace_back(rad * std::sin(th) * std::cos(ph), rad * std::sin(th) * std::sin(ph), rad * std::cos(th));
    }
  g.points.emplace_back(0, 0, -1 - amp * U(rng));
  const std::size_t south = g.points.size() - 1;
  auto id = [&](int i, int j) { return static_cast<std::size_t>(1 + (i - 1) * m + (j + m) % m); };
  for (int j = 0; j < m; ++j) g.faces.push_back({0, id(1, j), id(1, j + 1)});
  for (int i = 1; i + 1 < n; ++i)
    for (int j = 0; j < m; ++j) {
      g.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      g.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  for (int j = 0; j < m; ++j) g.faces.push_back({south, id(n - 1, j + 1), id(n - 1, j)});
  return g;
}

/// Triangles of a generated mesh (quads fanned), for the oracles.
inline std::vector<std::array<std::size_t, 3>> fan(const Gen& g) {
  std::vector<std::array<std::size_t, 3>> t;
  for (const auto& f : g.faces)
    for (std::size_t i = 1; i + 1 < f.size(); ++i) t.push_back({f[0], f[i], f[i + 1]});
  return t;
}

/// Exact 6 × signed volume of triangles over points.
template <class Tris>
mpq_class six_volume(const std::vector<Vec3>& p, const Tris& tris) {
  mpq_class s = 0;
  for (const auto& t : tris) {
    const Vec3 &a = p[t[0]], &b = p[t[1]], &c = p[t[2]];
    mpq_class ax(a.x()), ay(a.y()), az(a.z()), bx(b.x()), by(b.y()), bz(b.z()), cx(c.x()), cy(c.y()), cz(c.z());
    s += ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
  }
  return s;
}

inline std::string num(double x) {
  std::ostringstream o;
  o.precision(17);
  o << x;
  return o.str();
}

inline std::string write_obj(const Gen& g) {
  std::string s = "# gen\n";
  for (const auto& p : g.points) s += "v " + num(p.x()) + " " + num(p.y()) + " " + num(p.z()) + "\n";
  for (const auto& f : g.faces) {
    s += "f";
    for (std::size_t v : f) s += " " + std::to_string(v + 1);
    s += "\n";
  }
  return s;
}

inline std::string write_off(const Gen& g) {
  std::string s = "OFF\n" + std::to_string(g.points.size()) + " " + std::to_string(g.faces.size()) + " 0\n";
  for (const auto& p : g.points) s += num(p.x()) + " " + num(p.y()) + " " + num(p.z()) + "\n";
  for (const auto& f : g.faces) {
    s += std::to_string(f.size());
    for (std::size_t v : f) s += " " + std::to_string(v);
    s += "\n";
  }
  return s;
}

inline std::string write_stl_ascii(const Gen& g) {
  std::string s = "solid gen\n";
  for (const auto& t : fan(g)) {
    s += " facet normal 0 0 0\n  outer loop\n";
    for (std::size_t v : t) s += "   vertex " + num(g.points[v].x()) + " " + num(g.points[v].y()) + " " + num(g.points[v].z()) + "\n";
    s += "  endloop\n endfacet\n";
  }
  return s + "endsolid gen\n";
}

template <class T>
void put(std::string& s, T x, bool big) {
  auto u = std::bit_cast<std::array<char, sizeof(T)>>(x);
  if (big) std::reverse(u.begin(), u.end());
  s.append(u.data(), u.size());
}

inline std::string write_stl_binary(const Gen& g) {
  std::string s(80, ' ');
  const auto t = fan(g);
  put<std::uint32_t>(s, static_cast<std::uint32_t>(t.size()), false);
  for (const auto& tri : t) {
    for (int k = 0; k < 3; ++k) put<float>(s, 0.0f, false);
    for (std::size_t v : tri)
      for (int a = 0; a < 3; ++a) put<float>(s, static_cast<float>(g.points[v][a]), false);
    put<std::uint16_t>(s, 0, false);
  }
  return s;
}

/// PLY: "ascii", "binary_little_endian" or "binary_big_endian"; vertices as double plus an
/// unused uchar property, faces as uchar-counted int lists.
inline std::string write_ply(const Gen& g, const std::string& format) {
  std::string s = "ply\nformat " + format + " 1.0\ncomment gen\nelement vertex " + std::to_string(g.points.size()) +
                  "\nproperty double x\nproperty double y\nproperty double z\nproperty uchar red\nelement face " +
                  std::to_string(g.faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  const bool big = format == "binary_big_endian";
  for (const auto& p : g.points) {
    if (format == "ascii") s += num(p.x()) + " " + num(p.y()) + " " + num(p.z()) + " 7\n";
    else {
      for (int a = 0; a < 3; ++a) put<double>(s, p[a], big);
      put<std::uint8_t>(s, 7, big);
    }
  }
  for (const auto& f : g.faces) {
    if (format == "ascii") {
      s += std::to_string(f.size());
      for (std::size_t v : f) s += " " + std::to_string(v);
      s += "\n";
    } else {
      put<std::uint8_t>(s, static_cast<std::uint8_t>(f.size()), big);
      for (std::size_t v : f) put<std::int32_t>(s, static_cast<std::int32_t>(v), big);
    }
  }
  return s;
}

}  // namespace mesh3_test
