// pendepth — parallel batches (src/front/batch.hpp).
#include "front/batch.hpp"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace pendepth::front {

void parallel_for(std::size_t n, unsigned threads, const std::function<void(std::size_t)>& run) {
  if (n == 0) return;
  if (threads == 1 || n == 1) {
    for (std::size_t i = 0; i < n; ++i) run(i);
    return;
  }
  // Blocks of a few queries: a query costs from ~100 ns (convex σ) to milliseconds, so the
  // std::function call and the task overhead stay small against the work of a block.
  const auto body = [&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 8), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) run(i);
    });
  };
  if (threads == 0) {
    body();
  } else {
    // More threads than the machine runs at once would only wait (TBB warns): same answers.
    tbb::task_arena arena(std::min(static_cast<int>(threads), tbb::info::default_concurrency()));
    arena.execute(body);
  }
}

}  // namespace pendepth::front
