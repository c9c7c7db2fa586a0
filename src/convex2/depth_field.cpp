// DepthField: σ(t) for a fixed pair of convex polygons in O(log(n + m)) per query after
// O((n + m) log(n + m)) preprocessing (DHS §3, Theorem 3.2; docs/algorithms.md §R3.2 "spoke tree").
// N = |M|, M = P ⊕ (−Q); σ(t) = dist(t, ∂M) for t ∈ int M, else 0.
//
// Structure: the medial axis of M (convex2/medial_axis.cpp) and a centroid decomposition of its
// tree of N − 2 internal nodes. The three spokes of a medial node v (from v along the outward
// normals of its three lines, to the tangent points) cut M into three pieces; the interior of a
// Voronoi cell of any other edge cannot cross a spoke, so each piece holds one branch of the tree
// and only the cells along it. A query descends the decomposition with one 3-sector test per
// level; when a branch ends (at an earlier centroid or a vertex of M) the query lies between the
// cells of the two lines separated by that last medial edge. Depth <= floor(log2(N − 2)) + 1.
//
// Exactness. The sector tests use constructed (rounded) medial vertices and normals, so a query
// can be misrouted only within rounding distance of a spoke. There the spoke's own edge — whose
// line is already a candidate, since every visited node contributes its three lines — is within
// that distance of optimal. The answer is the certified minimum (convex2::nearest_edge: filtered
// double, accurate fallback) over all lines collected on the path, so it is always the exact
// distance to a line of M, an upper bound of σ, and equals σ whenever routing is right. The
// inside test is the exact MinkowskiSum::contains_interior. If rounding makes the medial axis
// undefined (consecutive edge directions of M below ~1e-16 rad apart, or overflow) the field
// falls back to the O(N) certified scan and reports max_search_depth() = N, node_count() = 0.
//
// Build: centroid decomposition without recursion (the medial tree may be a path). Rooted at the
// node created last, subtree sizes come from one pass in creation order; after removing a
// centroid c only the sizes on the path from the component's root down to c change, and that
// path is the one walked to find c, so each component costs O(depth of its centroid) and the
// whole build O(N log N). The tree is renumbered heavy-child-first so those walks run through
// consecutive memory; the spoke nodes are laid out in decomposition preorder (sector 0's child
// adjacent).
#include <pendepth/depth2.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "convex2/medial_axis.hpp"
#include "convex2/minkowski_sum.hpp"
#include "geometry/exact.hpp"

namespace pendepth {

namespace {

// One centroid of the decomposition: a medial vertex and its three spokes. 128 bytes.
struct alignas(64) SpokeNode {
  double x, y;             // medial vertex, relative to Impl::origin
  double nx[3], ny[3];     // spoke k = outward normal of line k (CCW order)
  double c[3];             // offsets of the three lines (relative to Impl::origin)
  std::int32_t child[3];   // sector k (spoke k to spoke k+1, CCW): next node, or -1 if the branch ends
  std::uint32_t edge[3];   // the three edges of M
  std::int32_t wide;       // the sector wider than 180° (at most one), or 3
};

// Depth of the decomposition is <= log2(N) + 1 < 34 for N < 2^32.
constexpr std::size_t kMaxDepth = 64;

// Rigorous bound on |estimate − true distance| for the candidate prefilter, in units of
// unit-roundoff × (|vertex| + 2|vertex − origin| + 2|t − origin|), L1 norms. The estimate
// c_k − n_k·(t − origin) carries: normal direction error <= 5ε (rounded edge vector, norm,
// division), vertex rounding <= ε|v| + ε|v − origin|, two dot products <= 2ε each, the
// subtraction and the rounding of t − origin <= ε each: about 12ε(...) in all; 32 leaves margin.
constexpr double kEstimateBound = 32 * exact::kUnit;

}  // namespace

struct DepthField::Impl {
  explicit Impl(const ConvexPolygon& P, const ConvexPolygon& Q) : M(P, Q) {}
  convex2::MinkowskiSum M;
  Vec2 origin{0, 0};
  double scale = 0;  // max |v|_1 + 2 max |v − origin|_1 over vertices v of M
  std::vector<SpokeNode> nodes;
  std::size_t medial_nodes = 0;
  std::size_t depth = 0;
  bool linear = false;  // medial axis undefined in double: certified O(N) scan

