#pragma once
// Writes the G-code of a plan while it is being made: the planner hands over each layer once it is
// final (planning/PrintPlanner.h FinalLayer), and a thread of this writer writes it through the
// GCodeExport (gcode/PlanWriter.h writeLayer) as the later layers are still being planned. The text
// is writePlan()'s for the finished plan, renumbered as the pipeline renumbers (first_number).
// Layers are written in the order they are handed over; the planner's layers stay in place until
// finish() returns. The GCodeExport and the LayerOutput are the writer thread's alone until finish()
// returns: each layer's chunk goes to the LayerOutput as soon as it is written (to Cura's socket, or
// kept). When writing or the output fails, the next hand-over rethrows it, so planning stops too.
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "gcode/PlanWriter.h"
#include "pipeline/LayerStream.h"
#include "planning/PrintPlanner.h"

namespace mixengine {

class StreamedWriter {
  public:
    /// `first_number`: the number of the plan's first layer (the rest follow it); nothing: the
    /// layers keep their own numbers.
    StreamedWriter(const PlanWriterParams& params, GCodeExport& gcode, std::optional<int> first_number,
                   LayerOutput& output);
    ~StreamedWriter();  ///< stops and joins the thread (e.g. when planning threw)
    StreamedWriter(const StreamedWriter&) = delete;
    StreamedWriter& operator=(const StreamedWriter&) = delete;

    /// The planner's FinalLayer: queues the layer for the writer thread.
    FinalLayer observer();
    /// After the last layer was handed over: waits for the writer; rethrows what it threw. The
    /// result's chunks are empty (they went to the LayerOutput); its bounds are the layers'.
    WrittenLayers finish();

  private:
    void hand(const PrintPlan& plan, std::size_t layer);
    void run();
    void stop();

    const PlanWriterParams& params_;
    GCodeExport& gcode_;
    std::optional<int> first_number_;
    LayerOutput& output_;
    std::vector<std::string> mesh_names_;  ///< copies of the plan's tables (PlanTables)
    std::vector<MixVector> mixes_;
    std::vector<std::array<std::uint8_t, 3>> outlet_colors_;
    std::mutex mutex_;
    std::condition_variable handed_;
    std::vector<const PlannedLayer*> queue_;  ///< handed over, in order
    bool done_ = false;
    std::exception_ptr error_;
    WrittenLayers written_;
    std::thread thread_;
};

}  // namespace mixengine
