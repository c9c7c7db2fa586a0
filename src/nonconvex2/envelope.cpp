// Right envelope of a simple polygon's outer ring seen from infinity along a direction, in linear
// time (DHS §6; contract in envelope.hpp).
//
// Algorithm: a visibility walk in the style of Lee / Joe–Simpson, with the viewpoint at u = +∞ so
// that the angle around the viewpoint becomes the level w and every shadow ray is a horizontal
// line through a vertex. Start at a rightmost vertex v0 (visible: nothing lies to its right). By
// the Jordan curve theorem the visible points appear along the counter-clockwise ring from v0 in
// increasing level above w(v0) (the rays towards +∞ from visible points do not cross, so their
// order on the ring is their order at infinity); the half below w(v0) is the same walk run
// clockwise in the frame mirrored across d (levels and orientations negated). A walk keeps the
// visible chain of the walked prefix on a stack of pieces (edge, level range), contiguous from
// w(v0) up, and is in one of three states:
//   OnTop  at the chain's top point (the rightmost walked point of the top level; nothing walked
//          lies above). Up: push. Horizontal to the right: stay. Horizontal to the left, or down
//          behind the top piece's edge: Scan, window = the top level left of the top point.
//          Down in front of it: Desc.
//   Desc   descending in front of the chain. A descending edge has P's interior on its +u side,
//          so the chain levels it covers are hidden for good (the final envelope there lies on
//          edges still to come): pop them, truncate the piece straddling the new level. Turning up
//          to the right of the descent (a left turn): visible, push, OnTop. Turning up or left
//          behind it (a right turn): Scan, window = the descent's bottom level between the chain
//          and the bottom vertex, downwards (the pocket between the descent and the popped chain
//          opens only there). Passing behind the next piece at its top level (a "door" between
//          that piece's top and the popped part): Scan, window = that level between the descent
//          and the piece, upwards. Covering every level above w(v0): Scan, window = w(v0) right
//          of the descent, upwards.
//   Scan   hidden; resumes when the walk crosses the window's level in the window's direction
//          strictly between its two bounds (an up window pushes the crossing edge from the
//          window's level, OnTop; a down window resumes Desc). Crossings outside the bounds lead
//          into closed pockets of already-walked boundary and are ignored: simplicity makes the
//          walk leave such a pocket the way it came in.
// Each step pushes at most one piece and pops only pieces it hides, so the walk costs O(n) exact
// predicates: the level order (sign of d × (a − b)), the orientation, the order along d at equal
// levels, and the order along d of an edge and a bound at a vertex's level (degree 6). A crossing
// exactly at a bound's point happens only when the walk leaves the bound's own end vertex, and is
// resolved by the turn there. The window rules follow Joe–Simpson's case analysis specialised to
// a viewpoint at infinity; the argument is sketched here, not written out as a proof. The tests
// compare every envelope with an independent divide-and-conquer construction (random stars,
// spirals, mazes, notched polygons, combs, holes, nesting pieces, degenerate directions; every
// state and window kind above is exercised).
// Departure from the textbook algorithms: the viewpoint is at infinity, so every breakpoint is a
// vertex level and no intersection point is ever constructed; windows are (level vertex, bounds).
#include "nonconvex2/envelope.hpp"

#include <algorithm>

#include "geometry/exact.hpp"

namespace pendepth::nonconvex2 {

namespace {

using exact::exact_sign;

// A stack piece: levels (lo, hi), on the edge from ea up to eb (frame levels), global edge id.
struct Piece {
  std::uint32_t lo, hi, ea, eb, edge;
};

class Walk {
 public:
  // sgn = +1: the counter-clockwise walk from v0 (levels above w(v0)); −1: the mirrored frame.
  Walk(const Polygon& S, const Vec2& dir, int sgn, std::uint32_t v0)
      : V_(S.vertices()), n_(static_cast<std::uint32_t>(S.ring(0).size())), d_(dir), sgn_(sgn), v0_(v0) {}

  std::vector<Piece> run() {
    std::uint32_t prev = vertex(n_ - 1);
    for (std::uint32_t k = 0; k < n_; ++k) {
      const std::uint32_t a = vertex(k), q = vertex(k + 1), g = sgn_ > 0 ? a : q;
      step(prev, a, q, g);
      prev = a;
    }
    return std::move(S_);
  }

 private:
  enum class State { OnTop, Desc, Scan };

