#pragma once
// Colour spaces and colour difference, through Little CMS 2 (Debian's liblcms2): sRGB ↔ CIELAB
// (D50, relative colorimetric, so sRGB white is L* 100, a* = b* = 0), XYZ (D50-relative, Y of the
// white = 1) → CIELAB, and the CIEDE2000 difference ΔE00 (kL = kC = kH = 1). No colour science is
// written here by hand: this file only owns the lcms profiles and transforms (no global state:
// every ColorSpace holds its own). Hex colours are "#rrggbb" (case-insensitive).
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace mixengine {

using Rgb = std::array<std::uint8_t, 3>;  ///< 8-bit sRGB

struct Lab {
    double L = 0, a = 0, b = 0;
};

struct Xyz {
    double X = 0, Y = 0, Z = 0;
};

class ColorSpace {
  public:
    ColorSpace();
    ~ColorSpace();
    ColorSpace(const ColorSpace&) = delete;
    ColorSpace& operator=(const ColorSpace&) = delete;

    Lab labOf(const Rgb& srgb) const;
    /// The nearest 8-bit sRGB colour (out-of-range channels are clipped).
    Rgb srgbOf(const Lab& lab) const;
    /// XYZ relative to the D50 white (the white's Y = 1) → CIELAB.
    static Lab labOfXyz(const Xyz& xyz_d50);
    /// The D50 white point (Y = 1), the reference white of labOfXyz.
    static Xyz whiteD50();

  private:
    struct Transforms;
    std::unique_ptr<Transforms> transforms_;
};

/// CIEDE2000 colour difference between two CIELAB colours.
double deltaE00(const Lab& x, const Lab& y);

/// "#ff8000" → {255, 128, 0}; throws InputError "<label>: '<text>' is not a colour like #ff8800"
/// when `text` (surrounding blanks aside) is not #rrggbb.
Rgb parseHexColor(std::string_view label, std::string_view text);

/// "#00ffff,#ff00ff" → its colours in order (parseHexColor on each comma-separated item).
std::vector<Rgb> parseHexColorList(std::string_view label, std::string_view text);

/// {255, 128, 0} → "#ff8000".
std::string hexOf(const Rgb& rgb);

}  // namespace mixengine
