#pragma once
// A minimal parallel loop over indices with std::thread (no global pool).
//
// Contract: task(index, worker) is called exactly once for every index in [0, count), from
// `threads` workers (at least 1, at most count; worker ∈ [0, workers)), indices handed out one at
// a time so uneven tasks balance. The calling thread is worker 0. If tasks throw, the remaining
// indices are skipped and the first exception is rethrown after every worker has stopped.
#include <cstddef>
#include <functional>

namespace mixengine {

/// The number of workers parallelFor will use.
int workerCount(std::size_t count, int threads);

void parallelFor(std::size_t count, int threads,
                 const std::function<void(std::size_t index, int worker)>& task);

}  // namespace mixengine
