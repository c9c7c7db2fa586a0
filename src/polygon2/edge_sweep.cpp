// Polygon validation, step 2: the Shamos–Hoey sweep over the rings' edges (contract in
// edge_sweep.hpp). M. I. Shamos, D. Hoey, "Geometric intersection problems", FOCS 1976; the
// degenerate cases as in de Berg et al., Computational Geometry, §2.1.
//
// Which contacts are allowed: only the shared vertex of two ring-adjacent edges that do not fold
// back. A violating pair may meet only at an endpoint of both when a vertex of one ring equals a
// vertex of another (within a ring, step 1 already refused repeated vertices): (a) a pre-pass
// finds those by sorting the vertices, O(N log N). Every other violating pair (fold-backs
// included: they overlap along a segment) meets at a point interior to one of its edges, and
// (b) the sweep finds one: events are the edges' endpoints in lexicographic (x, y) order (the
// sweep line is x = const tilted infinitesimally, so a vertical edge runs from its lower to its
// upper end); at a point, edges ending there leave the status before edges starting there enter.
// The status is ordered at the current event by orient2d: a new edge whose left end lies on
// the line of an active edge touches that edge's interior (or, from a shared left end, overlaps
// it) — a violation, reported at once; otherwise it lies strictly above or below. Each insertion
// checks the new edge against its two neighbours, each deletion the neighbours that become
// adjacent. Proof sketch: let q be the lexicographically first point where a violating pair
// meets. If q is the left end of one edge of the pair, the other contains q in its interior (or
// starts at q along the same ray: a fold-back) and is active when the first edge starting at q is inserted; that insertion compares the new edge with
// some active edge through q (the status is sorted; edges through q would otherwise lie between
// the insertion point's two compared neighbours) — a contact, q interior to that edge. Else, after the last event before q, the edges squeezed
// between the two edges of the pair all pass through q; the edge next to one whose interior
// contains q then meets it there, a violation, and the two were checked when they became adjacent.
// No contact before q changes the order (allowed contacts are shared vertices: both ends are
// events), so the status stays sorted without swaps.
//
// Every reported pair is confirmed by edge_pair_violation (the pairwise rule the former
// O(N log N + K) box sweep applied), so a reported violation is always a real one; which pair is
// named when there are several may differ from that former sweep.
//
// Complexity: O(N log N) time, O(N) space (a std::set over the active edges).
//
// check_edges, what Polygon runs, first tries the former box sweep with a budget of 32·N pairs
// of overlapping x-extents (it is 4–7× faster on combs and spirals, where K = O(N)), and runs
// the Shamos–Hoey sweep only when that budget runs out (stars with long spikes: K = Θ(N²)).
// Both apply the same pairwise rule, so the verdict does not depend on which one decides.
#include "polygon2/edge_sweep.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

namespace pendepth::polygon2 {

namespace {

using predicates::orient2d;

// r on the closed segment pq, given orient(p, q, r) == 0.
bool on_collinear_segment(const Vec2& p, const Vec2& q, const Vec2& r) {
  return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
         std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
}

// Do the closed segments a0a1 and b0b1 share a point?
bool segments_intersect(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1) {
  int o1 = orient2d(a0, a1, b0), o2 = orient2d(a0, a1, b1);
  int o3 = orient2d(b0, b1, a0), o4 = orient2d(b0, b1, a1);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && on_collinear_segment(a0, a1, b0)) || (o2 == 0 && on_collinear_segment(a0, a1, b1)) ||
         (o3 == 0 && on_collinear_segment(b0, b1, a0)) || (o4 == 0 && on_collinear_segment(b0, b1, a1));
}

bool lex_less(const Vec2& p, const Vec2& q) { return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y()); }

struct SweepEdge {
  Vec2 l, r;            // lexicographically smaller / larger end
  std::size_t ring, i;  // ring index, input edge index
};

struct Contact {  // thrown by the status order: edges e and f touch at the current event
  std::size_t e, f;
};

