// Line queries on the outer DK hierarchy: DHS Lemma 5.2 (first intersection of a directed line)
// and Lemma 5.3 (first contact of a translating line). O(log n) each, O(1) work per level.
//
// Both work in a plane Π: for Lemma 5.3 the plane the moving line sweeps (through the line,
// spanned by line_dir and move_dir), for Lemma 5.2 a plane through the line (normal
// dir × e_k, e_k the axis of dir's smallest component, so Π is exact). Let S_i = Π ∩ P_i, the
// section of outer level i (P_1 = P ⊂ … ⊂ P_k). Going one level finer only adds the planes of
// an independent set of faces g; the part of P_{i+1} beyond such a g is the "tent" over g, and
// tents are pairwise disjoint (the dual statement of disjoint caps: vertices of a polytope above
// a plane are connected, independent vertices are not). Facts used:
//   (a) a point of S_{i+1} lies in at most one tent, and if it lies on the closed primal segment
//       of a dual edge e of level i+1, that tent's face is one of O(1) candidates read off e
//       (the face whose hole created e — then the whole segment is in its tent — or one of the
//       two apexes of e one level finer: the segment only grows past an end whose third plane
//       was removed, and that extension lies beyond that plane);
//   (b) P_{i+1} ∩ plane(g) is exactly the face g of P_i (a face is cut out of its plane by its
//       neighbours' half-spaces, and the neighbours of a removed face are kept), so a point of
//       S_{i+1} on plane(g) is in P_i, and the chord Π ∩ face g has at most 8 edge candidates.
// Lemma 5.3: the first contact is the minimum of the key (w·x, l·x) over S_1, where l =
// line_dir and w = move_dir's component orthogonal to l (a strict total order on Π). The minimum
// e_{i+1} of S_{i+1} either survives (it is not beyond any new plane) or lies in one tent g, and
// then the minimum of S_i is the better end of the chord Π ∩ face g (a local minimum of a convex
// set is global, so it lies on the cutting plane, and (b)).
// Lemma 5.2: the line meets P_{i+1} in [a, b]; only a tent containing the entry (exit) point can
// move a (b), the new entry is where the line crosses that face, and a point of the chord of the
// entry face that is beyond g forces an end of the chord beyond g, whose dual edge carries g as a
// candidate (a). So each end keeps its face and the two ends of its chord in Π.
// Exactness: points are meets of three planes (ids; -1, -2 the query planes); every decision is
// the exact sign of a polynomial in the input doubles (outer_hierarchy.hpp). Nothing relies on
// general position: a line through vertices, along edges or in a face plane takes the same path.
// Touching: a line that only touches P is a hit with t_enter == t_exit (or the touched segment).
// An empty chord (or an entry face crossed the wrong way) proves the line / plane misses P_i,
// hence P. Departures from DHS (who cite DK for the proofs): both lemmas descend the OUTER
// hierarchy inside a plane through the line, so a query never has to track a separation; on an
// inner level P_i the descent uses P_i's own outer hierarchy (built on demand). Query times:
// docs/benchmarks.md.
#include "convex3/outer_hierarchy.hpp"

#include <cassert>
#include <cmath>
#include <sstream>
#include <string>
#include <type_traits>

namespace pendepth {

using convex3::DKLevel;
using convex3::OuterHierarchy;
using convex3::PlaneDef;
using convex3::PolytopeData;

namespace {

using Tri = std::array<int, 3>;  // a point: the meet of three planes (face ids; -1, -2 query planes)

struct End {
  Tri pt;
  int he;  ///< a dual half-edge of the current level whose closed primal segment contains pt
};

struct Ctx {
  const PolytopeData& d;
  const OuterHierarchy& O;
  PlaneDef q[2];
  mutable std::size_t visits = 0;
  exact::Fl qfl[2][4] = {};  // the query planes in filtered double (fast filters)

