#pragma once
// Turns SIGTERM and SIGINT into a call on a thread of its own while it lives, so that a process
// told to stop (Cura ends its engine with SIGTERM) can end its work and its threads cleanly instead
// of dying half-way. The constructor blocks both signals in the calling thread; every thread
// started after it inherits the block, so no signal interrupts library code. Its thread takes the
// signals with sigtimedwait() and calls `on_signal(signal_number)` for each.
//
// Construct it before any other thread starts. The block stays when the watch is gone: a signal
// that arrives during the last clean-up stays pending and dies with the process, rather than
// killing it half-way through.
#include <atomic>
#include <functional>
#include <thread>

namespace mixengine {

class SignalWatch {
  public:
    explicit SignalWatch(std::function<void(int signal_number)> on_signal);
    ~SignalWatch();  ///< stops and joins the watching thread
    SignalWatch(const SignalWatch&) = delete;
    SignalWatch& operator=(const SignalWatch&) = delete;

  private:
    void watch();

    std::function<void(int)> on_signal_;
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

}  // namespace mixengine
