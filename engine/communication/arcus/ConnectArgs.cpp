#include "communication/arcus/ConnectArgs.h"

#include <charconv>

#include "common/Error.h"

namespace mixengine {
namespace {

/// `text` as an integer in [low, high]; otherwise InputError naming `word` and `what` it should be.
int parseBounded(const std::string& text, int low, int high, const std::string& word,
                 const std::string& what) {
    int value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || value < low || value > high)
        throw InputError("connect: '" + word + "' is not " + what);
    return value;
}

bool isVerbosityFlag(const std::string& word) {
    return word.size() >= 2 && word.find_first_not_of('v', 1) == std::string::npos;
}

}  // namespace

ConnectArgs parseConnectArguments(const std::vector<std::string>& words) {
    ConnectArgs args;
    bool have_address = false;
    for (const std::string& word : words) {
        if (word.empty())
            continue;  // Cura passes a trailing ""
        if (word == "--help" || word == "-h") {
            args.help = true;
        } else if (word[0] == '-' && isVerbosityFlag(word)) {
            args.verbosity += static_cast<int>(word.size()) - 1;
        } else if (word.rfind("-m", 0) == 0 && word.size() > 2) {
            args.threads = parseBounded(word.substr(2), 1, 1024, word, "-m<threads> with 1 to 1024 threads");
        } else if (word[0] == '-') {
            args.ignored.push_back(word);
        } else if (!have_address) {
            const auto colon = word.rfind(':');
            args.host = colon == std::string::npos ? word : word.substr(0, colon);
            if (colon != std::string::npos)
                args.port = parseBounded(word.substr(colon + 1), 1, 65535, word,
                                         "<host>:<port> with a port from 1 to 65535");
            if (args.host.empty())
                throw InputError("connect: '" + word + "' names no host");
            have_address = true;
        } else {
            args.ignored.push_back(word);
        }
    }
    if (!have_address && !args.help)
        throw InputError("connect: missing <host>[:<port>] (Cura passes e.g. 127.0.0.1:49674)");
    return args;
}

}  // namespace mixengine
