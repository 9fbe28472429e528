#pragma once
// Where a print's G-code goes while it is being made (Cura's socket, communication/arcus): every
// layer as soon as it is written, the start code as soon as it is known. Without a stream the
// pipeline keeps the layers in GCodeOutput::layer_chunks as before; with one it hands each chunk
// over and keeps none, so the text of the whole print is never held at once.
//
// Order: layers are handed over in print order from one thread at a time (the streamed writer's,
// or the pipeline's own), each chunk exactly the text GCodeOutput::layer_chunks would hold (BFB
// line ends applied). The start code (GCodeOutput::start) is handed over once, when the number of
// model layers of the whole print is known: before the first layer of a print of one mesh group,
// and before the last group's first layer otherwise — the layers handed over before it print
// after it. A mixing print's layers are handed over once the group's mixes are assigned (the
// chamber's look-ahead runs over the whole group).
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "planning/LayerPlan.h"

namespace mixengine {

struct StreamedLayer {
    int number = 0;                       ///< its ";LAYER:<number>"
    const PlannedLayer* layer = nullptr;  ///< valid during the call only
    bool first_of_group = false;          ///< the first layer of its mesh group
    std::string gcode;                    ///< the layer's chunk
};

struct LayerStream {
    std::function<void(StreamedLayer&& layer)> layer;  ///< empty: no stream
    std::function<void(const std::string& start)> start;
};

/// Hands written layers to a stream, or keeps them (no stream), applying BFB line ends
/// (gcode/Bfb.h) when `bfb_verbatim` is set.
class LayerOutput {
  public:
    LayerOutput(LayerStream stream, const std::vector<std::string>* bfb_verbatim,
                std::vector<std::string>& kept)
        : stream_(std::move(stream)), bfb_verbatim_(bfb_verbatim), kept_(kept) {}

    /// The start code of the print (once).
    void start(const std::string& text) const;
    /// The chunk just written for `layer` (moved out of `chunks`' last entry).
    void take(std::vector<std::string>& chunks, const PlannedLayer& layer, int number);
    /// The next layer taken is the first of a new mesh group.
    void newGroup() { first_of_group_ = true; }
    /// How many layers were taken so far.
    int taken() const { return taken_; }

  private:
    LayerStream stream_;
    const std::vector<std::string>* bfb_verbatim_;
    std::vector<std::string>& kept_;
    bool first_of_group_ = true;
    int taken_ = 0;
};

}  // namespace mixengine
