#include "slicing/ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace mixengine {

int workerCount(std::size_t count, int threads) {
    const std::size_t wanted = static_cast<std::size_t>(std::max(1, threads));
    return static_cast<int>(std::max<std::size_t>(1, std::min(wanted, count)));
}

void parallelFor(std::size_t count, int threads,
                 const std::function<void(std::size_t index, int worker)>& task) {
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr first_error;
    std::mutex error_mutex;
    auto work = [&](int worker) {
        for (std::size_t i = next++; i < count && !failed; i = next++) {
            try {
                task(i, worker);
            } catch (...) {
                std::lock_guard lock(error_mutex);
                if (!first_error)
                    first_error = std::current_exception();
                failed = true;
            }
        }
    };
    const int workers = workerCount(count, threads);
    std::vector<std::thread> helpers;
    for (int w = 1; w < workers; ++w) {
        try {
            helpers.emplace_back(work, w);
        } catch (const std::system_error&) {
            break;  // no more threads available: the started workers share the rest
        }
    }
    work(0);
    for (std::thread& helper : helpers)
        helper.join();
    if (first_error)
        std::rethrow_exception(first_error);
}

}  // namespace mixengine
