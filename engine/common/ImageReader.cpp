#include "common/ImageReader.h"

#include <png.h>
// libjpeg's header needs FILE and size_t declared first
#include <jpeglib.h>
#include <cstdio>

#include <csetjmp>
#include <optional>
#include <string>

#include "common/BmpReader.h"
#include "common/Error.h"
#include "common/TextFile.h"

namespace mixengine {
namespace {

bool startsWith(const std::string& bytes, std::string_view magic) {
    return bytes.size() >= magic.size() && std::string_view(bytes).substr(0, magic.size()) == magic;
}

/// libpng's simplified reader: the file's channels at 8 bits, a palette expanded.
std::optional<DecodedImage> decodePng(const std::string& bytes) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (png_image_begin_read_from_memory(&png, bytes.data(), bytes.size()) == 0)
        return std::nullopt;
    png.format &= ~static_cast<png_uint_32>(PNG_FORMAT_FLAG_COLORMAP | PNG_FORMAT_FLAG_LINEAR);
    DecodedImage image{static_cast<int>(png.width),
                       static_cast<int>(png.height),
                       static_cast<int>(PNG_IMAGE_SAMPLE_CHANNELS(png.format)),
                       {}};
    image.samples.resize(PNG_IMAGE_SIZE(png));
    if (png_image_finish_read(&png, nullptr, image.samples.data(), 0, nullptr) == 0) {
        png_image_free(&png);
        return std::nullopt;
    }
    return image;
}

/// libjpeg reports errors by longjmp back here.
struct JpegErrors {
    jpeg_error_mgr manager;
    std::jmp_buf jump;
};

void jumpBack(j_common_ptr info) {
    std::longjmp(reinterpret_cast<JpegErrors*>(info->err)->jump, 1);
}

/// Holds no C++ objects with destructors between setjmp and the libjpeg calls (`image` is the
/// caller's), so the jump is safe.
bool decodeJpegInto(const std::string& bytes, DecodedImage& image) {
    jpeg_decompress_struct info{};
    JpegErrors errors{};
    info.err = jpeg_std_error(&errors.manager);
    errors.manager.error_exit = jumpBack;
    if (setjmp(errors.jump)) {
        jpeg_destroy_decompress(&info);
        return false;
    }
    jpeg_create_decompress(&info);
    jpeg_mem_src(&info, reinterpret_cast<const unsigned char*>(bytes.data()),
                 static_cast<unsigned long>(bytes.size()));
    jpeg_read_header(&info, TRUE);
    jpeg_start_decompress(&info);
    image.width = static_cast<int>(info.output_width);
    image.height = static_cast<int>(info.output_height);
    image.channels = info.output_components;
    const std::size_t row = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.channels);
    image.samples.resize(row * static_cast<std::size_t>(image.height));
    while (info.output_scanline < info.output_height) {
        JSAMPROW line = image.samples.data() + row * info.output_scanline;
        jpeg_read_scanlines(&info, &line, 1);
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    return true;
}

std::optional<DecodedImage> decodeJpeg(const std::string& bytes) {
    DecodedImage image;
    if (!decodeJpegInto(bytes, image))
        return std::nullopt;
    return image;
}

}  // namespace

DecodedImage readImage(const std::filesystem::path& path) {
    const std::string bytes = readTextFile(path);
    std::optional<DecodedImage> image;
    if (startsWith(bytes, "\x89PNG"))
        image = decodePng(bytes);
    else if (startsWith(bytes, "\xFF\xD8"))
        image = decodeJpeg(bytes);
    else if (startsWith(bytes, "BM"))
        image = decodeBmp(bytes);
    else
        throw InputError(path.string() + ": not a PNG, JPEG or BMP image");
    if (!image || image->width <= 0 || image->height <= 0 || image->channels < 1)
        throw InputError(path.string() + ": cannot decode the image");
    return *image;
}

}  // namespace mixengine
