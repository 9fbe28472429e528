#pragma once
// Counts work done item by item (e.g. layers) on several threads and reports the share done to a
// callback — Log::progress, whose sink may throw to stop the work (Cura ended the talk): the
// exception then leaves the parallelFor the item runs in. A default WorkProgress reports nothing.
#include <atomic>
#include <cstddef>
#include <functional>
#include <utility>

namespace mixengine {

class WorkProgress {
  public:
    WorkProgress() = default;
    WorkProgress(std::function<void(double share_done)> report, std::size_t total_items)
        : report_(std::move(report)), total_(total_items) {}
    WorkProgress(const WorkProgress&) = delete;
    WorkProgress& operator=(const WorkProgress&) = delete;

    /// One more item done (thread-safe); reports the share done, 0..1.
    void itemDone() const {
        const std::size_t done = ++done_;
        if (report_ && total_ > 0)
            report_(static_cast<double>(std::min(done, total_)) / static_cast<double>(total_));
    }

  private:
    std::function<void(double)> report_;
    std::size_t total_ = 0;
    mutable std::atomic<std::size_t> done_{0};
};

}  // namespace mixengine
