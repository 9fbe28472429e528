#pragma once
// Minimal image input: PNG (libpng), JPEG (libjpeg) and uncompressed BMP (8-bit palette, 24 and
// 32 bits), decoded to 8-bit samples with the file's own channels, as stb_image (which CuraEngine
// uses) gives them: grey, grey + alpha, RGB or RGBA (a palette becomes RGB, or RGBA when it has
// transparency; 16-bit samples keep their high byte; a 32-bit BMP whose alpha is all 0 reads as
// opaque).
#include <cstdint>
#include <filesystem>
#include <vector>

namespace mixengine {

struct DecodedImage {
    int width = 0;
    int height = 0;
    int channels = 0;                   ///< samples per pixel, 1..4
    std::vector<std::uint8_t> samples;  ///< row-major from the top row, `channels` per pixel
};

/// The image in `path`, recognised by its first bytes. Throws InputError naming the path when the
/// file cannot be read, is of another kind or is damaged.
DecodedImage readImage(const std::filesystem::path& path);

}  // namespace mixengine
