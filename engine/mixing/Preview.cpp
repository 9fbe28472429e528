#include "mixing/Preview.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/PngWriter.h"

namespace mixengine {
namespace {

double toLinear(std::uint8_t c) {
    const double v = c / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

std::uint8_t toSrgb(double v) {
    v = std::clamp(v, 0.0, 1.0);
    const double s = v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    return static_cast<std::uint8_t>(std::lround(s * 255.0));
}

constexpr Rgb kBackground{230, 230, 230};
constexpr int kMarginPx = 10;

/// Pixel canvas with a depth buffer (smaller depth = nearer to the viewer).
struct Canvas {
    int width, height;
    std::vector<std::uint8_t> rgb;
    std::vector<float> depth;

    Canvas(int w, int h)
        : width(w),
          height(h),
          rgb(static_cast<std::size_t>(w * h) * 3),
          depth(static_cast<std::size_t>(w * h), std::numeric_limits<float>::max()) {
        for (std::size_t i = 0; i < rgb.size(); i += 3)
            std::copy(kBackground.begin(), kBackground.end(), rgb.begin() + static_cast<std::ptrdiff_t>(i));
    }
    void plot(int x, int y, float d, const Rgb& color, double shade) {
        const std::size_t i = static_cast<std::size_t>(y * width + x);
        if (d >= depth[i])
            return;
        depth[i] = d;
        for (std::size_t k = 0; k < 3; ++k)
            rgb[i * 3 + k] = static_cast<std::uint8_t>(std::lround(color[k] * shade));
    }
};

}  // namespace

Rgb mixColor(const MixVector& mix, const std::vector<Rgb>& channel_colors) {
    std::array<double, 3> linear{};
    const double sum = mix.sum() > 0 ? mix.sum() : 1.0;
    const int channels = std::min<int>(mix.channels, static_cast<int>(channel_colors.size()));
    for (int c = 0; c < channels; ++c) {
        for (std::size_t k = 0; k < 3; ++k)
            linear[k] += mix[c] / sum * toLinear(channel_colors[static_cast<std::size_t>(c)][k]);
    }
    return {toSrgb(linear[0]), toSrgb(linear[1]), toSrgb(linear[2])};
}

SidePreview::SidePreview(std::vector<Rgb> channel_colors, int max_size_px)
    : colors_(std::move(channel_colors)), max_size_px_(max_size_px) {}

SidePreview::SidePreview(std::shared_ptr<const PigmentModel> pigments, std::vector<Rgb> channel_colors,
                         int max_size_px)
    : colors_(std::move(channel_colors)), pigments_(std::move(pigments)), max_size_px_(max_size_px) {}

SidePreview SidePreview::forSettings(const Settings& global) {
    const MixingOutput output = parseMixingOutput(global);
    std::vector<Rgb> colors = parseChannelColors(global, output.enabled() ? output.channels : 1);
    const bool gradient_colors = output.mode == MixingMode::Gradient &&
                                 global.text(key::mixing_gradient_colors).find('#') != std::string::npos;
    if (output.mode == MixingMode::Color || gradient_colors)
        return SidePreview(std::make_shared<const PigmentModel>(colors), colors);
    return SidePreview(std::move(colors));
}

void SidePreview::add(const PrintPlan& plan) {
    std::vector<Rgb> mix_colors;
    for (const MixVector& mix : plan.mixes)
        mix_colors.push_back(pigments_ ? pigments_->predictRgb(mix) : mixColor(mix, colors_));
    const Rgb single = colors_.empty() ? Rgb{128, 128, 128} : colors_.front();
    Point2 head{0, 0};
    coord_um below = 0;
    for (const PlannedLayer& layer : plan.layers) {
        for (const PlanStep& step : layer.steps) {
            if (step.kind == PlanStep::Kind::Extrude) {
                Rgb color = step.mix >= 0 ? mix_colors[static_cast<std::size_t>(step.mix)] : single;
                if (step.outlet_color >= 0)  // what leaves the nozzle (mixing/transition/OutletPrediction.h)
                    color = plan.outlet_colors[static_cast<std::size_t>(step.outlet_color)];
                bands_.push_back({static_cast<std::int32_t>(head.X), static_cast<std::int32_t>(head.Y),
                                  static_cast<std::int32_t>(step.to.X), static_cast<std::int32_t>(step.to.Y),
                                  static_cast<std::int32_t>(below), static_cast<std::int32_t>(layer.z),
                                  color});
            }
            if (step.kind == PlanStep::Kind::Extrude || step.kind == PlanStep::Kind::Travel)
                head = step.to;
        }
        below = layer.z;
    }
}

Rgb SidePreview::Image::at(int x, int y) const {
    const std::size_t i =
        (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

std::string SidePreview::png() const {
    const Image image = render();
    return encodePng(image.width, image.height, image.rgb);
}

SidePreview::Image SidePreview::render() const {
    if (bands_.empty()) {
        Canvas blank(2 * kMarginPx, 2 * kMarginPx);
        return {blank.width, blank.height, std::move(blank.rgb)};
    }
    std::int32_t x_min = INT32_MAX, x_max = INT32_MIN, y_min = INT32_MAX, y_max = INT32_MIN;
    std::int32_t z_min = INT32_MAX, z_max = INT32_MIN;
    for (const Band& b : bands_) {
        x_min = std::min({x_min, b.x0_um, b.x1_um});
        x_max = std::max({x_max, b.x0_um, b.x1_um});
        y_min = std::min({y_min, b.y0_um, b.y1_um});
        y_max = std::max({y_max, b.y0_um, b.y1_um});
        z_min = std::min(z_min, b.z_bottom_um);
        z_max = std::max(z_max, b.z_top_um);
    }
    const double span = std::max({x_max - x_min, z_max - z_min, 1});
    const double px_per_um = (max_size_px_ - 2 * kMarginPx) / span;
    Canvas canvas(static_cast<int>(std::ceil((x_max - x_min) * px_per_um)) + 2 * kMarginPx,
                  static_cast<int>(std::ceil((z_max - z_min) * px_per_um)) + 2 * kMarginPx);
    const double depth_span = std::max(1, y_max - y_min);
    auto column = [&](double x_um) {
        return std::clamp(static_cast<int>((x_um - x_min) * px_per_um) + kMarginPx, 0, canvas.width - 1);
    };
    auto row = [&](double z_um) {
        return std::clamp(canvas.height - 1 - kMarginPx - static_cast<int>((z_um - z_min) * px_per_um), 0,
                          canvas.height - 1);
    };
    for (const Band& b : bands_) {
        const int c0 = column(std::min(b.x0_um, b.x1_um)), c1 = column(std::max(b.x0_um, b.x1_um));
        const int r_top = row(b.z_top_um), r_bottom = std::max(r_top, row(b.z_bottom_um) - 1);
        for (int c = c0; c <= c1; ++c) {
            // Depth along the segment at this column (the nearer end for a segment seen end-on).
            const double t = c1 > c0 ? double(c - c0) / (c1 - c0) : 0.0;
            const bool forward = b.x0_um <= b.x1_um;
            const double y =
                c1 > c0 ? (forward ? b.y0_um + t * (b.y1_um - b.y0_um) : b.y1_um + t * (b.y0_um - b.y1_um))
                        : std::min(b.y0_um, b.y1_um);
            const double shade = 1.0 - 0.35 * (y - y_min) / depth_span;
            for (int r = r_top; r <= r_bottom; ++r)
                canvas.plot(c, r, static_cast<float>(y), b.color, shade);
        }
    }
    return {canvas.width, canvas.height, std::move(canvas.rgb)};
}

}  // namespace mixengine
