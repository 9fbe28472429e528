// `mixengine connect <host>:<port>`: the engine Cura spawns. Connects to Cura's socket, waits for
// one Slice, runs the same pipeline as `slice`, streams the results back and exits 0.
#include <algorithm>

#include "Cura.pb.h"
#include "common/ParallelFor.h"
#include "common/SignalWatch.h"
#include "communication/Commands.h"
#include "communication/HelpText.h"
#include "communication/arcus/ArcusSession.h"
#include "communication/arcus/ConnectArgs.h"
#include "communication/arcus/PreviewLayers.h"
#include "communication/arcus/ResultMessages.h"
#include "communication/arcus/SliceMessage.h"
#include "pipeline/FffProcessor.h"

namespace mixengine {
namespace {

using namespace std::chrono_literals;

/// The pipeline's stage reports → one monotonic 0..1 amount for Cura's progress bar. As CuraEngine's
/// stages fill it: Slicing (0–0.3) is its slicing, Toolpaths (0.3–0.8, by the meshes' layers done)
/// its parts, inset/skin and support, GCode its export, Done its finish.
double overallProgress(ProgressStage stage, double fraction) {
    switch (stage) {
        case ProgressStage::Slicing:
            return 0.3 * fraction;
        case ProgressStage::Toolpaths:
            return 0.3 + 0.5 * fraction;
        case ProgressStage::GCode:
            return 0.8;
        case ProgressStage::Done:
            return 1.0;
    }
    return 0.0;
}

class ProgressReporter {
  public:
    explicit ProgressReporter(ArcusSession& session) : session_(session) {}
    void operator()(ProgressStage stage, double fraction) {
        session_.checkOpen();  // every report is a point where the slice stops once Cura has gone
        const double amount = std::max(sent_, overallProgress(stage, fraction));
        if (amount - sent_ < 0.001 && !(amount == 1.0 && sent_ < 1.0))
            return;
        sent_ = amount;
        session_.send(*progressMessage(amount));  // throws CuraEnded when Cura has gone: the slice stops
    }

  private:
    ArcusSession& session_;
    double sent_ = -1.0;
};

/// Sends each layer as it is written: its G-code, then its preview. Layers made before the start
/// code is known (a print of several mesh groups) wait for it, then go in order.
class LayerSender {
  public:
    explicit LayerSender(ArcusSession& session) : session_(session) {}

    void start(const std::string& start_code) {
        session_.send(*gcodeLayerMessage(start_code));
        started_ = true;
        for (const auto& [gcode, preview] : held_) {
            session_.send(*gcode);
            session_.send(*preview);
        }
        held_.clear();
    }

    void layer(StreamedLayer&& layer) {
        if (layer.first_of_group)
            cursor_.previous_z = 0;
        MessagePtr preview = previewLayer(*layer.layer, layer.number, cursor_);
        MessagePtr gcode = gcodeLayerMessage(layer.gcode);
        if (!started_) {
            held_.emplace_back(std::move(gcode), std::move(preview));
            return;
        }
        session_.send(*gcode);
        session_.send(*preview);
        ++sent_;
    }

    int layersSent() const { return sent_ + static_cast<int>(held_.size()); }

  private:
    ArcusSession& session_;
    PreviewCursor cursor_;
    bool started_ = false;
    std::vector<std::pair<MessagePtr, MessagePtr>> held_;
    int sent_ = 0;
};

/// Cura's progress bar hears of the pipeline for as long as this lives.
class ProgressLink {
  public:
    ProgressLink(Log& log, ArcusSession& session) : log_(log) {
        log_.setProgressSink(ProgressReporter(session));
    }
    ~ProgressLink() { log_.setProgressSink({}); }
    ProgressLink(const ProgressLink&) = delete;
    ProgressLink& operator=(const ProgressLink&) = delete;

  private:
    Log& log_;
};

void sliceAndReply(const cura::proto::Slice& slice, int threads, ArcusSession& session, Log& log) {
    SliceRequest request = requestFromSlice(slice);
    const ProgressLink progress(log, session);
    const Scene scene = prepareScene(request, log);

    LayerSender sender(session);
    LayerStream stream;
    stream.start = [&sender](const std::string& start_code) { sender.start(start_code); };
    stream.layer = [&sender](StreamedLayer&& layer) { sender.layer(std::move(layer)); };
    const GCodeOutput gcode = runPipeline(scene, effectiveThreads(threads), log, {}, stream);

    session.send(*gcodePrefixMessage(gcode.header));
    session.send(*gcodeLayerMessage(gcode.suffix));
    session.send(*estimatesMessage(gcode.summary));
    session.send(*slicingFinishedMessage());
    log.info("sliced " + std::to_string(sender.layersSent()) + " layers for Cura");
}

}  // namespace

int runConnectCommand(const Words& words, std::ostream& out, std::ostream& err) {
    const ConnectArgs args = parseConnectArguments(words);
    if (args.help) {
        out << commandHelp("connect").value_or("");
        return 0;
    }
    Log log(err, args.verbosity);
    for (const std::string& word : args.ignored)
        log.warning("connect: ignoring unknown option '" + word + "'");
    ArcusSession session(log);
    // Cura ends its engine with SIGTERM (CuraEngineBackend._terminate): the talk ends and the slice
    // stops at its next message, every thread joined, exit 0.
    const SignalWatch signals([&session, &log](int signal_number) {
        log.info("signal " + std::to_string(signal_number) + ": ending the talk with Cura");
        session.end();
    });
    session.connect(args.host, args.port, 10s);
    try {
        const std::unique_ptr<cura::proto::Slice> slice = session.waitForSlice();
        if (!slice) {
            log.info("Cura ended the talk before sending a slice");
            return 0;
        }
        sliceAndReply(*slice, args.threads, session, log);
        session.close(10s);
    } catch (const CuraEnded& ended) {
        log.info(std::string(ended.what()) + " before the slice was sent; stopped");
    }
    return 0;
}

}  // namespace mixengine