  void build();
};

void DepthField::Impl::build() {
  const std::size_t N = M.size();
  convex2::MedialAxis ma = convex2::medial_axis(M);
  origin = ma.origin;
  double s_world = 0, s_local = 0;
  for (std::size_t k = 0; k < N; ++k) {
    const Vec2 v = M.vertex(k);
    s_world = std::max(s_world, v.cwiseAbs().sum());
    s_local = std::max(s_local, (v - origin).cwiseAbs().sum());
  }
  scale = s_world + 2 * s_local;
  if (!ma.ok || !std::isfinite(scale)) {
    linear = true;
    depth = N;
    medial_nodes = ma.ok ? ma.centre.size() : 0;
    return;
  }
  const std::size_t K = ma.centre.size();
  medial_nodes = K;

  // Rooted at the node created last, the parent of every other node is the later node that
  // consumed its wavefront vertex (its branch 2, see medial_axis.hpp), so parents have larger
  // indices and one ascending pass gives the subtree sizes.
  std::vector<std::int32_t> size(K, 1);
  for (std::size_t v = 0; v < K; ++v)
    if (std::int32_t(v) != ma.root) size[ma.adj[v][2]] += size[v];

  // Renumber in heavy-child-first preorder: the centroid searches below walk down heavy paths,
  // which then run through consecutive memory. Preorder positions follow from the sizes in one
  // descending pass (parents first): the heaviest child comes right after its parent, the others
  // after the subtrees before them. Each tree node keeps its children's current sizes, so a
  // search step reads only the node it stands on.
  struct TreeNode {
    std::int32_t adj[3];   // renumbered neighbours, −1 for leaves of the medial axis
    std::int32_t sub[3];   // size of the child behind adj[k] within the current component; 0 if
                           // adj[k] is the parent, a leaf, or already a centroid
    std::int32_t parent;   // −1 at the root
    std::int32_t size;     // own subtree size within the current component
    std::int32_t old;      // index in ma
    std::int8_t slot;      // k with tree[parent].adj[k] == this node
  };
  std::vector<TreeNode> tree(K);
  {
    std::vector<std::int32_t> pos(K);
    pos[ma.root] = 0;
    for (std::size_t v = K; v-- > 0;) {
      const auto& a = ma.adj[v];
      const bool is_root = std::int32_t(v) == ma.root;
      const int children = is_root ? 3 : 2;
      int order[3] = {0, 1, 2};  // child slots, heaviest first
      auto weight = [&](int k) { return a[k] >= 0 ? size[a[k]] : 0; };
      for (int k = 1; k < children; ++k)
        if (weight(order[k]) > weight(order[0])) std::swap(order[k], order[0]);
      if (children == 3 && weight(order[2]) > weight(order[1])) std::swap(order[1], order[2]);
      TreeNode& t = tree[pos[v]];
      std::int32_t next = pos[v] + 1;
      for (int s = 0; s < children; ++s) {
        const int k = order[s];
        t.sub[k] = weight(k);
        if (a[k] < 0) {
          t.adj[k] = -1;
          continue;
        }
        t.adj[k] = pos[a[k]] = next;
        tree[next].slot = std::int8_t(k);
        next += size[a[k]];
      }
      if (!is_root) {
        t.adj[2] = t.parent = pos[a[2]];
        t.sub[2] = 0;
      } else {
        t.parent = -1;
        t.slot = -1;
      }
      t.size = size[v];
      t.old = std::int32_t(v);
    }
  }
  std::vector<std::int32_t>().swap(size);

  // Centroid decomposition. A component is identified by its root: its node closest to the tree
  // root, an ancestor of all its nodes; its root's parent (if any) is an earlier centroid.
  struct Work {
    std::int32_t root, parent_node, slot;
    std::uint32_t depth;
  };
  std::vector<Work> work{{0, -1, 0, 1}};
  std::vector<std::int32_t> spoke_of(K);
  nodes.resize(K);
  std::int32_t emitted = 0;
  while (!work.empty()) {
    const Work job = work.back();
    work.pop_back();
    const std::int32_t total = tree[job.root].size;
    std::int32_t c = job.root;
    for (bool moved = true; moved;) {
      moved = false;
      const TreeNode& t = tree[c];
      for (int k = 0; k < 3; ++k)
        if (2 * t.sub[k] > total) {
          c = t.adj[k];
          moved = true;
          break;
        }
    }
    // Remove c: the components of its children keep their sizes; its ancestors up to the
    // component root lose c's subtree.
    const std::int32_t removed = tree[c].size;
    for (std::int32_t a = c; a != job.root;) {
      TreeNode& p = tree[tree[a].parent];
      p.sub[tree[a].slot] -= removed;
      p.size -= removed;
      a = tree[a].parent;
    }
    const std::int32_t id = emitted++;
    spoke_of[c] = id;
    if (job.parent_node >= 0) nodes[job.parent_node].child[job.slot] = id;
    depth = std::max<std::size_t>(depth, job.depth);
    const TreeNode& t = tree[c];
    // Children pushed in reverse so that sector 0's subtree follows its parent in memory.
    for (int k = 2; k >= 0; --k) {
      std::int32_t root = -1;  // −1: the branch ends here, terminal pair (line k, line k+1)
      if (t.adj[k] >= 0 && t.adj[k] == t.parent) root = c == job.root ? -1 : job.root;
      else if (t.sub[k] > 0) root = t.adj[k];
      nodes[id].child[k] = -1;
      if (root >= 0) work.push_back({root, id, k, job.depth + 1});
    }
  }

  // Geometry of each centroid, read in tree order: consecutive tree nodes share lines of M.
  for (std::size_t v = 0; v < K; ++v) {
    const std::int32_t m = tree[v].old;
    SpokeNode& s = nodes[spoke_of[v]];
    s.x = ma.centre[m].x();
    s.y = ma.centre[m].y();
    s.wide = ma.wide[m];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t e = ma.line[m][k];
      s.nx[k] = ma.normal[e].x();
      s.ny[k] = ma.normal[e].y();
      s.c[k] = ma.offset[e];
      s.edge[k] = e;
    }
  }
  if (depth > kMaxDepth) {  // cannot happen for N < 2^32; keeps the query's buffers safe
    linear = true;
    depth = N;
    nodes.clear();
  }
}

