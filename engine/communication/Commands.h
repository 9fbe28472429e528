#pragma once
// The sub-commands of the mixengine binary. Each takes the words after its name and returns the
// exit code; bad input is thrown as InputError.
#include <ostream>
#include <string>
#include <vector>

namespace mixengine {

using Words = std::vector<std::string>;

int runSliceCommand(const Words& args, std::ostream& out, std::ostream& err);
int runLayersCommand(const Words& args, std::ostream& out, std::ostream& err);
int runSettingsCommand(const Words& args, std::ostream& out, std::ostream& err);
int runDemoCommand(const Words& args, std::ostream& out, std::ostream& err);
int runConnectCommand(const Words& args, std::ostream& out, std::ostream& err);
int runOrientCommand(const Words& args, std::ostream& out, std::ostream& err);
int runMixCommand(const Words& args, std::ostream& out, std::ostream& err);
int runCalibrateChamberCommand(const Words& args, std::ostream& out, std::ostream& err);

}  // namespace mixengine
