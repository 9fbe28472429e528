// `mixengine settings`: prints the resolved values of the global scope and of every extruder.
#include <nlohmann/json.hpp>

#include "common/Error.h"
#include "communication/CommandLineParser.h"
#include "communication/Commands.h"
#include "pipeline/Scene.h"

namespace mixengine {
namespace {

void printText(const Settings& settings, std::ostream& out) {
    out << "[" << settings.scope() << "]\n";
    for (const auto& [key, value] : settings.all()) {
        std::string shown = value;
        for (std::size_t p = shown.find('\n'); p != std::string::npos; p = shown.find('\n', p + 2))
            shown.replace(p, 1, "\\n");
        out << key << " = " << shown << '\n';
    }
}

}  // namespace

int runSettingsCommand(const Words& args, std::ostream& out, std::ostream& err) {
    bool json_output = false;
    Words slice_args;
    for (const std::string& word : args) {
        if (word == "--json") {
            json_output = true;
        } else {
            slice_args.push_back(word);
        }
    }
    const Scene scene = prepareSettings(parseSliceArguments(slice_args).request);
    for (const std::string& failure : scene.machine.formula_failures) {
        err << "[warning] formula fell back to default_value: " << failure << '\n';
    }
    if (json_output) {
        nlohmann::json doc;
        doc["machine"] = scene.definitions.machine_id;
        doc["global"] = scene.machine.global.all();
        for (const Settings& extruder : scene.machine.extruders)
            doc["extruders"].push_back(extruder.all());
        out << doc.dump(1) << '\n';
        return 0;
    }
    out << "machine: " << scene.definitions.machine_id << '\n';
    printText(scene.machine.global, out);
    for (const Settings& extruder : scene.machine.extruders)
        printText(extruder, out);
    return 0;
}

}  // namespace mixengine
