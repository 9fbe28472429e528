#include "mesh/formats/StlReader.h"

#include "common/Error.h"
#include "mesh/formats/FileBytes.h"
#include "mesh/formats/StlFormats.h"

namespace mixengine {

TriangleSoup readStl(const std::filesystem::path& file, std::vector<std::string>& warnings) {
    const std::string label = file.string();
    const FileBytes bytes = FileBytes::read(file);
    if (bytes.size() == 0) {
        throw InputError(label + ": empty file");
    }
    TriangleSoup soup;
    soup.name = file.stem().string();
    const std::string_view text = asciiStlText(bytes.view());
    if (!binaryStlSizeMatches(bytes.view()) && looksLikeAsciiStl(text)) {
        readAsciiStl(label, text, soup, warnings);
    } else {
        readBinaryStl(label, bytes.view(), soup, warnings);
    }
    if (soup.triangles.empty()) {
        throw InputError(label + ": contains no triangles");
    }
    return soup;
}

}  // namespace mixengine
