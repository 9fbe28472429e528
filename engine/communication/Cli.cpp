#include "communication/Cli.h"

#include "common/Error.h"
#include "communication/Commands.h"
#include "communication/HelpText.h"

namespace mixengine {

int runCli(int argc, char** argv, std::ostream& out, std::ostream& err) {
    Words words(argv + 1, argv + argc);
    if (words.empty()) {
        err << helpText();
        return 1;
    }
    const std::string command = words.front();
    words.erase(words.begin());
    if (command == "help" || command == "--help" || command == "-h") {
        out << helpText();
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
    throw InputError("unknown command '" + command +
                     "' (commands: help, slice, connect, layers, settings, demo, orient)");
}

}  // namespace mixengine
