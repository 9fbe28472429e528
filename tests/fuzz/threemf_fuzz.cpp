// libFuzzer target: the 3MF reader (our use of lib3mf: build items, components, transforms, units)
// and mesh building. lib3mf itself is Debian's uninstrumented library; a crash inside it still
// stops the run.
#include "FuzzSupport.h"
#include "common/Error.h"
#include "mesh/formats/ThreeMfReader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static mixengine::fuzz::MemoryFile file("fuzz.3mf");
    std::vector<std::string> warnings;
    try {
        mixengine::fuzz::buildAll(mixengine::readThreeMf(file.write(data, size), warnings));
    } catch (const mixengine::InputError&) {
    }
    return 0;
}
