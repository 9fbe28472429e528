#include "common/Log.h"

#include <cmath>

namespace mixengine {

void Log::write(std::string_view prefix, std::string_view message) {
    std::lock_guard lock(mutex_);
    if (prefix == "[warning] ")
        ++warnings_;
    out_ << prefix << message << '\n';
}

void Log::progress(ProgressStage stage, double fraction) {
    if (!progress_ && !sink_)
        return;
    std::lock_guard lock(mutex_);
    if (sink_)
        sink_(stage, fraction);
    const int percent = static_cast<int>(std::lround(fraction * 100.0));
    if (progress_ && (stage != printed_stage_ || percent != printed_percent_))  // once per percent
        out_ << "Progress: " << progressStageName(stage) << ' ' << percent << "%\n";
    printed_stage_ = stage;
    printed_percent_ = percent;
}

}  // namespace mixengine
