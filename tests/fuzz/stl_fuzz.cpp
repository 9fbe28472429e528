// libFuzzer target: the STL reader (binary/ASCII detection, both parsers) and mesh building.
#include "FuzzSupport.h"
#include "common/Error.h"
#include "mesh/formats/StlReader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static mixengine::fuzz::MemoryFile file("fuzz.stl");
    std::vector<std::string> warnings;
    try {
        std::vector<mixengine::TriangleSoup> soups;
        soups.push_back(mixengine::readStl(file.write(data, size), warnings));
        mixengine::fuzz::buildAll(soups);
    } catch (const mixengine::InputError&) {
    }
    return 0;
}
