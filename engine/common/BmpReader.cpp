#include "common/BmpReader.h"

#include <algorithm>
#include <cstdlib>

namespace mixengine {
namespace {

std::uint32_t le(const std::string& bytes, std::size_t at, int size) {
    std::uint32_t value = 0;
    for (int i = size - 1; i >= 0; --i)
        value = (value << 8) | static_cast<std::uint8_t>(bytes[at + static_cast<std::size_t>(i)]);
    return value;
}

struct BmpHeader {
    std::size_t pixels_at = 0, palette_at = 0;
    int width = 0, height = 0, bits = 0;
    bool top_down = false;
};

std::optional<BmpHeader> headerOf(const std::string& bytes) {
    if (bytes.size() < 54 || bytes[0] != 'B' || bytes[1] != 'M')
        return std::nullopt;
    BmpHeader h;
    h.pixels_at = le(bytes, 10, 4);
    h.palette_at = 14 + le(bytes, 14, 4);
    h.width = static_cast<int>(le(bytes, 18, 4));
    const auto height = static_cast<std::int32_t>(le(bytes, 22, 4));
    h.top_down = height < 0;
    h.height = std::abs(height);
    h.bits = static_cast<int>(le(bytes, 28, 2));
    const std::uint32_t compression = le(bytes, 30, 4);
    const bool plain = compression == 0 || (compression == 3 && h.bits == 32);  // 3: bit fields
    if (!plain || (h.bits != 8 && h.bits != 24 && h.bits != 32) || h.width <= 0 || h.height <= 0 ||
        h.width > 1 << 15 || h.height > 1 << 15)
        return std::nullopt;
    const std::size_t row =
        (static_cast<std::size_t>(h.width) * static_cast<std::size_t>(h.bits) / 8 + 3) / 4 * 4;
    if (h.pixels_at + row * static_cast<std::size_t>(h.height) > bytes.size() ||
        (h.bits == 8 && h.palette_at >= h.pixels_at))  // 8 bits need the palette before the pixels
        return std::nullopt;
    return h;
}

/// One pixel's samples (RGB or RGBA) from its stored bytes (BGR(A) or a palette index).
void appendPixel(const std::string& bytes, const BmpHeader& h, std::size_t at,
                 std::vector<std::uint8_t>& out) {
    std::size_t bgr = at;
    if (h.bits == 8)
        bgr = h.palette_at + 4 * static_cast<std::uint8_t>(bytes[at]);
    if (bgr + 3 > bytes.size()) {
        out.insert(out.end(), {0, 0, 0});
    } else {
        for (const int c : {2, 1, 0})
            out.push_back(static_cast<std::uint8_t>(bytes[bgr + static_cast<std::size_t>(c)]));
    }
    if (h.bits == 32)
        out.push_back(static_cast<std::uint8_t>(bytes[at + 3]));
}

}  // namespace

std::optional<DecodedImage> decodeBmp(const std::string& bytes) {
    const std::optional<BmpHeader> header = headerOf(bytes);
    if (!header)
        return std::nullopt;
    const BmpHeader& h = *header;
    DecodedImage image{h.width, h.height, h.bits == 32 ? 4 : 3, {}};
    image.samples.reserve(static_cast<std::size_t>(h.width) * static_cast<std::size_t>(h.height) * 4);
    const std::size_t step = static_cast<std::size_t>(h.bits) / 8;
    const std::size_t row = (static_cast<std::size_t>(h.width) * step + 3) / 4 * 4;
    for (int y = 0; y < h.height; ++y) {
        const auto stored = static_cast<std::size_t>(h.top_down ? y : h.height - 1 - y);
        for (int x = 0; x < h.width; ++x)
            appendPixel(bytes, h, h.pixels_at + stored * row + static_cast<std::size_t>(x) * step,
                        image.samples);
    }
    if (image.channels == 4) {
        bool all_clear = true;
        for (std::size_t i = 3; i < image.samples.size() && all_clear; i += 4)
            all_clear = image.samples[i] == 0;
        for (std::size_t i = 3; all_clear && i < image.samples.size(); i += 4)
            image.samples[i] = 255;  // as stb_image: an alpha channel that is all 0 is not used
    }
    return image;
}

}  // namespace mixengine
