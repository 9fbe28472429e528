// mixengine — entry point. Turns typed errors into one line on stderr and an exit code.
#include <iostream>

#include "common/Error.h"
#include "communication/Cli.h"

int main(int argc, char** argv) {
    try {
        return mixengine::runCli(argc, argv, std::cout, std::cerr);
    } catch (const mixengine::InputError& e) {
        std::cerr << "mixengine: error: " << e.what() << '\n';
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "mixengine: internal error: " << e.what() << '\n';
        return 2;
    }
}
