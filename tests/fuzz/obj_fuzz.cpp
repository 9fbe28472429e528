// libFuzzer target: the Wavefront OBJ reader and mesh building.
#include "FuzzSupport.h"
#include "common/Error.h"
#include "mesh/formats/ObjReader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static mixengine::fuzz::MemoryFile file("fuzz.obj");
    std::vector<std::string> warnings;
    try {
        mixengine::fuzz::buildAll(mixengine::readObj(file.write(data, size), warnings));
    } catch (const mixengine::InputError&) {
    }
    return 0;
}