// Strict order of the status at the current event. Called only between the edge being inserted
// and active edges, so the later-starting edge's left end decides.
struct Below {
  const std::vector<SweepEdge>* edges;
  bool operator()(std::size_t e, std::size_t f) const {
    if (e == f) return false;
    const SweepEdge &E = (*edges)[e], &F = (*edges)[f];
    if (E.l == F.l) {  // same left end: by direction
      const int o = orient2d(E.l, F.r, E.r);
      if (o == 0) throw Contact{e, f};
      return o < 0;
    }
    if (lex_less(F.l, E.l)) {
      const int o = orient2d(F.l, F.r, E.l);
      if (o == 0) throw Contact{e, f};
      return o < 0;
    }
    const int o = orient2d(E.l, E.r, F.l);
    if (o == 0) throw Contact{e, f};
    return o > 0;
  }
};

}  // namespace

std::string validation_ring_name(std::size_t k) {
  return k == 0 ? "ring 0 (outer)" : "ring " + std::to_string(k) + " (hole " + std::to_string(k) + ")";
}

std::optional<std::string> edge_pair_violation(const std::vector<std::vector<Vec2>>& rings, std::size_t a,
                                               std::size_t i, std::size_t b, std::size_t j) {
  auto edge = [&](std::size_t k, std::size_t e) {
    return std::pair<const Vec2&, const Vec2&>(rings[k][e], rings[k][(e + 1) % rings[k].size()]);
  };
  if (a != b) {
    if (a > b) {
      std::swap(a, b);
      std::swap(i, j);
    }
    auto [x0, x1] = edge(a, i);
    auto [y0, y1] = edge(b, j);
    if (!segments_intersect(x0, x1, y0, y1)) return std::nullopt;
    return validation_ring_name(a) + " and " + validation_ring_name(b) + " touch or cross (edge " +
           std::to_string(i) + " of ring " + std::to_string(a) + ", edge " + std::to_string(j) + " of ring " +
           std::to_string(b) + ")";
  }
  if (i > j) std::swap(i, j);  // i < j
  const std::size_t n = rings[a].size();
  auto [x0, x1] = edge(a, i);
  auto [y0, y1] = edge(a, j);
  bool bad;
  if (j == i + 1) {  // share x1 == y0
    bad = orient2d(x0, x1, y1) == 0 && predicates::dot_edges(x0, x1, y0, y1) < 0;
  } else if (i == 0 && j == n - 1) {  // share y1 == x0
    bad = orient2d(y0, y1, x1) == 0 && predicates::dot_edges(y0, y1, x0, x1) < 0;
  } else {
    bad = segments_intersect(x0, x1, y0, y1);
  }
  if (!bad) return std::nullopt;
  return validation_ring_name(a) + ": self-intersecting (edges " + std::to_string(i) + " and " +
         std::to_string(j) + " intersect)";
}