DepthField::DepthField(const ConvexPolygon& P, const ConvexPolygon& Q) : impl_(std::make_unique<Impl>(P, Q)) {
  impl_->build();
}
DepthField::~DepthField() = default;
DepthField::DepthField(DepthField&&) noexcept = default;
DepthField& DepthField::operator=(DepthField&&) noexcept = default;

Depth2 DepthField::minimum(const Vec2& t) const {
  convex2::require_finite(t, "placement t");
  const Impl& F = *impl_;
  if (!F.M.contains_interior(t)) return Depth2{};
  if (F.linear) {
    const convex2::Nearest best = convex2::nearest_edge(F.M, t);
    // t ∈ int M was decided exactly; a distance that rounds to 0 (subnormal scale) stays 0.
    return F.M.result_for_edge(best.edge, t, std::max(best.distance, 0.0));
  }

  const double ox = t.x() - F.origin.x(), oy = t.y() - F.origin.y();
  const double bound = kEstimateBound * (F.scale + 2 * (std::abs(ox) + std::abs(oy))) + exact::kTiny;
  double estimate[3 * kMaxDepth];
  std::uint32_t edge[3 * kMaxDepth];
  std::size_t count = 0;
  double best = std::numeric_limits<double>::infinity();
  std::int32_t at = 0;
  for (;;) {
    const SpokeNode& s = F.nodes[at];
    const double wx = ox - s.x, wy = oy - s.y;
    double turn[3];  // > 0: o − v lies counter-clockwise of spoke k
    for (int k = 0; k < 3; ++k) {
      const double d = s.c[k] - (s.nx[k] * ox + s.ny[k] * oy);
      estimate[count] = d;
      edge[count++] = s.edge[k];
      best = std::min(best, d);
      turn[k] = s.nx[k] * wy - s.ny[k] * wx;
    }
    // Sectors narrower than 180° by two turn signs; otherwise the wide one (or sector 0 when o
    // coincides with v, where all three lines are candidates anyway).
    int sector = s.wide < 3 ? s.wide : 0;
    for (int k = 0; k < 3; ++k)
      if (k != s.wide && turn[k] >= 0 && turn[(k + 1) % 3] < 0) {
        sector = k;
        break;
      }
    const std::int32_t next = s.child[sector];
    if (next < 0) break;
    at = next;
  }

  // Keep every candidate whose line may be the nearest, then decide among them with certified
  // distances.
  std::size_t kept[3 * kMaxDepth];
  std::size_t nkept = 0;
  const double limit = best + 2 * bound;
  for (std::size_t s = 0; s < count; ++s) {
    if (estimate[s] > limit) continue;
    // Consecutive nodes share lines; evaluate each line once.
    if (std::find(kept, kept + nkept, std::size_t(edge[s])) == kept + nkept) kept[nkept++] = edge[s];
  }
  const convex2::Nearest nearest = convex2::nearest_edge(F.M, t, kept, kept + nkept);
  // t ∈ int M was decided exactly above; a distance that rounds to 0 (subnormal scale) stays 0.
  return F.M.result_for_edge(nearest.edge, t, std::max(nearest.distance, 0.0));
}

std::size_t DepthField::edge_count() const { return impl_->M.size(); }
std::size_t DepthField::node_count() const { return impl_->medial_nodes; }
std::size_t DepthField::max_search_depth() const { return impl_->depth; }

}  // namespace pendepth
