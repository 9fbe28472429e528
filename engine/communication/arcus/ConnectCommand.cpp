// `mixengine connect <host>:<port>`: the engine Cura spawns. Connects to Cura's socket, waits for
// one Slice, runs the same pipeline as `slice`, streams the results back and exits 0.
#include <algorithm>

#include "Cura.pb.h"
#include "common/ParallelFor.h"
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
/// stages fill it: Slicing is its slicing, Toolpaths its parts, inset/skin and support, GCode its
/// export, Done its finish.
double overallProgress(ProgressStage stage, double fraction) {
    switch (stage) {
        case ProgressStage::Slicing:
            return 0.3 * fraction;
        case ProgressStage::Toolpaths:
            return 0.3;
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
        const double amount = std::max(sent_, overallProgress(stage, fraction));
        if (amount - sent_ < 0.001 && !(amount == 1.0 && sent_ < 1.0))
            return;
        sent_ = amount;
        session_.send(progressMessage(amount));  // throws when Cura has gone: the slice stops
    }

  private:
    ArcusSession& session_;
    double sent_ = -1.0;
};

void sliceAndReply(const cura::proto::Slice& slice, int threads, ArcusSession& session, Log& log) {
    SliceRequest request = requestFromSlice(slice);
    log.setProgressSink(ProgressReporter(session));
    const Scene scene = prepareScene(request, log);

    std::vector<std::shared_ptr<cura::proto::LayerOptimized>> preview;
    Point2 head{0, 0};
    int extruder = 0;
    const PlanObserver observe = [&](const PrintPlan& plan) {
        auto layers = previewLayers(plan, 0, head, extruder);  // the plan's indexes run on across groups
        preview.insert(preview.end(), layers.begin(), layers.end());
    };
    const GCodeOutput gcode = runPipeline(scene, effectiveThreads(threads), log, observe);

    session.send(gcodeLayerMessage(gcode.start));
    for (const std::string& chunk : gcode.layer_chunks)
        session.send(gcodeLayerMessage(chunk));
    for (const auto& layer : preview)
        session.send(layer);
    session.send(gcodePrefixMessage(gcode.header));
    session.send(gcodeLayerMessage(gcode.suffix));
    session.send(estimatesMessage(gcode.summary));
    session.send(slicingFinishedMessage());
    log.setProgressSink({});
    log.info("sliced " + std::to_string(gcode.layer_chunks.size()) + " layers for Cura");
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
    session.connect(args.host, args.port, 10s);
    const std::shared_ptr<cura::proto::Slice> slice = session.waitForSlice();
    if (!slice) {
        log.info("Cura closed the connection before sending a slice");
        return 0;
    }
    sliceAndReply(*slice, args.threads, session, log);
    session.close(10s);
    return 0;
}

}  // namespace mixengine
