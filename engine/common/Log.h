#pragma once
// A small logger passed by reference (no global state). Messages go to a stream (stderr in main).
// Verbosity: 0 = warnings and errors only, 1 = info (-v), 2 = debug (-vv).
#include <functional>
#include <mutex>
#include <ostream>
#include <string_view>
#include <utility>

#include "common/ProgressStage.h"

namespace mixengine {

class Log {
  public:
    explicit Log(std::ostream& out, int verbosity = 0) : out_(out), verbosity_(verbosity) {}

    void warning(std::string_view message) { write("[warning] ", message); }
    void info(std::string_view message) {
        if (verbosity_ >= 1)
            write("[info] ", message);
    }
    void debug(std::string_view message) {
        if (verbosity_ >= 2)
            write("[debug] ", message);
    }
    /// Progress of a stage, 0..1; printed ("Progress: slicing 42%", once per stage and percent)
    /// only when progress reporting is on (-p).
    void progress(ProgressStage stage, double fraction);

    /// Also hands every progress report to `sink` (e.g. Cura's socket), whether or not -p is on.
    /// The sink is called under the log's lock, so it sees one report at a time.
    using ProgressSink = std::function<void(ProgressStage stage, double fraction)>;
    void setProgressSink(ProgressSink sink) { sink_ = std::move(sink); }

    void setVerbosity(int verbosity) { verbosity_ = verbosity; }
    void setProgress(bool enabled) { progress_ = enabled; }
    int warningCount() const { return warnings_; }

  private:
    void write(std::string_view prefix, std::string_view message);

    std::ostream& out_;
    int verbosity_;
    bool progress_ = false;
    ProgressSink sink_;
    int warnings_ = 0;
    ProgressStage printed_stage_ = ProgressStage::Done;
    int printed_percent_ = -1;
    std::mutex mutex_;
};

}  // namespace mixengine