void check_edges_sweep(const std::vector<std::vector<Vec2>>& rings, const std::string& name) {
  auto check = [&](std::size_t a, std::size_t i, std::size_t b, std::size_t j) {
    if (auto msg = edge_pair_violation(rings, a, i, b, j)) throw InvalidInput(name + ": " + *msg);
  };

  // (a) A vertex shared by two rings (vertex i starts edge i).
  struct Vertex {
    Vec2 p;
    std::size_t ring, i;
  };
  std::vector<Vertex> vs;
  for (std::size_t k = 0; k < rings.size(); ++k)
    for (std::size_t i = 0; i < rings[k].size(); ++i) vs.push_back({rings[k][i], k, i});
  std::sort(vs.begin(), vs.end(), [](const Vertex& u, const Vertex& w) {
    return lex_less(u.p, w.p) || (u.p == w.p && (u.ring < w.ring || (u.ring == w.ring && u.i < w.i)));
  });
  for (std::size_t t = 1; t < vs.size(); ++t)
    if (vs[t].p == vs[t - 1].p && vs[t].ring != vs[t - 1].ring) check(vs[t - 1].ring, vs[t - 1].i, vs[t].ring, vs[t].i);

  // (b) The sweep.
  std::vector<SweepEdge> edges;
  for (std::size_t k = 0; k < rings.size(); ++k)
    for (std::size_t i = 0, n = rings[k].size(); i < n; ++i) {
      const Vec2 &a = rings[k][i], &b = rings[k][(i + 1) % n];
      edges.push_back(lex_less(a, b) ? SweepEdge{a, b, k, i} : SweepEdge{b, a, k, i});
    }
  struct Event {
    std::size_t edge;
    bool start;
  };
  std::vector<Event> events;
  events.reserve(2 * edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    events.push_back({e, true});
    events.push_back({e, false});
  }
  auto point = [&](const Event& v) -> const Vec2& { return v.start ? edges[v.edge].l : edges[v.edge].r; };
  std::sort(events.begin(), events.end(), [&](const Event& u, const Event& w) {
    const Vec2 &p = point(u), &q = point(w);
    if (lex_less(p, q)) return true;
    if (lex_less(q, p)) return false;
    return u.start < w.start;  // at one point: ends before starts
  });

  auto check_edges = [&](std::size_t e, std::size_t f) {
    check(edges[e].ring, edges[e].i, edges[f].ring, edges[f].i);
  };
  using Status = std::set<std::size_t, Below>;
  Status status(Below{&edges});
  std::vector<Status::iterator> where(edges.size());
  for (const Event& v : events) {
    const std::size_t e = v.edge;
    if (v.start) {
      Status::iterator it;
      try {
        it = status.insert(e).first;
      } catch (const Contact& c) {
        check_edges(c.e, c.f);
        throw std::logic_error("polygon edge sweep: a contact the pairwise rule allows (edges " +
                               std::to_string(c.e) + ", " + std::to_string(c.f) + ")");
      }
      where[e] = it;
      if (it != status.begin()) check_edges(*std::prev(it), e);
      if (std::next(it) != status.end()) check_edges(e, *std::next(it));
    } else {
      auto it = status.erase(where[e]);
      if (it != status.begin() && it != status.end()) check_edges(*std::prev(it), *it);
    }
  }
}

bool check_edges_boxes(const std::vector<std::vector<Vec2>>& rings, const std::string& name, std::size_t budget) {
  struct Box {
    std::size_t ring, i;
    double xlo, xhi, ylo, yhi;
  };
  std::vector<Box> boxes;
  for (std::size_t k = 0; k < rings.size(); ++k)
    for (std::size_t i = 0, n = rings[k].size(); i < n; ++i) {
      const Vec2 &a = rings[k][i], &b = rings[k][(i + 1) % n];
      boxes.push_back({k, i, std::min(a.x(), b.x()), std::max(a.x(), b.x()), std::min(a.y(), b.y()),
                       std::max(a.y(), b.y())});
    }
  std::sort(boxes.begin(), boxes.end(), [](const Box& e, const Box& f) { return e.xlo < f.xlo; });
  std::size_t examined = 0;
  for (std::size_t u = 0; u < boxes.size(); ++u) {
    const Box& e = boxes[u];
    for (std::size_t w = u + 1; w < boxes.size() && boxes[w].xlo <= e.xhi; ++w) {
      if (++examined > budget) return false;
      const Box& f = boxes[w];
      if (f.ylo > e.yhi || e.ylo > f.yhi) continue;
      if (auto msg = edge_pair_violation(rings, e.ring, e.i, f.ring, f.i)) throw InvalidInput(name + ": " + *msg);
    }
  }
  return true;
}

void check_edges(const std::vector<std::vector<Vec2>>& rings, const std::string& name, std::size_t budget_per_edge) {
  std::size_t n = 0;
  for (const auto& r : rings) n += r.size();
  if (!check_edges_boxes(rings, name, budget_per_edge * n)) check_edges_sweep(rings, name);
}

}  // namespace pendepth::polygon2
