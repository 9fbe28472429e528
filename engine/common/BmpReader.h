#pragma once
// Uncompressed BMP decoding for common/ImageReader.h (8-bit palette → RGB, 24 bits → RGB, 32 bits
// → RGBA; rows bottom-up or top-down as the header says).
#include <optional>
#include <string>

#include "common/ImageReader.h"

namespace mixengine {

/// The image in `bytes` (a whole BMP file), or nothing when it is damaged or of a kind not read here
/// (compressed, 1/4/16 bits).
std::optional<DecodedImage> decodeBmp(const std::string& bytes);

}  // namespace mixengine
