#pragma once
// The --preview picture: the print seen from the front (looking along +Y; X to the right, Z up),
// every extrusion drawn as the band it fills (one layer thick) in the colour of its mix, so a
// gradient can be checked before printing. The channel colours (mixing_channel_colors) are
// mixed in linear light; the extrusion nearest to the viewer wins, and deeper ones are drawn a
// little darker so that the object's shape stays readable. Single mode draws channel A's colour.
// When the print asks for colours (mixing_mode color, or mixing_gradient_colors in the global
// settings) the mixes are drawn in the colour the pigment model predicts (mixing/color/KubelkaMunk.h),
// the colour the solver aimed at, instead of the linear-light blend. An extrusion whose colour leaving
// the nozzle is predicted (PlanStep::outlet_color, mixing/transition/OutletPrediction.h: every mixing print)
// is drawn in that colour: the preview shows what the chamber lets out, not what the G-code commands.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mixing/color/KubelkaMunk.h"
#include "mixing/setup/MixingSettings.h"
#include "planning/LayerPlan.h"

namespace mixengine {

/// The colour of `mix` from the channel colours (sRGB in, sRGB out, weights in linear light).
Rgb mixColor(const MixVector& mix, const std::vector<Rgb>& channel_colors);

class SidePreview {
  public:
    explicit SidePreview(std::vector<Rgb> channel_colors, int max_size_px = 800);
    /// Mixes drawn in the colours `pigments` predicts.
    SidePreview(std::shared_ptr<const PigmentModel> pigments, std::vector<Rgb> channel_colors,
                int max_size_px = 800);
    /// Colours from `global` (mixing_channel_colors, as many as mixing channels).
    static SidePreview forSettings(const Settings& global);

    /// Collects the extrusions of one mesh group's plan (after the mixing stage).
    void add(const PrintPlan& plan);
    struct Image {
        int width = 0, height = 0;
        std::vector<std::uint8_t> rgb;  ///< rows from the top, 3 bytes per pixel
        Rgb at(int x, int y) const;
    };
    /// The picture (a small blank picture when nothing was extruded); png() encodes it.
    Image render() const;
    std::string png() const;

  private:
    struct Band {
        std::int32_t x0_um, y0_um, x1_um, y1_um, z_bottom_um, z_top_um;
        Rgb color;
    };
    std::vector<Rgb> colors_;
    std::shared_ptr<const PigmentModel> pigments_;  ///< null: linear-light blend (mixColor)
    int max_size_px_;
    std::vector<Band> bands_;
};

}  // namespace mixengine
