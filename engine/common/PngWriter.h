#pragma once
// Minimal PNG output (libpng): 8-bit RGB pixels, rows top to bottom, no alpha.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace mixengine {

/// The bytes of a PNG file for `rgb` (width × height × 3 bytes, row-major from the top row).
/// Throws InternalError when the sizes do not match or libpng fails.
std::string encodePng(int width, int height, const std::vector<std::uint8_t>& rgb);

/// Writes encodePng(...) to `path` directly (callers wanting atomic output write the bytes of
/// encodePng() through their own atomic writer). Throws InputError naming the path.
void writePng(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgb);

}  // namespace mixengine
