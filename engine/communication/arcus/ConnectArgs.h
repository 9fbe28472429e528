#pragma once
// The words after `mixengine connect`, as Cura gives them: `<host>[:<port>]`, then an empty
// argument, and `-vvv` when Cura runs with --debug. Like CuraEngine 4.13: -v… raises the
// verbosity, -m<n> sets the thread count, other flags are warned about and ignored, empty words
// are skipped, and the port defaults to 49674.
#include <string>
#include <vector>

namespace mixengine {

struct ConnectArgs {
    std::string host = "127.0.0.1";
    int port = 49674;
    int verbosity = 0;
    int threads = 0;  ///< 0 = all cores
    bool help = false;
    std::vector<std::string> ignored;  ///< unknown flags, to be warned about
};

/// Throws InputError naming the word that is not a valid address or port.
ConnectArgs parseConnectArguments(const std::vector<std::string>& words);

}  // namespace mixengine
