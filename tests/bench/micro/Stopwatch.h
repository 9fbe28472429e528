#pragma once
// Wall and CPU time of a piece of work, for the micro benchmarks (they print, never judge).
#include <chrono>
#include <cstdio>
#include <ctime>

namespace mixengine::bench {

/// CPU time of this process in all its threads, seconds.
inline double processCpuSeconds() {
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

struct Timing {
    double wall_s = 0;
    double cpu_s = 0;
};

/// Runs `work` once and returns its wall and CPU time.
template <class Work>
Timing timed(Work&& work) {
    const auto wall_start = std::chrono::steady_clock::now();
    const double cpu_start = processCpuSeconds();
    work();
    const double cpu = processCpuSeconds() - cpu_start;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    return {wall, cpu};
}

/// One result line: "bench <name>: <wall> ms wall, <cpu> ms CPU (<what>)".
inline void printTiming(const char* name, const Timing& t, const char* what) {
    std::printf("bench %s: %.3f ms wall, %.3f ms CPU (%s)\n", name, t.wall_s * 1e3, t.cpu_s * 1e3, what);
}

}  // namespace mixengine::bench
