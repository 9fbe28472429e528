// Image input (common/ImageReader.h): PNG written by common/PngWriter.h and hand-made BMP files
// read back pixel for pixel.
#include "common/ImageReader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/Error.h"
#include "common/PngWriter.h"

namespace mixengine {
namespace {

std::filesystem::path tempFile(const std::string& name, const std::string& bytes) {
    const std::filesystem::path path = std::filesystem::temp_directory_path() / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

std::string le(std::uint32_t value, int bytes) {
    std::string out;
    for (int i = 0; i < bytes; ++i)
        out.push_back(static_cast<char>((value >> (8 * i)) & 0xFF));
    return out;
}

/// A 24-bit BMP of 2 × 2 pixels, rows stored bottom-up and padded to 4 bytes.
std::string bmp2x2() {
    const std::string bottom =
        std::string("\x00\x00\xff", 3) + std::string("\xff\xff\xff", 3) + std::string(2, '\0');
    const std::string top =
        std::string("\xff\x00\x00", 3) + std::string("\x00\xff\x00", 3) + std::string(2, '\0');
    std::string file = "BM" + le(54 + 16, 4) + le(0, 4) + le(54, 4);
    file += le(40, 4) + le(2, 4) + le(2, 4) + le(1, 2) + le(24, 2) + le(0, 4) + le(16, 4);
    file += le(2835, 4) + le(2835, 4) + le(0, 4) + le(0, 4);
    return file + bottom + top;
}

TEST(ImageReader, PngReadsBackItsPixels) {
    const std::vector<std::uint8_t> rgb{10,  20,  30,  40,  50,  60,  70,  80,  90,
                                        100, 110, 120, 130, 140, 150, 160, 170, 180};
    const auto path = tempFile("mixengine_image_test.png", encodePng(3, 2, rgb));
    const DecodedImage image = readImage(path);
    std::filesystem::remove(path);
    EXPECT_EQ(image.width, 3);
    EXPECT_EQ(image.height, 2);
    EXPECT_EQ(image.channels, 3);
    EXPECT_EQ(image.samples, rgb);
}

TEST(ImageReader, BmpRowsFromTheTopInRgb) {
    const auto path = tempFile("mixengine_image_test.bmp", bmp2x2());
    const DecodedImage image = readImage(path);
    std::filesystem::remove(path);
    EXPECT_EQ(image.width, 2);
    EXPECT_EQ(image.height, 2);
    ASSERT_EQ(image.channels, 3);
    // top row: blue, green; bottom row: red, white (BMP stores BGR, bottom row first)
    const std::vector<std::uint8_t> expected{0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255};
    EXPECT_EQ(image.samples, expected);
}

TEST(ImageReader, OtherFilesAreInputErrors) {
    const auto text = tempFile("mixengine_image_test.txt", "not an image");
    EXPECT_THROW(readImage(text), InputError);
    std::filesystem::remove(text);
    const auto broken = tempFile("mixengine_image_test_broken.png", "\x89PNG\r\n\x1a\n garbage");
    EXPECT_THROW(readImage(broken), InputError);
    std::filesystem::remove(broken);
    EXPECT_THROW(readImage("/nonexistent/mixengine.png"), InputError);
}

}  // namespace
}  // namespace mixengine
