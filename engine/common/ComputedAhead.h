#pragma once
// Overlaps an order-dependent loop with the independent work it needs: use(i, make(i)) for i in
// [0, count), use() on the calling thread in ascending i (it may carry state from one i to the
// next), make() on `threads` helper threads ahead of it, at most `ahead` values made but not yet
// used (memory stays bounded). The helpers run at a lower scheduling priority (Linux: nice +10 per
// thread), so on a machine with no core to spare use() keeps its core: it is the ordered critical
// path, and made values wait for it anyway. threads ≤ 1: make and use alternate on the calling
// thread. The first exception thrown by make or use stops the helpers and is rethrown.
#include <cerrno>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#ifdef __linux__
#include <sys/resource.h>
#include <unistd.h>
#endif

namespace mixengine {

/// Lowers the calling thread's scheduling priority by `niceness` (Linux; elsewhere nothing).
inline void yieldPriorityToOthers(int niceness) {
#ifdef __linux__
    const auto tid = static_cast<id_t>(gettid());
    errno = 0;
    const int current = getpriority(PRIO_PROCESS, tid);
    if (errno == 0)
        (void)setpriority(PRIO_PROCESS, tid, current + niceness);  // best effort: ignored when refused
#else
    (void)niceness;
#endif
}

template <typename T, typename Make, typename Use>
void computeAhead(std::size_t count, int threads, std::size_t ahead, Make make, Use use) {
    if (threads <= 1 || count <= 1) {
        for (std::size_t i = 0; i < count; ++i)
            use(i, make(i));
        return;
    }
    std::vector<std::optional<T>> made(count);
    std::mutex mutex;
    std::condition_variable changed;
    std::size_t next = 0, used = 0;
    bool stop = false;
    std::exception_ptr error;
    auto fail = [&] {
        std::lock_guard lock(mutex);
        if (!error)
            error = std::current_exception();
        stop = true;
    };
    auto helper = [&] {
        yieldPriorityToOthers(10);
        for (;;) {
            std::size_t i = 0;
            {
                std::unique_lock lock(mutex);
                changed.wait(lock, [&] { return stop || next >= count || next < used + ahead; });
                if (stop || next >= count)
                    return;
                i = next++;
            }
            try {
                T value = make(i);
                std::lock_guard lock(mutex);
                made[i] = std::move(value);
            } catch (...) {
                fail();
            }
            changed.notify_all();
        }
    };
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back(helper);
    try {
        for (std::size_t i = 0; i < count; ++i) {
            std::optional<T> value;
            {
                std::unique_lock lock(mutex);
                changed.wait(lock, [&] { return stop || made[i].has_value(); });
                if (stop)
                    break;
                value = std::move(made[i]);
                made[i].reset();
                used = i + 1;
            }
            changed.notify_all();
            use(i, std::move(*value));
        }
    } catch (...) {
        fail();
    }
    {
        std::lock_guard lock(mutex);
        stop = true;
    }
    changed.notify_all();
    for (std::thread& t : pool)
        t.join();
    if (error)
        std::rethrow_exception(error);
}

}  // namespace mixengine
