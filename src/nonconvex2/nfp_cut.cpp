// The per-pair no-fit polygon, reference cutting of one candidate (issue 5 item 4; see
// nfp_build.cpp): the candidate is cut by the open sums S_ij whose boxes meet its box (dual descent
// over the two triangle hierarchies; floating filters first, then sum_interval exactly), and the
// uncovered closed pieces are kept (edge_cut.hpp, the same cutting as σ). A point of a candidate
// lies on ∂S for a non-degenerate S of the family, so if no open sum covers it, it is in
// cl(O) \ O = ∂O.
// Cost per candidate: the pairs whose sum box meets the candidate's box, worst case O(nm) exact
// tests. A floating oriented-slab filter (the candidate's line and its extent along it, separable
// over the two triangles) drops most visited pairs before a sum is built; on real pieces only a
// few sums per candidate are built and cut exactly (counts in docs/benchmarks.md).
// The builder classifies candidates by nfp_classify.cpp, which is cheaper when few candidates
// cross; it falls back to this cutting for a candidate it cannot settle, and the tests use this
// as the reference for nfp_classify (the same pieces, exactly).
#include <cmath>

#include "geometry/exact.hpp"
#include "nonconvex2/nfp_impl.hpp"

namespace pendepth::nonconvex2 {

namespace {

double lower(double x) { return x - std::abs(x) * 0x1p-44 - 0x1p-1000; }
double upper(double x) { return x + std::abs(x) * 0x1p-44 + 0x1p-1000; }

// The point at parameter p of E, each coordinate to a few ulps (a sum vertex: rounded to nearest).
Vec2 point_at(const NfpCandidate& c, const Param& p) {
  if (p.kind == Param::Zero) return c.A;
  if (p.kind == Param::One) return c.B;
  // An axis-parallel candidate (common on real pieces) keeps that coordinate of its ends exactly;
  // accurate_ratio would need rationals to certify the exact value.
  const bool flat_y = c.E.a1.y() == c.E.b1.y(), flat_x = c.E.a1.x() == c.E.b1.x();
  const Cand cd{c.E, p, {}};
  if (flat_y || flat_x) {
    return flat_y ? Vec2(cand_coord(cd, Vec2(0, 0), 0), c.A.y()) : Vec2(c.A.x(), cand_coord(cd, Vec2(0, 0), 1));
  }
  return cand_translation(cd, Vec2(0, 0));
}

// The oriented slab filter: true when every vertex of T ⊕ B lies strictly on one side of the
// candidate line (normal values cross(dir, v) vs nA), or strictly before pA or after pB along dir,
// each by the margin. Sum vertices are t + b, so extremes split over T and B.
bool slab_rejects(const Tri& T, const Tri& B, const Vec2& dir, double dlen, double nA, double pA, double pB, double scale_edge) {
  double nlo = INFINITY, nhi = -INFINITY, plo = INFINITY, phi = -INFINITY, sc = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec2& t = T.v[k];
    const double n = dir.x() * t.y() - dir.y() * t.x(), p = dir.dot(t);
    nlo = std::min(nlo, n), nhi = std::max(nhi, n), plo = std::min(plo, p), phi = std::max(phi, p);
    sc = std::max(sc, std::abs(t.x()) + std::abs(t.y()));
  }
  double mlo = INFINITY, mhi = -INFINITY, qlo = INFINITY, qhi = -INFINITY, sb = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec2& b = B.v[k];
    const double n = dir.x() * b.y() - dir.y() * b.x(), p = dir.dot(b);
    mlo = std::min(mlo, n), mhi = std::max(mhi, n), qlo = std::min(qlo, p), qhi = std::max(qhi, p);
    sb = std::max(sb, std::abs(b.x()) + std::abs(b.y()));
  }
  const double margin = (sc + sb + scale_edge) * dlen * 0x1p-36;
  return nhi + mhi < nA - margin || nlo + mlo > nA + margin || phi + qhi < pA - margin || plo + qlo > pB + margin;
}

}  // namespace

NfpPiece make_piece(const NfpCandidate& c, const Param& lo, const Param& hi) { return make_piece(c, lo, hi, point_at(c, lo), point_at(c, hi)); }

NfpPiece make_piece(const NfpCandidate& c, const Param& lo, const Param& hi, const Vec2& a, const Vec2& b) {
  NfpPiece pc{c.E, c.line, lo, hi, a, b, {}, {}};
  pc.blo = Vec2(lower(std::min(pc.a.x(), pc.b.x())), lower(std::min(pc.a.y(), pc.b.y())));
  pc.bhi = Vec2(upper(std::max(pc.a.x(), pc.b.x())), upper(std::max(pc.a.y(), pc.b.y())));
  return pc;
}

void nfp_cut(const PairDepth2::Impl& S, const NfpCandidate& c, std::vector<NfpPiece>& out) {
  const Ray& E = c.E;
  const Line& line = c.line;
  const Vec2 &A = c.A, &B = c.B, &slo = c.lo, &shi = c.hi;
  const double scale_edge = A.cwiseAbs().maxCoeff() + B.cwiseAbs().maxCoeff();
  // The candidate's frame for the oriented slab filter: the direction B − A and its normal (dir
  // from the exact input difference a1 − b1, so it is accurate even for a short candidate).
  const Vec2 dir = E.a1 - E.b1;
  const double dlen = std::abs(dir.x()) + std::abs(dir.y());
  const double nA = dir.x() * A.y() - dir.y() * A.x(), pA = dir.dot(A), pB = pA + dir.dot(dir);
  std::vector<Cover> covers;
  const Param zero{Param::Zero, {}}, one{Param::One, {}};
  bool swallowed = false;
  S.descend(
      [&](const Vec2& lo, const Vec2& hi) {
        return !(lo.x() > shi.x() || hi.x() < slo.x() || lo.y() > shi.y() || hi.y() < slo.y());
      },
      [&](std::uint32_t i, std::uint32_t j) {
        // Oriented slab filter (no sum built): T_i ⊕ (−U_j) entirely on one side of the
        // candidate's line, or entirely before A or after B along it, by a margin far above every
        // rounding (A, B and the triangle vertices are within a few ulps of exact points; the
        // products within a few ulps) cannot cover any point of the candidate: the exact tests
        // below would reject it too.
        if (slab_rejects(S.tp[i], S.tb[j], dir, dlen, nA, pA, pB, scale_edge)) return false;
        const Sum F = make_sum(S.tp[i], S.tb[j]);
        double scale = 0;
        for (const auto& v : F.v) scale = std::max(scale, v.p.cwiseAbs().maxCoeff() + v.b.cwiseAbs().maxCoeff());
        if (surely_outside(F, A, B, scale + scale_edge)) return false;
        if (surely_inside(F, A, B, scale + scale_edge)) return swallowed = true;
        Cover cv;
        if (!sum_interval(F, E, cv.entry, cv.exit, &line)) return false;
        const Param en{Param::Cut, cv.entry}, ex{Param::Cut, cv.exit};
        const Vec2 o(0, 0);
        if (compare_params(ex, zero, E, o) <= 0 || compare_params(en, one, E, o) >= 0) return false;
        if (compare_params(en, zero, E, o) < 0 && compare_params(ex, one, E, o) > 0) return swallowed = true;
        covers.push_back(cv);
        return false;
      },
      nullptr);
  if (swallowed) return;
  uncovered_pieces(covers, E, Vec2(0, 0), zero, one, [&](const Param& lo, const Param& hi) { out.push_back(make_piece(c, lo, hi)); });
}

}  // namespace pendepth::nonconvex2
