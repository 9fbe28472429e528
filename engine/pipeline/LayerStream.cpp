#include "pipeline/LayerStream.h"

#include "gcode/Bfb.h"

namespace mixengine {

void LayerOutput::start(const std::string& text) const {
    if (stream_.start)
        stream_.start(bfb_verbatim_ ? withBfbLineEnds(text, *bfb_verbatim_) : text);
}

void LayerOutput::take(std::vector<std::string>& chunks, const PlannedLayer& layer, int number) {
    std::string chunk = std::move(chunks.back());
    chunks.pop_back();
    const bool first = first_of_group_;
    first_of_group_ = false;
    ++taken_;
    if (!stream_.layer) {
        kept_.push_back(std::move(chunk));  // BFB line ends: applied to the whole output at the end
        return;
    }
    if (bfb_verbatim_)
        chunk = withBfbLineEnds(chunk, *bfb_verbatim_);
    stream_.layer(StreamedLayer{number, &layer, first, std::move(chunk)});
}

}  // namespace mixengine
