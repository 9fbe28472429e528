#pragma once
// Internal to StlReader: the two STL encodings. `label` names the file in messages; both readers
// append to soup.triangles, add warnings prefixed with the label and throw InputError on defects.
#include <string>
#include <string_view>
#include <vector>

#include "mesh/formats/ModelReader.h"

namespace mixengine {

constexpr std::size_t kStlHeaderBytes = 84;  ///< 80-byte header + uint32 triangle count
constexpr std::size_t kStlRecordBytes = 50;  ///< normal, 3 vertices (12 floats) + uint16 attribute

/// True when the size is exactly 84 + 50 * (the header's triangle count).
bool binaryStlSizeMatches(std::string_view bytes);

/// The bytes without a leading UTF-8 byte-order mark and trailing NUL / Ctrl-Z padding, which
/// some old exporters leave after ASCII STL text.
std::string_view asciiStlText(std::string_view bytes);

/// True when `text` (see asciiStlText) starts with "solid" (any case, after blanks) and holds no
/// binary bytes.
bool looksLikeAsciiStl(std::string_view text);

void readBinaryStl(std::string_view label, std::string_view bytes, TriangleSoup& soup,
                   std::vector<std::string>& warnings);

void readAsciiStl(std::string_view label, std::string_view text, TriangleSoup& soup,
                  std::vector<std::string>& warnings);

}  // namespace mixengine
