#include "communication/Cli.h"

#include <algorithm>

#include "common/Error.h"
#include "communication/Commands.h"
#include "communication/HelpText.h"

namespace mixengine {
namespace {

bool asksForHelp(const Words& words) {
    return std::any_of(words.begin(), words.end(),
                       [](const std::string& w) { return w == "--help" || w == "-h"; });
}

int runHelp(const Words& words, std::ostream& out) {
    if (words.empty()) {
        out << helpText();
        return 0;
    }
    const std::optional<std::string> usage = commandHelp(words.front());
    if (!usage)
        throw InputError(
            "help: unknown command '" + words.front() +
            "' (commands: help, slice, connect, layers, settings, demo, orient, mix, calibrate-chamber)");
    out << *usage;
    return 0;
}

}  // namespace

int runCli(int argc, char** argv, std::ostream& out, std::ostream& err) {
    Words words(argv + 1, argv + argc);
    if (words.empty()) {
        err << helpText();
        return 1;
    }
    const std::string command = words.front();
    words.erase(words.begin());
    if (command == "help" || command == "--help" || command == "-h")
        return runHelp(words, out);
    // `<command> --help` anywhere on the line: the command's usage, nothing run, nothing written
    if (const std::optional<std::string> usage = commandHelp(command); usage && asksForHelp(words)) {
        out << *usage;
        return 0;
    }
    if (command == "slice")
        return runSliceCommand(words, out, err);
    if (command == "layers")
        return runLayersCommand(words, out, err);
    if (command == "settings")
        return runSettingsCommand(words, out, err);
    if (command == "demo")
        return runDemoCommand(words, out, err);
    if (command == "connect")
        return runConnectCommand(words, out, err);
    if (command == "orient")
        return runOrientCommand(words, out, err);
    if (command == "mix")
        return runMixCommand(words, out, err);
    if (command == "calibrate-chamber")
        return runCalibrateChamberCommand(words, out, err);
    throw InputError(
        "unknown command '" + command +
        "' (commands: help, slice, connect, layers, settings, demo, orient, mix, calibrate-chamber)");
}

}  // namespace mixengine
