// Steiner pieces for the fans of a long edge: see strip_pieces.hpp (construction, checks, proof).
#include "nonconvex2/strip_pieces.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/exact.hpp"

namespace pendepth::nonconvex2 {

int& nfp_strip_mode() {
  thread_local int mode = kStripOn;
  return mode;
}
StripStats& nfp_strip_stats() {
  thread_local StripStats stats;
  return stats;
}

namespace {

constexpr std::uint32_t kFanDegree = 32;  // parts at A plus parts at B that make AB worth re-covering
constexpr std::uint32_t kNone = ~std::uint32_t(0);

std::uint64_t key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; }

// Closed segments [p, q] and [r, s] may meet (conservative: collinear ones count as meeting).
bool may_meet(const Vec2& p, const Vec2& q, const Vec2& r, const Vec2& s) {
  const int o1 = predicates::orient2d(p, q, r), o2 = predicates::orient2d(p, q, s);
  if (o1 * o2 > 0) return false;
  const int o3 = predicates::orient2d(r, s, p), o4 = predicates::orient2d(r, s, q);
  return o3 * o4 <= 0;
}

bool finite(const Vec2& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

struct Piece {
  std::vector<Vec2> v;
  std::vector<std::uint32_t> id;
};

// One region: the chain v_0 = B … v_K = A (coordinates w, ids cid). Appends T0 and the Q_j to
// `pieces` when every check passes; false otherwise (nothing appended).
bool cover(const std::vector<Vec2>& w, const std::vector<std::uint32_t>& cid, bool planted, std::vector<Piece>& pieces) {
  const std::size_t K = w.size() - 1;
  if (K < 2) return false;
  const Vec2 &B = w[0], &A = w[K];
  const Vec2 ab = B - A;
  const double L = ab.norm();
  if (!(L > 0) || !std::isfinite(L)) return false;
  const Vec2 u = ab / L, n(-u.y(), u.x());
  double hmin = INFINITY;
  for (std::size_t j = 1; j < K; ++j) hmin = std::min(hmin, n.dot(w[j] - A));
  const double H = std::min(0.5 * hmin, 0.25 * L);
  if (!(H > 0) || !std::isfinite(H)) return false;
  const Vec2 cA = A + H * (u + n), cB = B + H * (n - u);
  if (!finite(cA) || !finite(cB)) return false;
  using predicates::orient2d;
  // T0 strictly convex CCW; c_A, c_B inside R's angles at A and B.
  if (orient2d(A, B, cB) <= 0 || orient2d(B, cB, cA) <= 0 || orient2d(cB, cA, A) <= 0 || orient2d(cA, A, B) <= 0) return false;
  if (orient2d(B, w[1], cB) <= 0 || orient2d(A, cA, w[K - 1]) <= 0) return false;
  // No chain edge meets T0's sides [A, c_A], [c_A, c_B], [c_B, B] (the edges at A and B meet the
  // side through their end there only at that end: the angle checks above).
  for (std::size_t j = 0; j < K; ++j) {
    const Vec2 &p = w[j], &q = w[j + 1];
    if (j != K - 1 && may_meet(p, q, A, cA)) return false;
    if (may_meet(p, q, cA, cB)) return false;
    if (j != 0 && may_meet(p, q, cB, B)) return false;
  }
  // s_j on the midline, abscissa t decreasing in j, on the inner side of the edges at v_j.
  std::vector<Vec2> s(K + 1);
  s[0] = B, s[K] = A;
  const double mid = 0.5 * H, lo0 = 0.55 * H, hi0 = L - 0.55 * H, gap = 1e-3 * H;
  double t_prev = L;
  for (std::size_t j = 1; j < K; ++j) {
    double lo = lo0, hi = hi0;
    for (const std::size_t e : {j - 1, j}) {
      // cross(d, p − x0) > 0 for p = A + t·u + mid·n: α + β·t > 0.
      const Vec2 d = w[e + 1] - w[e], x0 = w[e];
      auto cross = [](const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); };
      const double alpha = cross(d, A - x0) + mid * cross(d, n), beta = cross(d, u);
      if (beta > 0) lo = std::max(lo, -alpha / beta);
      else if (beta < 0) hi = std::min(hi, -alpha / beta);
      else if (!(alpha > 0)) return false;
    }
    if (!(hi > lo)) return false;
    const double delta = std::min(0.1 * (hi - lo), 0.05 * H);
    double t = std::min(u.dot(w[j] - A), t_prev - gap);
    t = std::min(t, hi - delta);
    t = std::max(t, lo + delta);
    if (!(t < t_prev) || !std::isfinite(t)) return false;
    s[j] = A + t * u + mid * n;
    if (!finite(s[j])) return false;
    t_prev = t;
  }
  for (std::size_t j = 1; j < K; ++j)
    if (orient2d(A, B, s[j]) <= 0 || orient2d(B, cB, s[j]) <= 0 || orient2d(cB, cA, s[j]) <= 0 || orient2d(cA, A, s[j]) <= 0) return false;
  std::vector<Piece> out;
  out.push_back({{A, B, cB, cA}, {cid[K], cid[0], kSteiner, kSteiner}});
  for (std::size_t j = 0; j < K; ++j) {
    Piece q;
    q.v = {w[j], w[j + 1]}, q.id = {cid[j], cid[j + 1]};
    if (j + 1 < K) q.v.push_back(s[j + 1]), q.id.push_back(kSteiner);
    if (j > 0) q.v.push_back(s[j]), q.id.push_back(kSteiner);
    const std::size_t m = q.v.size();
    for (std::size_t i = 0; i < m; ++i)
      if (orient2d(q.v[i], q.v[(i + 1) % m], q.v[(i + 2) % m]) <= 0) return false;
    if (planted && (j == K / 2 || j == K / 2 + 1)) continue;  // kStripPlanted: a gap in the cover
    out.push_back(std::move(q));
  }
  for (Piece& p : out) pieces.push_back(std::move(p));
  return true;
}

}  // namespace