  void init() {
    for (int i = 0; i < 2; ++i) {
      auto p = convex3::eval_plane(q[i], O.center, exact::LiftFl{});
      for (int k = 0; k < 3; ++k) qfl[i][k] = p.n[k];
      qfl[i][3] = p.h;
    }
  }
  PlaneDef def(int id) const { return id >= 0 ? O.face_plane(d.v, id) : q[-id - 1]; }
  template <class L>
  auto plane(int id, L lift) const {
    return convex3::eval_plane(def(id), O.center, lift);
  }
  // Filtered-double plane values: cached for faces, computed once per query for query planes.
  convex3::PlaneVal<exact::Fl> flp(int id) const {
    if (id >= 0) return O.fl[id];
    const exact::Fl* v = qfl[-id - 1];
    return {{v[0], v[1], v[2]}, v[3]};
  }
  template <class L>
  auto meet(const Tri& t, L lift) const {
    return convex3::meet(plane(t[0], lift), plane(t[1], lift), plane(t[2], lift));
  }
  // Filtered-double meets, memoised: a query tests the same few points against many planes.
  struct Slot {
    Tri key{0, 0, 0};
    bool used = false;
    convex3::MeetVal<exact::Fl> val;
  };
  mutable std::array<Slot, 64> memo{};
  const convex3::MeetVal<exact::Fl>& flmeet(const Tri& t) const {
    const unsigned hsh = (unsigned(t[0]) * 73856093u) ^ (unsigned(t[1]) * 19349663u) ^ (unsigned(t[2]) * 83492791u);
    Slot& s = memo[(hsh ^ (hsh >> 11)) & 63u];
    if (!s.used || s.key != t) s.key = t, s.used = true, s.val = convex3::meet(flp(t[0]), flp(t[1]), flp(t[2]));
    return s.val;
  }
  int dsign(const Tri& t) const {
    int s = exact::certified_sign(flmeet(t).D);
    return s != 2 ? s : exact::exact_sign([&](auto L) { return meet(t, L).D; });
  }
  /// Sign of n_g·x − h_g for the point x = meet(t): > 0 strictly beyond plane g.
  int side(int g, const Tri& t) const {
    ++visits;
    const auto& m = flmeet(t);
    int a = exact::certified_sign(convex3::side_num(flp(g), m)), b = exact::certified_sign(m.D);
    if (a != 2 && b != 2) return a * b;
    int s = exact::exact_sign([&](auto L) { return convex3::side_num(plane(g, L), meet(t, L)); });
    return s == 0 ? 0 : s * dsign(t);
  }
  /// Sign of n_g·(p − c) − h_g for a double point p.
  int side_point(int g, const Vec3& p) const {
    return exact::exact_sign([&](auto L) {
      auto G = plane(g, L);
      return G.n[0] * (L(p[0]) - L(O.center[0])) + G.n[1] * (L(p[1]) - L(O.center[1])) +
             G.n[2] * (L(p[2]) - L(O.center[2])) - G.h;
    });
  }
  /// Sign of n_g·u for a vector u given as a generic lambda (u(LiftFl) is its filtered value).
  template <class U>
  int normal_dot(int g, U&& u) const {
    auto G = flp(g);
    auto v = u(exact::LiftFl{});
    int s = exact::certified_sign(G.n[0] * v[0] + G.n[1] * v[1] + G.n[2] * v[2]);
    if (s != 2) return s;
    return exact::exact_sign([&](auto L) {
      auto G = plane(g, L);
      auto v = u(L);
      return G.n[0] * v[0] + G.n[1] * v[1] + G.n[2] * v[2];
    });
  }
  /// Sign of u·(X − Y).
  template <class U>
  int along(U&& u, const Tri& X, const Tri& Y) const {
    {
      const auto mx = flmeet(X), my = flmeet(Y);
      auto v = u(exact::LiftFl{});
      auto e = (v[0] * mx.N[0] + v[1] * mx.N[1] + v[2] * mx.N[2]) * my.D -
               (v[0] * my.N[0] + v[1] * my.N[1] + v[2] * my.N[2]) * mx.D;
      int a = exact::certified_sign(e), b = exact::certified_sign(mx.D), c = exact::certified_sign(my.D);
      if (a != 2 && b != 2 && c != 2) return a * b * c;
    }
    int s = exact::exact_sign([&](auto L) {
      auto mx = meet(X, L);
      auto my = meet(Y, L);
      auto v = u(L);
      return (v[0] * mx.N[0] + v[1] * mx.N[1] + v[2] * mx.N[2]) * my.D -
             (v[0] * my.N[0] + v[1] * my.N[1] + v[2] * my.N[2]) * mx.D;
    });
    return s == 0 ? 0 : s * dsign(X) * dsign(Y);
  }
};

template <class L>
auto lift3(const Vec3& v, L lift) {
  using T = decltype(lift(0.0));
  return std::array<T, 3>{lift(v[0]), lift(v[1]), lift(v[2])};
}

// Direction of the line Π ∩ plane(f): n_Π × n_f (cached filtered planes in the double tier).
auto chord_dir(const Ctx& c, int f) {
  return [&c, f](auto L) {
    auto cross = [](const auto& a, const auto& b) {
      using T = std::remove_cv_t<std::remove_reference_t<decltype(a.n[0])>>;
      return std::array<T, 3>{a.n[1] * b.n[2] - a.n[2] * b.n[1], a.n[2] * b.n[0] - a.n[0] * b.n[2],
                              a.n[0] * b.n[1] - a.n[1] * b.n[0]};
    };
    if constexpr (std::is_same_v<std::decay_t<decltype(L)>, exact::LiftFl>)
      return cross(c.flp(-1), c.flp(f));
    else
      return cross(c.plane(-1, L), c.plane(f, L));
  };
}

// The chord Π ∩ face f at level L (h0: any dual half-edge out of f there): its two ends, each the
// meet of Π, f and a neighbour N with the half-edge (f -> N) (face f ∩ plane N is the primal
// segment of that dual edge). False if the chord is empty. O(degree of f).
bool chord(Ctx& c, const DKLevel& L, int f, int h0, End& lo, End& hi) {
  auto dir = chord_dir(c, f);
  lo.he = hi.he = -1;
  std::vector<int> parallel;  // constraints parallel to the chord (rare; empty in general position)
  int h = h0;
  do {
    ++c.visits;
    int N = L.target(h);
    int s = c.normal_dot(N, dir);
    Tri t{-1, f, N};
    if (s > 0) {  // moving along dir leaves N's half-space: an upper end
      if (hi.he < 0 || c.along(dir, t, hi.pt) < 0) hi = {t, h};
    } else if (s < 0) {
      if (lo.he < 0 || c.along(dir, t, lo.pt) > 0) lo = {t, h};
    } else {
      parallel.push_back(N);
    }
    h = L.ccw(h);
  } while (h != h0);
  if (lo.he < 0 || hi.he < 0) return false;
  if (c.along(dir, lo.pt, hi.pt) > 0) return false;
  for (int N : parallel)
    if (c.side(N, lo.pt) > 0) return false;
  return true;
}

int top_out_edge(const DKLevel& T, int f) {
  for (int h = 0; h < static_cast<int>(T.fv.size()); ++h)
    if (T.fv[h] == f) return h;
  return -1;
}

// Level j+1 -> j for a dual half-edge h of level j+1: the half-edge of level j that carries the
// same primal point (the same edge, or (origin -> creator) for a diagonal of a hole), and the
// faces removed at level j whose tents may contain a point of h's primal segment (fact (a)).
struct Mapped {
  int he;
  int cand[2];
  int nc = 0;
};
Mapped map_down(const OuterHierarchy& O, int j, int h) {
  const DKLevel& C = O.levels[j + 1].dual;
  const DKLevel& L = O.levels[j].dual;
  Mapped m;
  m.he = C.down[h];
  if (L.target(m.he) != C.target(h)) {
    m.cand[m.nc++] = L.target(m.he);  // a diagonal created by removing this face: all in its tent
  } else {
    for (int g : {L.target(L.ccw(m.he)), L.target(L.cw(m.he))})
      if (O.last_level[g] == j) m.cand[m.nc++] = g;  // an end extended past a removed apex
  }
  return m;
}

// A dual half-edge (g -> N) at level j whose primal segment contains the point p of face g
// (p on plane N; prefer N == prefer). g was removed at level j (degree <= 8).
int edge_through(Ctx& c, int g, const Tri& p, int prefer) {
  const DKLevel& L = c.O.levels[c.O.last_level[g]].dual;
  int h0 = c.O.last_he[g], h = h0, found = -1;
  do {
    int N = L.target(h);
    if (N == prefer) return h;
    if (found < 0 && c.side(N, p) == 0) found = h;
    h = L.ccw(h);
  } while (h != h0);
  return found;
}

// num / den rounded to nearest in almost all cases: both evaluated in certified double-double,
// then one Newton-style correction; exact rationals when the double-double bounds are too loose.
template <class N, class D>
double precise_ratio(N&& num, D&& den) {
  exact::DD a = num(exact::LiftDD{}), b = den(exact::LiftDD{});
  if (exact::dd_finite(a) && exact::dd_finite(b) && b.hi != 0 && a.e <= std::abs(a.hi) * 0x1p-64 &&
      b.e <= std::abs(b.hi) * 0x1p-64) {
    double q1 = a.hi / b.hi;
    exact::DD r = a - exact::DD{q1, 0, 0} * b;
    double q = q1 + (r.hi + r.lo) / b.hi;
    if (std::isfinite(q)) return q;
  }
  mpq_class x = num(exact::LiftQ{}).v / den(exact::LiftQ{}).v;
  double t = x.get_d();  // truncated; step to the nearest neighbour if closer
  for (double u : {std::nextafter(t, -INFINITY), std::nextafter(t, INFINITY)})
    if (std::isfinite(u) && abs(x - mpq_class(u)) < abs(x - mpq_class(t))) t = u;
  return t;
}

std::string vec_str(const Vec3& v) {
  std::ostringstream os;
  os << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
  return os.str();
}

void require(bool ok, const std::string& name, const std::string& what) {
  if (!ok) throw InvalidInput(name + ": " + what);
}

}  // namespace

std::size_t ConvexPolytope::face_count() const { return convex3::outer_hierarchy(*d_).face_ref.size(); }
int ConvexPolytope::face_of_triangle(std::size_t t) const {
  return convex3::outer_hierarchy(*d_).face_of_tri.at(t);
}
std::size_t ConvexPolytope::outer_hierarchy_levels() const { return convex3::outer_hierarchy(*d_).levels.size(); }

LineContact ConvexPolytope::first_contact(const Vec3& point, const Vec3& line_dir, const Vec3& move_dir,
                                          std::size_t level) const {
  const std::string who = d_->name + ": first_contact";
  require(point.allFinite(), who, "point " + vec_str(point) + " is not finite");
  require(line_dir.allFinite() && line_dir != Vec3::Zero(), who,
          "line_dir " + vec_str(line_dir) + " must be finite and non-zero");
  require(move_dir.allFinite() && move_dir != Vec3::Zero(), who,
          "move_dir " + vec_str(move_dir) + " must be finite and non-zero");
  const Vec3 &l = line_dir, &m = move_dir;
  auto cross_zero = [&](int i, int j) {
    return exact::exact_sign([&](auto L) { return L(l[i]) * L(m[j]) - L(l[j]) * L(m[i]); }) == 0;
  };
  require(!(cross_zero(1, 2) && cross_zero(2, 0) && cross_zero(0, 1)), who,
          "line_dir " + vec_str(l) + " is parallel to move_dir " + vec_str(m));

  require(level < d_->levels.size(), who, "no hierarchy level " + std::to_string(level));
  const OuterHierarchy& O = convex3::outer_hierarchy(*d_, level);
  Ctx c{*d_, O, {PlaneDef{1, point, l, m}, PlaneDef{1, point, l, m}}};
  c.init();
  auto w = [&](auto L) {  // m |l|² − l (l·m): move_dir's part orthogonal to l (scaled)
    auto L3 = lift3(l, L), M3 = lift3(m, L);
    auto ll = L3[0] * L3[0] + L3[1] * L3[1] + L3[2] * L3[2];
    auto lm = L3[0] * M3[0] + L3[1] * M3[1] + L3[2] * M3[2];
    return std::array<decltype(ll), 3>{M3[0] * ll - L3[0] * lm, M3[1] * ll - L3[1] * lm, M3[2] * ll - L3[2] * lm};
  };
  auto lv = [&](auto L) { return lift3(l, L); };
  auto better = [&](const Tri& X, const Tri& Y) {
    int s = c.along(w, X, Y);
    return s != 0 ? s < 0 : c.along(lv, X, Y) < 0;
  };

  LineContact r;
  // Top level: the key-minimal vertex of the section, over the dual edges whose primal segment
  // meets Π (its end vertices, the dual triangles, are not strictly on one side).
  const int top = static_cast<int>(O.top());
  const DKLevel& T = O.levels[top].dual;
  std::vector<int> tside(T.fv.size() / 3);
  for (std::size_t t = 0; t < tside.size(); ++t)
    tside[t] = c.side(-1, {T.fv[3 * t], T.fv[3 * t + 1], T.fv[3 * t + 2]});
  End best{{0, 0, 0}, -1};
  for (int h = 0; h < static_cast<int>(T.fv.size()); ++h) {
    int u = T.fv[h], v = T.target(h);
    int s1 = tside[h / 3], s2 = tside[T.twin[h] / 3];
    if (u > v || (s1 > 0 && s2 > 0) || (s1 < 0 && s2 < 0)) continue;
    Tri X{-1, u, v};
    ++c.visits;
    if (c.dsign(X) == 0) continue;  // the edge lies in Π: its ends are found on other edges
    if (best.he < 0 || better(X, best.pt)) best = {X, h};
  }
  if (best.he < 0) {
    r.nodes_visited = c.visits;
    return r;
  }
  for (int j = top - 1; j >= 0; --j) {
    Mapped mp = map_down(O, j, best.he);
    int cut = -1;
    for (int i = 0; i < mp.nc && cut < 0; ++i)
      if (c.side(mp.cand[i], best.pt) > 0) cut = mp.cand[i];
    if (cut < 0) {
      best.he = mp.he;
      continue;
    }
    End lo, hi;
    if (!chord(c, O.levels[j].dual, cut, O.last_he[cut], lo, hi)) {  // Π misses P_j, hence P
      r.nodes_visited = c.visits;
      return r;
    }
    best = better(lo.pt, hi.pt) ? lo : hi;
  }

  r.contact = true;
  r.nodes_visited = c.visits;
  const DKLevel& B = O.levels[0].dual;
  int v1 = O.base_vertex[best.he / 3], v2 = O.base_vertex[B.twin[best.he] / 3];
  auto is_point = [&](int v) {  // vertex v is the meet point: it lies on its three planes
    for (int id : best.pt) {
      int s = id >= 0 ? predicates::orient3d(d_->v[O.face_ref[id][0]], d_->v[O.face_ref[id][1]],
                                             d_->v[O.face_ref[id][2]], d_->v[v])
                      : c.side_point(id, d_->v[v]);
      if (s != 0) return false;
    }
    return true;
  };
  const Tri X = best.pt;
  if (v1 == v2 || is_point(v1)) {
    r.feature = LineContact::Feature::Vertex, r.vertex = v1;
  } else if (is_point(v2)) {
    r.feature = LineContact::Feature::Vertex, r.vertex = v2;
  } else {
    r.feature = LineContact::Feature::Edge, r.edge = {std::min(v1, v2), std::max(v1, v2)};
  }
  const Vec3& ctr = O.center;
  if (r.feature == LineContact::Feature::Vertex) {
    r.point = d_->v[r.vertex];
  } else {
    for (int i = 0; i < 3; ++i)
      r.point[i] = precise_ratio([&](auto L) { auto M = c.meet(X, L); return L(ctr[i]) * M.D + M.N[i]; },
                                         [&](auto L) { return c.meet(X, L).D; });
  }
  // shift = w·(x − point) / (w·m), x − c = N / D.
  r.shift = precise_ratio(
      [&](auto L) {
        auto M = c.meet(X, L);
        auto W = w(L);
        auto p = lift3(point, L), cc = lift3(ctr, L);
        return W[0] * M.N[0] + W[1] * M.N[1] + W[2] * M.N[2] -
               M.D * (W[0] * (p[0] - cc[0]) + W[1] * (p[1] - cc[1]) + W[2] * (p[2] - cc[2]));
      },
      [&](auto L) {
        auto M = c.meet(X, L);
        auto W = w(L);
        auto M3 = lift3(m, L);
        return M.D * (W[0] * M3[0] + W[1] * M3[1] + W[2] * M3[2]);
      });
  return r;
}

LineHit ConvexPolytope::first_hit(const Vec3& origin, const Vec3& dir, std::size_t level) const {
  const std::string who = d_->name + ": first_hit";
  require(origin.allFinite(), who, "origin " + vec_str(origin) + " is not finite");
  require(dir.allFinite() && dir != Vec3::Zero(), who, "dir " + vec_str(dir) + " must be finite and non-zero");
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(dir[i]) < std::abs(dir[k])) k = i;
  Vec3 ek = Vec3::Zero();
  ek[k] = 1;
  const Vec3 nu = dir.cross(ek);  // exact: its components are 0 and ±dir_i
  require(level < d_->levels.size(), who, "no hierarchy level " + std::to_string(level));
  const OuterHierarchy& O = convex3::outer_hierarchy(*d_, level);
  // Π (normal dir × e_k) and Π' (normal dir × ν) both contain the line; it is their meet.
  Ctx c{*d_, O, {PlaneDef{1, origin, dir, ek}, PlaneDef{1, origin, dir, nu}}};
  c.init();
  auto dv = [&](auto L) { return lift3(dir, L); };

