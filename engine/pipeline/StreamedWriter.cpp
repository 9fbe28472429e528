#include "pipeline/StreamedWriter.h"

namespace mixengine {

StreamedWriter::StreamedWriter(const PlanWriterParams& params, GCodeExport& gcode,
                               std::optional<int> first_number, LayerOutput& output)
    : params_(params), gcode_(gcode), first_number_(first_number), output_(output), thread_([this] {
          run();
      }) {}

StreamedWriter::~StreamedWriter() {
    stop();
}

FinalLayer StreamedWriter::observer() {
    return [this](const PrintPlan& plan, std::size_t layer) { hand(plan, layer); };
}

void StreamedWriter::hand(const PrintPlan& plan, std::size_t layer) {
    {
        std::lock_guard lock(mutex_);
        if (error_)
            std::rethrow_exception(error_);  // the writer or its output failed: stop planning
        if (layer == 0) {                    // the tables are complete before the first layer is
            mesh_names_ = plan.mesh_names;
            mixes_ = plan.mixes;
            outlet_colors_ = plan.outlet_colors;
        }
        queue_.push_back(&plan.layers[layer]);
    }
    handed_.notify_one();
}

void StreamedWriter::run() {
    const PlanTables tables{mesh_names_, mixes_, outlet_colors_};
    int offset = 0;
    for (std::size_t next = 0;; ++next) {
        const PlannedLayer* layer = nullptr;
        {
            std::unique_lock lock(mutex_);
            handed_.wait(lock, [&] { return done_ || next < queue_.size(); });
            if (next >= queue_.size())
                return;
            layer = queue_[next];
        }
        if (next == 0 && first_number_)
            offset = *first_number_ - layer->index;
        try {
            const int number = layer->index + offset;
            writeLayer(*layer, number, tables, params_, gcode_, written_);
            output_.take(written_.chunks, *layer, number);
        } catch (...) {
            std::lock_guard lock(mutex_);
            error_ = std::current_exception();
            return;
        }
    }
}

void StreamedWriter::stop() {
    {
        std::lock_guard lock(mutex_);
        done_ = true;
    }
    handed_.notify_one();
    if (thread_.joinable())
        thread_.join();
}

WrittenLayers StreamedWriter::finish() {
    stop();
    if (error_)
        std::rethrow_exception(error_);
    return std::move(written_);
}

}  // namespace mixengine