bool strip_fans(const ConvexParts& X, ConvexParts& out) {
  const int mode = nfp_strip_mode();
  if (mode == kStripOff || X.size() < kFanDegree) return false;
  const auto P = static_cast<std::uint32_t>(X.size());
  std::uint32_t nv = 0;
  for (const std::uint32_t i : X.id) {
    if (i == kSteiner) return false;
    nv = std::max(nv, i + 1);
  }
  // Parts per vertex (CSR) and vertex coordinates.
  std::vector<std::uint32_t> deg(nv + 1, 0), at(X.id.size());
  std::vector<Vec2> pos(nv);
  for (std::size_t i = 0; i < X.id.size(); ++i) ++deg[X.id[i] + 1], pos[X.id[i]] = X.v[i];
  for (std::uint32_t v = 0; v < nv; ++v) deg[v + 1] += deg[v];
  {
    std::vector<std::uint32_t> fill(deg.begin(), deg.end() - 1);
    for (std::uint32_t k = 0; k < P; ++k)
      for (std::uint32_t i = X.start[k]; i < X.start[k + 1]; ++i) at[fill[X.id[i]]++] = k;
  }
  auto parts_at = [&](std::uint32_t v) { return std::pair(at.begin() + deg[v], at.begin() + deg[v + 1]); };
  auto degree = [&](std::uint32_t v) { return deg[v + 1] - deg[v]; };
  // Directed ring edges; boundary edges have no reverse. Per vertex its boundary out- and in-part.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edges;
  edges.reserve(X.id.size());
  for (std::uint32_t k = 0; k < P; ++k) {
    const std::uint32_t s = X.start[k], m = X.start[k + 1] - s;
    for (std::uint32_t i = 0; i < m; ++i) edges.push_back({key(X.id[s + i], X.id[s + (i + 1) % m]), k});
  }
  std::sort(edges.begin(), edges.end());
  auto has = [&](std::uint64_t k) {
    const auto it = std::lower_bound(edges.begin(), edges.end(), std::pair(k, std::uint32_t(0)));
    return it != edges.end() && it->first == k;
  };
  std::vector<std::uint32_t> out_part(nv, kNone), in_part(nv, kNone);
  struct Cand {
    std::uint32_t a, b, part, d;
  };
  std::vector<Cand> cands;
  for (const auto& [k, part] : edges) {
    const auto a = std::uint32_t(k >> 32), b = std::uint32_t(k);
    if (has(key(b, a))) continue;
    out_part[a] = part, in_part[b] = part;
  }
  for (const auto& [k, part] : edges) {
    const auto a = std::uint32_t(k >> 32), b = std::uint32_t(k);
    if (out_part[a] != part || in_part[b] != part || has(key(b, a))) continue;
    const std::uint32_t d = degree(a) + degree(b);
    if (d >= kFanDegree) cands.push_back({a, b, part, d});
  }
  if (cands.empty()) return false;
  std::sort(cands.begin(), cands.end(), [](const Cand& x, const Cand& y) { return x.d != y.d ? x.d > y.d : x.a < y.a; });
  std::vector<char> used(P, 0);
  std::vector<Piece> pieces;
  std::vector<std::uint32_t> R;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> be;  // R's boundary edges (key, unused)
  std::vector<Vec2> w;
  std::vector<std::uint32_t> cid;
  StripStats& stats = nfp_strip_stats();
  bool planted = mode == kStripPlanted;
  for (const Cand& c : cands) {
    const std::uint32_t A = c.a, B = c.b;
    R.clear();
    for (const std::uint32_t v : {A, B}) {
      const auto [b0, b1] = parts_at(v);
      for (auto it = b0; it != b1; ++it)
        if (*it == c.part || (*it != in_part[A] && *it != out_part[B])) R.push_back(*it);
    }
    std::sort(R.begin(), R.end());
    R.erase(std::unique(R.begin(), R.end()), R.end());
    if (std::any_of(R.begin(), R.end(), [&](std::uint32_t k) { return used[k]; })) continue;
    // R's boundary: its parts' ring edges without the diagonals between them.
    be.clear();
    for (const std::uint32_t k : R) {
      const std::uint32_t s = X.start[k], m = X.start[k + 1] - s;
      for (std::uint32_t i = 0; i < m; ++i) be.push_back({key(X.id[s + i], X.id[s + (i + 1) % m]), 0});
    }
    std::sort(be.begin(), be.end());
    auto in_be = [&](std::uint64_t k) {
      const auto it = std::lower_bound(be.begin(), be.end(), std::pair(k, std::uint32_t(0)));
      return it != be.end() && it->first == k;
    };
    for (auto& e : be) e.second = in_be(key(std::uint32_t(e.first), std::uint32_t(e.first >> 32)));
    std::erase_if(be, [](const auto& e) { return e.second != 0; });
    // The chain B → … → A: one out-edge per vertex, one cycle through A → B.
    bool ok = in_be(key(A, B));
    w.clear(), cid.clear();
    std::uint32_t cur = B;
    w.push_back(pos[B]), cid.push_back(B);
    while (ok && cur != A) {
      const auto it = std::lower_bound(be.begin(), be.end(), std::pair(key(cur, 0), std::uint32_t(0)));
      if (it == be.end() || std::uint32_t(it->first >> 32) != cur || (it + 1 != be.end() && std::uint32_t((it + 1)->first >> 32) == cur) ||
          w.size() > be.size()) {
        ok = false;
        break;
      }
      cur = std::uint32_t(it->first);
      w.push_back(pos[cur]), cid.push_back(cur);
    }
    ok = ok && w.size() == be.size();  // K chain edges plus A → B
    if (ok && cover(w, cid, planted, pieces)) {
      for (const std::uint32_t k : R) used[k] = 1;
      ++stats.replaced;
      planted = false;
    } else {
      ++stats.kept;
    }
  }
  if (pieces.empty()) return false;
  out.v.clear(), out.id.clear(), out.start.clear(), out.lo.clear(), out.hi.clear();
  auto add = [&](const Vec2* v, const std::uint32_t* id, std::size_t m) {
    out.start.push_back(std::uint32_t(out.v.size()));
    Vec2 lo = v[0], hi = v[0];
    for (std::size_t i = 0; i < m; ++i) out.v.push_back(v[i]), out.id.push_back(id[i]), lo = lo.cwiseMin(v[i]), hi = hi.cwiseMax(v[i]);
    out.lo.push_back(lo), out.hi.push_back(hi);
  };
  for (std::uint32_t k = 0; k < P; ++k)
    if (!used[k]) add(&X.v[X.start[k]], &X.id[X.start[k]], X.start[k + 1] - X.start[k]);
  for (const Piece& p : pieces) add(p.v.data(), p.id.data(), p.v.size());
  out.start.push_back(std::uint32_t(out.v.size()));
  return true;
}

}  // namespace pendepth::nonconvex2
