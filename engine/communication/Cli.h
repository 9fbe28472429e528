#pragma once
// The command line: `mixengine help | slice | settings | layers | demo`, CuraEngine 4.13 compatible
// for `slice`. Returns the process exit code; throws InputError for bad input (main prints it).
#include <ostream>

namespace mixengine {

int runCli(int argc, char** argv, std::ostream& out, std::ostream& err);

}  // namespace mixengine