  LineHit r;
  struct State {
    int F = -1;
    End e[2];
    Tri x() const { return {-1, -2, F}; }
  } st[2];  // st[0]: entry, st[1]: exit
  auto miss = [&] {
    LineHit m;
    m.nodes_visited = c.visits;
    return m;
  };

  const int top = static_cast<int>(O.top());
  const DKLevel& T = O.levels[top].dual;
  for (int f : T.verts) {
    ++c.visits;
    int s = c.normal_dot(f, dv);
    if (s == 0) {
      if (c.side_point(f, origin) > 0) return miss();
      continue;
    }
    State& S = st[s < 0 ? 0 : 1];
    Tri X{-1, -2, f};
    if (S.F < 0 || (s < 0 ? c.along(dv, X, S.x()) > 0 : c.along(dv, X, S.x()) < 0)) S.F = f;
  }
  if (st[0].F < 0 || st[1].F < 0 || c.along(dv, st[0].x(), st[1].x()) > 0) return miss();
  for (State& S : st)
    if (!chord(c, T, S.F, top_out_edge(T, S.F), S.e[0], S.e[1])) return miss();

  for (int j = top - 1; j >= 0; --j) {
    const DKLevel& L = O.levels[j].dual;
    Mapped mp[2][2];
    int cut[2] = {-1, -1};
    for (int s = 0; s < 2; ++s) {
      for (int i = 0; i < 2; ++i) mp[s][i] = map_down(O, j, st[s].e[i].he);
      const Tri x = st[s].x();
      for (int i = 0; i < 2 && cut[s] < 0; ++i)
        for (int q = 0; q < mp[s][i].nc && cut[s] < 0; ++q)
          if (c.side(mp[s][i].cand[q], x) > 0) cut[s] = mp[s][i].cand[q];
    }
    for (int s = 0; s < 2; ++s) {
      if (cut[s] < 0) continue;
      // The line must cross the cutting plane inwards at the entry (outwards at the exit).
      int nd = c.normal_dot(cut[s], dv);
      if (s == 0 ? nd >= 0 : nd <= 0) return miss();
      st[s].F = cut[s];
    }
    if ((cut[0] >= 0 || cut[1] >= 0) && c.along(dv, st[0].x(), st[1].x()) > 0) return miss();
    for (int s = 0; s < 2; ++s) {
      State& S = st[s];
      if (cut[s] >= 0) {
        if (!chord(c, L, S.F, O.last_he[S.F], S.e[0], S.e[1])) return miss();
        continue;
      }
      for (int i = 0; i < 2; ++i) {
        const Mapped& M = mp[s][i];
        int g = -1;
        for (int q = 0; q < M.nc && g < 0; ++q)
          if (c.side(M.cand[q], S.e[i].pt) > 0) g = M.cand[q];
        if (g < 0) {
          S.e[i].he = M.he;
        } else {  // the chord end moves to where the chord crosses plane g (in face g, fact (b))
          S.e[i].pt = {-1, S.F, g};
          S.e[i].he = edge_through(c, g, S.e[i].pt, S.F);
          assert(S.e[i].he >= 0 && "a chord end on face g lies on no edge of g");
        }
      }
    }
  }

  r.hit = true;
  r.nodes_visited = c.visits;
  const Vec3& ctr = O.center;
  for (int s = 0; s < 2; ++s) {
    const int F = st[s].F;
    // origin + t dir on plane F: t = (h − n·(origin − c)) / (n·dir).
    auto num = [&](auto L) {
      auto G = c.plane(F, L);
      return G.h - (G.n[0] * (L(origin[0]) - L(ctr[0])) + G.n[1] * (L(origin[1]) - L(ctr[1])) +
                    G.n[2] * (L(origin[2]) - L(ctr[2])));
    };
    auto den = [&](auto L) {
      auto G = c.plane(F, L);
      return G.n[0] * L(dir[0]) + G.n[1] * L(dir[1]) + G.n[2] * L(dir[2]);
    };
    double t = precise_ratio(num, den);
    Vec3 p;
    for (int i = 0; i < 3; ++i)
      p[i] = precise_ratio([&](auto L) { return L(origin[i]) * den(L) + L(dir[i]) * num(L); }, den);
    if (s == 0) r.t_enter = t, r.enter = p, r.face_enter = F;
    else r.t_exit = t, r.exit = p, r.face_exit = F;
  }
  return r;
}

}  // namespace pendepth