  std::uint32_t vertex(std::uint32_t k) const {
    k %= n_;
    return sgn_ > 0 ? (v0_ + k) % n_ : (v0_ + n_ - k) % n_;
  }
  // Sign of level(a) − level(b) in the walk's frame.
  int lv(std::uint32_t a, std::uint32_t b) const {
    const Vec2 &p = V_[a], &r = V_[b], &d = d_;
    return sgn_ * exact_sign([&](auto L) { return L(d.x()) * (L(p.y()) - L(r.y())) - L(d.y()) * (L(p.x()) - L(r.x())); });
  }
  // Orientation of (a, b, c) in the walk's frame (> 0: left turn).
  int orient(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    const Vec2 &p = V_[a], &r = V_[b], &s = V_[c];
    return sgn_ * exact_sign([&](auto L) {
      return (L(r.x()) - L(p.x())) * (L(s.y()) - L(p.y())) - (L(r.y()) - L(p.y())) * (L(s.x()) - L(p.x()));
    });
  }
  // Sign of u(a) − u(b) (u = d·x; the same in both frames).
  int ucmp(std::uint32_t a, std::uint32_t b) const {
    const Vec2 &p = V_[a], &r = V_[b], &d = d_;
    return exact_sign([&](auto L) { return L(d.x()) * (L(p.x()) - L(r.x())) + L(d.y()) * (L(p.y()) - L(r.y())); });
  }
  // Sign of u_A − u_B at the level of vertex z, for the non-horizontal edges A = a0a1, B = b0b1:
  // u_A·D_A = u(a0)·D_A + (w(z) − w(a0))·(u(a1) − u(a0)) with D_A = w(a1) − w(a0).
  int u_at(std::uint32_t a0, std::uint32_t a1, std::uint32_t b0, std::uint32_t b1, std::uint32_t z) const {
    const Vec2 &p0 = V_[a0], &p1 = V_[a1], &r0 = V_[b0], &r1 = V_[b1], &y = V_[z], &d = d_;
    const int s = exact_sign([&](auto L) {
      auto cr = [&](const Vec2& p) { return L(d.x()) * L(p.y()) - L(d.y()) * L(p.x()); };
      auto dt = [&](const Vec2& p) { return L(d.x()) * L(p.x()) + L(d.y()) * L(p.y()); };
      auto DA = cr(p1) - cr(p0), DB = cr(r1) - cr(r0);
      auto uA = dt(p0) * DA + (cr(y) - cr(p0)) * (dt(p1) - dt(p0));
      auto uB = dt(r0) * DB + (cr(y) - cr(r0)) * (dt(r1) - dt(r0));
      return uA * DB - uB * DA;
    });
    // Real-level signs of D_A and D_B (frame independent, like u).
    return s * sgn_ * lv(a1, a0) * sgn_ * lv(b1, b0);
  }

  void push(std::uint32_t lo, std::uint32_t ea, std::uint32_t eb, std::uint32_t g) {
    S_.push_back({lo, eb, ea, eb, g});
    state_ = State::OnTop;
  }

  // A bound of a window: none (infinite), a vertex, or an edge (its point at the window's level).
  struct Bound {
    enum Kind { None, Vertex, Edge } kind = None;
    std::uint32_t a = 0, b = 0;
  };
  static Bound vertex_bound(std::uint32_t v) { return {Bound::Vertex, v, v}; }
  static Bound edge_bound(std::uint32_t a, std::uint32_t b) { return {Bound::Edge, a, b}; }

  void scan(int dir, std::uint32_t z, Bound lb, Bound rb) {
    state_ = State::Scan;
    win_dir_ = dir, win_z_ = z, win_lb_ = lb, win_rb_ = rb;
  }

  // Sign of u(crossing of edge a→q with the window level) − u(bound); a zero (the crossing point is
  // the bound's own point: the walk leaves the bound vertex) is resolved by the turn at a.
  int side_of(std::uint32_t a, std::uint32_t q, const Bound& bd) const {
    int s;
    if (bd.kind == Bound::Vertex) {
      s = u_at_point(a, q, bd.a);
    } else {
      s = u_at(a, q, bd.a, bd.b, win_z_);
    }
    if (s != 0) return s;
    // The crossing point is a itself, the end of the bound edge (a descent) or the bound vertex:
    // the edge a→q leaves on the +u side of the bound edge iff it turns left.
    if (bd.kind == Bound::Edge && bd.b == a) return orient(bd.a, a, q) > 0 ? 1 : -1;
    return 0;
  }
  bool in_window(std::uint32_t a, std::uint32_t q) const {
    if (win_dir_ > 0 ? !(lv(a, win_z_) <= 0 && lv(q, win_z_) > 0) : !(lv(a, win_z_) >= 0 && lv(q, win_z_) < 0)) return false;
    if (win_lb_.kind != Bound::None && side_of(a, q, win_lb_) <= 0) return false;
    if (win_rb_.kind != Bound::None && side_of(a, q, win_rb_) >= 0) return false;
    return true;
  }

