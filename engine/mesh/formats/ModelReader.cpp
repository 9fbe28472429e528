#include "mesh/formats/ModelReader.h"

#include "common/Error.h"
#include "mesh/formats/ObjReader.h"
#include "mesh/formats/StlReader.h"
#include "mesh/formats/TextScan.h"
#include "mesh/formats/ThreeMfReader.h"

namespace mixengine {

std::vector<TriangleSoup> readModelFile(const std::filesystem::path& file,
                                        std::vector<std::string>& warnings) {
    const std::string extension = file.extension().string();
    if (sameWord(extension, ".stl")) {
        std::vector<TriangleSoup> parts;
        parts.push_back(readStl(file, warnings));  // moved: a braced list would copy the triangles
        return parts;
    }
    if (sameWord(extension, ".obj")) {
        return readObj(file, warnings);
    }
    if (sameWord(extension, ".3mf")) {
        return readThreeMf(file, warnings);
    }
    const std::string shown = extension.empty() ? "(no extension)" : "'" + extension + "'";
    throw InputError(file.string() + ": unsupported model file type " + shown +
                     "; expected .stl, .obj or .3mf");
}

}  // namespace mixengine
