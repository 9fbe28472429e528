#include "orient/VMapPng.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "common/Error.h"
#include "common/PngWriter.h"
#include "geometry/Angles.h"

namespace mixengine::orient {
namespace {

struct Rgb {
    unsigned char r = 255, g = 255, b = 255;
};

/// A raster with a 3×5 pixel font for labels.
class Canvas {
  public:
    Canvas(int width, int height) : width_(width), height_(height), pixels_(width * height) {}
    void set(int x, int y, Rgb c) {
        if (x >= 0 && y >= 0 && x < width_ && y < height_)
            pixels_[y * width_ + x] = c;
    }
    void fill(int x0, int y0, int w, int h, Rgb c) {
        for (int y = y0; y < y0 + h; ++y) {
            for (int x = x0; x < x0 + w; ++x)
                set(x, y, c);
        }
    }
    /// Text with its top-left corner at (x, y), each font pixel `scale` pixels wide.
    void text(int x, int y, const std::string& s, int scale, Rgb c);
    int width() const { return width_; }
    int height() const { return height_; }
    /// Row-major RGB bytes from the top row, as common/PngWriter takes them.
    std::vector<std::uint8_t> bytes() const {
        std::vector<std::uint8_t> out;
        out.reserve(pixels_.size() * 3);
        for (const Rgb& p : pixels_)
            out.insert(out.end(), {p.r, p.g, p.b});
        return out;
    }

  private:
    int width_, height_;
    std::vector<Rgb> pixels_;
};

/// 3×5 glyphs, one row per 3-bit number (top row first).
struct Glyph {
    char c;
    std::array<int, 5> rows;
};
constexpr Glyph kGlyphs[] = {
    {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}}, {'3', {7, 1, 3, 1, 7}},
    {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}}, {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 2, 2}},
    {'8', {7, 5, 7, 5, 7}}, {'9', {7, 5, 7, 1, 7}}, {'.', {0, 0, 0, 0, 2}}, {'-', {0, 0, 7, 0, 0}},
    {'A', {2, 5, 7, 5, 5}}, {'L', {4, 4, 4, 4, 7}}, {'T', {7, 2, 2, 2, 2}}, {'O', {7, 5, 5, 5, 7}},
    {'N', {6, 5, 5, 5, 5}}, {'V', {5, 5, 5, 5, 2}}, {'M', {5, 7, 7, 5, 5}}, {'E', {7, 4, 6, 4, 7}},
    {'X', {5, 5, 2, 5, 5}}, {'I', {7, 2, 2, 2, 7}}, {'C', {7, 4, 4, 4, 7}}, {' ', {0, 0, 0, 0, 0}}};

const Glyph* glyphOf(char c) {
    for (const Glyph& g : kGlyphs) {
        if (g.c == c)
            return &g;
    }
    return nullptr;
}

void Canvas::text(int x, int y, const std::string& s, int scale, Rgb c) {
    for (const char ch : s) {
        if (const Glyph* glyph = glyphOf(ch)) {
            for (int r = 0; r < 5; ++r) {
                for (int b = 0; b < 3; ++b) {
                    if (glyph->rows[r] & (4 >> b))
                        fill(x + b * scale, y + r * scale, scale, scale, c);
                }
            }
        }
        x += 4 * scale;
    }
}

/// A perceptual blue → green → yellow ramp (t in 0..1).
Rgb colour(double t) {
    static const std::array<std::array<double, 3>, 5> stops = {
        {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}}};
    t = std::clamp(t, 0.0, 1.0) * (stops.size() - 1);
    const auto i = std::min<std::size_t>(static_cast<std::size_t>(t), stops.size() - 2);
    const double f = t - static_cast<double>(i);
    auto mix = [&](int k) {
        return static_cast<unsigned char>(std::lround(stops[i][k] * (1 - f) + stops[i + 1][k] * f));
    };
    return {mix(0), mix(1), mix(2)};
}

std::string formatValue(double v) {
    char text[32];
    std::snprintf(text, sizeof text, v >= 100 ? "%.0f" : "%.1f", v);
    return text;
}

}  // namespace

std::string renderVMapPng(const VMap& map, const LatLon& chosen) {
    const int cell = std::max(1, 540 / std::max(1, map.columns));
    const int plot_w = cell * map.columns, plot_h = cell * map.rows;
    const int left = 48, top = 28, bottom = 40, bar = 24;
    Canvas canvas(left + plot_w + 24 + bar + 80, top + plot_h + bottom);
    const auto [lo_it, hi_it] = std::minmax_element(map.values.begin(), map.values.end());
    const double lo = map.values.empty() ? 0 : *lo_it, hi = map.values.empty() ? 1 : *hi_it;
    const double span = hi > lo ? hi - lo : 1.0;
    for (int r = 0; r < map.rows; ++r) {
        for (int c = 0; c < map.columns; ++c) {
            const double t = (map.values[r * map.columns + c] - lo) / span;
            canvas.fill(left + c * cell, top + plot_h - (r + 1) * cell, cell, cell, colour(t));
        }
    }
    const Rgb black{0, 0, 0}, white{255, 255, 255};
    const double px_per_deg = plot_w / 360.0;
    for (int deg = 0; deg <= 360; deg += 90) {  // ticks and labels on both axes
        const int x = left + static_cast<int>(std::lround(deg * px_per_deg));
        const int y = top + plot_h - static_cast<int>(std::lround(deg * px_per_deg * plot_h / plot_w));
        canvas.fill(x, top + plot_h, 1, 6, black);
        canvas.text(x - 6, top + plot_h + 9, std::to_string(deg), 2, black);
        canvas.fill(left - 6, y, 6, 1, black);
        canvas.text(4, y - 5, std::to_string(deg), 2, black);
    }
    canvas.text(left + plot_w / 2 - 12, top + plot_h + 24, "LON", 2, black);
    canvas.text(4, 8, "LAT", 2, black);
    canvas.text(left + plot_w / 2 - 60, 8, map.exact ? "V EXACT MM3" : "V MM3", 2, black);
    const int bar_x = left + plot_w + 24;
    for (int y = 0; y < plot_h; ++y)
        canvas.fill(bar_x, top + y, bar, 1, colour(1.0 - static_cast<double>(y) / std::max(1, plot_h - 1)));
    canvas.text(bar_x + bar + 4, top, formatValue(hi), 2, black);
    canvas.text(bar_x + bar + 4, top + plot_h - 10, formatValue(lo), 2, black);
    const int cx =
        left + static_cast<int>(std::lround((chosen.longitude_deg + map.step_deg / 2) * px_per_deg));
    const int cy = top + plot_h -
                   static_cast<int>(std::lround((chosen.latitude_deg + map.step_deg / 2) * plot_h / 360.0));
    for (int a = 0; a < 360; ++a) {  // ring of radius 8 px, white with a black outline
        for (const auto& [radius, c] :
             {std::pair{9.0, black}, std::pair{8.0, white}, std::pair{7.0, white}}) {
            canvas.set(cx + static_cast<int>(std::lround(radius * std::cos(radiansFromDegrees(a)))),
                       cy + static_cast<int>(std::lround(radius * std::sin(radiansFromDegrees(a)))), c);
        }
    }
    return encodePng(canvas.width(), canvas.height(), canvas.bytes());
}

}  // namespace mixengine::orient
