#include "communication/Cli.h"

namespace mixengine {

int runCli(int, char**, std::ostream& out, std::ostream&) {
    out << "mixengine (skeleton)\n";
    return 0;
}

}  // namespace mixengine
