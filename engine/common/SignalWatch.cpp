#include "common/SignalWatch.h"

#include <csignal>
#include <ctime>

#include <pthread.h>

namespace mixengine {
namespace {

sigset_t watchedSignals() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGINT);
    return set;
}

}  // namespace

SignalWatch::SignalWatch(std::function<void(int)> on_signal) : on_signal_(std::move(on_signal)) {
    const sigset_t set = watchedSignals();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    thread_ = std::thread([this] { watch(); });
}

SignalWatch::~SignalWatch() {
    stop_ = true;
    thread_.join();
}

void SignalWatch::watch() {
    const sigset_t set = watchedSignals();
    const timespec poll_interval{0, 50'000'000};  // how often it looks whether to stop
    while (!stop_) {
        const int signal_number = sigtimedwait(&set, nullptr, &poll_interval);
        if (signal_number > 0)
            on_signal_(signal_number);
    }
}

}  // namespace mixengine