  // Sign of u(edge a→q at the level of v) − u(v), for a non-horizontal edge.
  int u_at_point(std::uint32_t a, std::uint32_t q, std::uint32_t v) const {
    return lv(q, a) * orient(a, q, v);
  }

  // The descending edge a→q is in front of the chain at the top piece's upper level: pop what it
  // hides; stop at the piece straddling level(q), or at a piece the descent passes behind.
  void descend(std::uint32_t a, std::uint32_t q) {
    for (;;) {
      if (S_.empty()) {  // every level above w(v0) is covered: re-entry above w(v0), right of a→q
        scan(+1, v0_, edge_bound(a, q), Bound{});
        return;
      }
      Piece& T = S_.back();
      const int c = lv(T.lo, q);
      if (c < 0) {
        T.hi = q;
        state_ = State::Desc;
        return;
      }
      const std::uint32_t z = T.lo;
      S_.pop_back();
      if (S_.empty()) continue;
      const Piece& T2 = S_.back();
      const int s = c == 0 ? -u_at_point(T2.ea, T2.eb, q) : u_at(a, q, T2.ea, T2.eb, z);
      if (s <= 0) {  // the descent passes behind T2 at level z: hidden until it comes back up
        scan(+1, z, edge_bound(a, q), edge_bound(T2.ea, T2.eb));  // through the door (a→q, T2)
        return;
      }
      if (c == 0) {
        state_ = State::Desc;  // q is on the envelope at T2's upper level
        return;
      }
    }
  }

  void step(std::uint32_t prev, std::uint32_t a, std::uint32_t q, std::uint32_t g) {
    switch (state_) {
      case State::OnTop: {
        const int s = lv(q, a);
        if (s > 0) {
          push(a, a, q, g);
        } else if (s == 0) {
          if (ucmp(q, a) < 0) scan(+1, a, Bound{}, vertex_bound(a));
        } else if (S_.empty()) {
          scan(+1, a, Bound{}, Bound{});  // at v0, leaving the upper half
        } else {
          const Piece& T = S_.back();
          if (T.eb != a || orient(T.ea, T.eb, q) < 0) descend(a, q);
          else scan(+1, a, Bound{}, vertex_bound(a));
        }
        break;
      }
      case State::Desc: {
        const int s = lv(q, a);
        if (s < 0) descend(a, q);
        else if (s == 0) {
          if (ucmp(q, a) < 0) scan(-1, a, edge_bound(S_.back().ea, S_.back().eb), vertex_bound(a));
        } else if (orient(prev, a, q) > 0) {
          push(a, a, q, g);
        } else {
          scan(-1, a, edge_bound(S_.back().ea, S_.back().eb), vertex_bound(a));
        }
        break;
      }
      case State::Scan:
        if (in_window(a, q)) {
          if (win_dir_ > 0) push(win_z_, a, q, g);
          else descend(a, q);
        }
        break;
    }
  }

  std::span<const Vec2> V_;
  std::uint32_t n_;
  Vec2 d_;
  int sgn_;
  std::uint32_t v0_;
  std::vector<Piece> S_;
  State state_ = State::OnTop;
  int win_dir_ = 0;
  std::uint32_t win_z_ = 0;
  Bound win_lb_, win_rb_;
};

}  // namespace

std::vector<EnvelopePiece> right_envelope(const Polygon& shape, const Vec2& dir) {
  const auto V = shape.vertices();
  const std::uint32_t n = static_cast<std::uint32_t>(shape.ring(0).size());
  std::uint32_t v0 = 0;
  for (std::uint32_t i = 1; i < n; ++i)
    if (exact_sign([&](auto L) {
          return L(dir.x()) * (L(V[i].x()) - L(V[v0].x())) + L(dir.y()) * (L(V[i].y()) - L(V[v0].y()));
        }) > 0)
      v0 = i;
  Walk up(shape, dir, +1, v0), down(shape, dir, -1, v0);
  const std::vector<Piece> hi = up.run(), lo = down.run();
  std::vector<EnvelopePiece> out;
  out.reserve(hi.size() + lo.size());
  for (auto it = lo.rbegin(); it != lo.rend(); ++it) out.push_back({it->hi, it->lo, it->edge});
  for (const Piece& p : hi) {
    if (!out.empty() && out.back().edge == p.edge) out.back().hi = p.hi;
    else out.push_back({p.lo, p.hi, p.edge});
  }
  return out;
}

}  // namespace pendepth::nonconvex2
