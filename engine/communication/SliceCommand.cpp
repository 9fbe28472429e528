// `mixengine slice`: CuraEngine-compatible command line → pipeline → G-code file.
#include <chrono>
#include <optional>

#include "common/Log.h"
#include "common/ParallelFor.h"
#include "communication/CommandLineParser.h"
#include "communication/Commands.h"
#include "communication/OutputFile.h"
#include "mixing/Preview.h"
#include "pipeline/FffProcessor.h"

namespace mixengine {

int runSliceCommand(const Words& args, std::ostream& out, std::ostream& err) {
    const auto start = std::chrono::steady_clock::now();
    ParsedSliceArgs parsed = parseSliceArguments(args);
    const SliceRequest& request = parsed.request;
    Log log(err, request.verbosity);
    log.setProgress(request.progress);
    const int threads = effectiveThreads(request.threads);

    Scene scene = prepareScene(request, log);
    std::optional<SidePreview> preview;  // --preview: the side view coloured by the mix
    PlanObserver observe;
    if (!parsed.preview_png.empty()) {
        preview.emplace(SidePreview::forSettings(scene.machine.global));
        observe = [&preview](const PrintPlan& plan) { preview->add(plan); };
    }
    GCodeOutput gcode = runPipeline(scene, threads, log, observe);
    const std::vector<std::string_view> text = gcode.pieces();
    if (request.output.empty()) {
        for (std::string_view piece : text)
            out << piece;
    } else {
        writeFileAtomically(request.output, text);
    }
    if (preview)
        writeFileAtomically(parsed.preview_png, preview->png());
    for (const std::string& note : gcode.notes)
        err << note << '\n';
    // after the slice: a bad value that makes formulas fail (layer_height 0) is its one error line instead
    for (const std::string& failure : scene.machine.formula_failures)  // "key: formula: problem"
        log.warning("formula fell back to default_value: " + failure);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    log.info("Total time elapsed " + std::to_string(seconds) + "s");
    log.info("Print time (s): " + std::to_string(static_cast<long long>(gcode.summary.print_time_s)));
    log.info("Layers: " + std::to_string(gcode.layer_chunks.size()));
    return 0;
}

}  // namespace mixengine
