#include "mixing/color/ColorSpace.h"

#include <lcms2.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "common/Error.h"

namespace mixengine {

struct ColorSpace::Transforms {
    cmsHTRANSFORM to_lab = nullptr;
    cmsHTRANSFORM to_srgb = nullptr;
    ~Transforms() {
        if (to_lab)
            cmsDeleteTransform(to_lab);
        if (to_srgb)
            cmsDeleteTransform(to_srgb);
    }
};

ColorSpace::ColorSpace() : transforms_(std::make_unique<Transforms>()) {
    cmsHPROFILE srgb = cmsCreate_sRGBProfile();
    cmsHPROFILE lab = cmsCreateLab4Profile(nullptr);  // D50
    if (srgb && lab) {
        transforms_->to_lab =
            cmsCreateTransform(srgb, TYPE_RGB_8, lab, TYPE_Lab_DBL, INTENT_RELATIVE_COLORIMETRIC, 0);
        transforms_->to_srgb =
            cmsCreateTransform(lab, TYPE_Lab_DBL, srgb, TYPE_RGB_8, INTENT_RELATIVE_COLORIMETRIC, 0);
    }
    if (srgb)
        cmsCloseProfile(srgb);
    if (lab)
        cmsCloseProfile(lab);
    if (!transforms_->to_lab || !transforms_->to_srgb)
        throw InternalError("Little CMS: cannot create the sRGB <-> CIELAB transforms");
}

ColorSpace::~ColorSpace() = default;

Lab ColorSpace::labOf(const Rgb& srgb) const {
    cmsCIELab lab{};
    cmsDoTransform(transforms_->to_lab, srgb.data(), &lab, 1);
    return {lab.L, lab.a, lab.b};
}

Rgb ColorSpace::srgbOf(const Lab& lab) const {
    const cmsCIELab in{lab.L, lab.a, lab.b};
    Rgb out{};
    cmsDoTransform(transforms_->to_srgb, &in, out.data(), 1);
    return out;
}

Lab ColorSpace::labOfXyz(const Xyz& xyz_d50) {
    const cmsCIEXYZ in{xyz_d50.X, xyz_d50.Y, xyz_d50.Z};
    cmsCIELab lab{};
    cmsXYZ2Lab(cmsD50_XYZ(), &lab, &in);
    return {lab.L, lab.a, lab.b};
}

Xyz ColorSpace::whiteD50() {
    const cmsCIEXYZ* white = cmsD50_XYZ();
    return {white->X, white->Y, white->Z};
}

double deltaE00(const Lab& x, const Lab& y) {
    const cmsCIELab a{x.L, x.a, x.b};
    const cmsCIELab b{y.L, y.a, y.b};
    return cmsCIE2000DeltaE(&a, &b, 1.0, 1.0, 1.0);
}

Rgb parseHexColor(std::string_view label, std::string_view text) {
    const auto first = text.find_first_not_of(" \t");
    const auto last = text.find_last_not_of(" \t");
    const std::string_view hex = first == std::string_view::npos ? "" : text.substr(first, last - first + 1);
    const bool ok = hex.size() == 7 && hex[0] == '#' &&
                    std::all_of(hex.begin() + 1, hex.end(), [](char c) { return std::isxdigit(c) != 0; });
    if (!ok)
        throw InputError(std::string(label) + ": '" + std::string(hex) + "' is not a colour like #ff8800");
    Rgb rgb{};
    for (std::size_t k = 0; k < 3; ++k)
        rgb[k] = static_cast<std::uint8_t>(std::stoi(std::string(hex.substr(1 + 2 * k, 2)), nullptr, 16));
    return rgb;
}

std::string hexOf(const Rgb& rgb) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
    return text;
}

std::vector<Rgb> parseHexColorList(std::string_view label, std::string_view text) {
    std::vector<Rgb> colors;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t comma = text.find(',', start);
        if (comma == std::string_view::npos)
            comma = text.size();
        colors.push_back(parseHexColor(label, text.substr(start, comma - start)));
        start = comma + 1;
    }
    return colors;
}

}  // namespace mixengine
