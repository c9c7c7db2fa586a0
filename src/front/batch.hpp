// pendepth — parallel batches for the front door (src/front/).
//
// Contract: run(i) is called exactly once for every i in [0, n), on up to `threads` threads
// (0 = every core, 1 = the calling thread only). Each answer depends on its own input only, so
// results are bit-identical to one-at-a-time calls whatever the thread count or the schedule.
// run must not throw (inputs are validated before a batch starts).
//
// Why TBB (Debian's libtbb-dev): work stealing balances queries of very different cost (a σ
// deep inside a no-fit polygon against one far outside), nested use from a caller's own TBB code
// composes, and task_arena bounds the thread count per call without a pool of our own.
#pragma once

#include <cstddef>
#include <functional>

namespace pendepth::front {

/// Calls run(i) for i in [0, n) in parallel (see the file comment).
void parallel_for(std::size_t n, unsigned threads, const std::function<void(std::size_t)>& run);

}  // namespace pendepth::front
