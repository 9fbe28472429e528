#include "toolpaths/infill/cross/DensityImage.h"

#include <algorithm>
#include <fstream>
#include <memory>

#include "common/Error.h"

namespace mixengine {
namespace {

/// The image's pixels and where it lies in microns.
struct PlacedImage {
    DecodedImage image;
    Box2 print{0, 0, 0, 0};

    long long pixelSum(coord_um x, coord_um y) const {
        // as CuraEngine (stb_image): row 0 is the top row, laid at the largest y
        const auto row = static_cast<std::size_t>(image.height - 1 - y);
        const std::size_t at = (row * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)) *
                               static_cast<std::size_t>(image.channels);
        long long sum = 0;
        for (int c = 0; c < image.channels; ++c)
            sum += image.samples[at + static_cast<std::size_t>(c)];
        return sum;
    }

    float densityAt(const Box2& box) const;
};

float PlacedImage::densityAt(const Box2& box) const {
    const coord_um w = image.width, h = image.height;
    const coord_um span_x = std::max<coord_um>(print.right - print.left, 1);
    const coord_um span_y = std::max<coord_um>(print.bottom - print.top, 1);
    // As CuraEngine: both corners' x and y scaled, the lower by the width, the upper by the height.
    const Point2 low{(box.left - print.left - 1) * w / span_x, (box.top - print.top - 1) * w / span_x};
    const Point2 high{(box.right - print.left + 1) * h / span_y, (box.bottom - print.top + 1) * h / span_y};
    long long total = 0, count = 0;
    for (coord_um x = std::max<coord_um>(0, low.X); x <= std::min(w - 1, high.X); ++x) {
        for (coord_um y = std::max<coord_um>(0, low.Y); y <= std::min(h - 1, high.Y); ++y) {
            total += pixelSum(x, y);
            count += image.channels;
        }
    }
    if (count == 0) {  // between pixels or outside: the nearest one
        const coord_um x = std::clamp<coord_um>((low.X + high.X) / 2, 0, w - 1);
        const coord_um y = std::clamp<coord_um>((low.Y + high.Y) / 2, 0, h - 1);
        total = pixelSum(x, y);
        count = image.channels;
    }
    return 1.0f - float(total) / float(count) / 255.0f;
}

Box2 printBox(const DecodedImage& image, const Box2& model) {
    const coord_um model_x = model.right - model.left, model_y = model.bottom - model.top;
    const float model_aspect = float(model_x) / float(model_y);
    const float image_aspect = float(image.width) / float(image.height);
    Point2 size{0, 0};
    if (image_aspect < model_aspect)
        size = {coord_um(image.width) * model_x / image.width,
                coord_um(image.height) * model_x / image.width};
    else
        size = {coord_um(image.width) * model_y / image.height,
                coord_um(image.height) * model_y / image.height};
    const Point2 middle{(model.left + model.right) / 2, (model.top + model.bottom) / 2};
    return {middle.X - size.X / 2, middle.Y - size.Y / 2, middle.X + size.X / 2, middle.Y + size.Y / 2};
}

bool blank(const std::string& text) {
    return std::all_of(text.begin(), text.end(), [](char c) { return c == ' '; });
}

}  // namespace

DensityAt imageDensity(DecodedImage image, const Box2& model_box) {
    auto placed = std::make_shared<PlacedImage>();
    placed->print = printBox(image, model_box);
    placed->image = std::move(image);
    return [placed](const Box2& box) { return placed->densityAt(box); };
}

DensityAt densityImageAt(const std::string& file, const Box2& model_box, const std::string& key) {
    if (blank(file) || !std::ifstream(file).good())
        return nullptr;
    try {
        return imageDensity(readImage(file), model_box);
    } catch (const InputError& e) {
        throw InputError("setting '" + key + "': " + e.what());
    }
}

bool wantsCrossFill(const std::string& pattern, coord_um line_distance_um, coord_um line_width_um) {
    return (pattern == "cross" || pattern == "cross_3d") && line_distance_um > 0 && line_width_um > 0;
}

}  // namespace mixengine
