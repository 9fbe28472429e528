#include "common/PngWriter.h"

#include <png.h>

#include <fstream>

#include "common/Error.h"

namespace mixengine {
namespace {

void appendToString(png_structp png, png_bytep data, png_size_t size) {
    auto* out = static_cast<std::string*>(png_get_io_ptr(png));
    out->append(reinterpret_cast<const char*>(data), size);
}

void flushNothing(png_structp) {}

/// libpng reports errors by longjmp; this function holds no C++ objects with destructors between
/// setjmp and the writes, so the jump is safe.
bool encodeRows(std::string& out, int width, int height, const std::uint8_t* rgb) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, &out, appendToString, flushNothing);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y)
        png_write_row(png, rgb + static_cast<std::size_t>(y) * static_cast<std::size_t>(width) * 3);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

std::string encodePng(int width, int height, const std::vector<std::uint8_t>& rgb) {
    if (width <= 0 || height <= 0 ||
        rgb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3)
        throw InternalError("encodePng: " + std::to_string(width) + "x" + std::to_string(height) +
                            " image with " + std::to_string(rgb.size()) + " bytes");
    std::string out;
    if (!encodeRows(out, width, height, rgb.data()))
        throw InternalError("encodePng: libpng failed");
    return out;
}

void writePng(const std::filesystem::path& path, int width, int height,
              const std::vector<std::uint8_t>& rgb) {
    const std::string bytes = encodePng(width, height, rgb);
    std::ofstream file(path, std::ios::binary);
    file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!file)
        throw InputError(path.string() + ": cannot write the PNG file");
}

}  // namespace mixengine
