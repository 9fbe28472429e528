#include "mixing/fields/PaintSchedule.h"

#include <cmath>
#include <map>
#include <string>

#include "common/Error.h"
#include "settings/ValueParse.h"

namespace mixengine {
namespace {

std::vector<Rgb> paintColors(const Settings& scope, const std::vector<Rgb>& channel_colors) {
    const std::string text = scope.text(key::mixing_paint_colors);
    if (text.find_first_not_of(" \t") == std::string::npos)
        return channel_colors;
    return parseHexColorList("setting 'mixing_paint_colors'", text);
}

Rgb colorOfCode(std::uint32_t code, const std::vector<Rgb>& extruder_colors, const std::string& mesh) {
    if ((code & Mesh::kPaintedRgb) != 0)
        return {static_cast<std::uint8_t>(code >> 16), static_cast<std::uint8_t>(code >> 8),
                static_cast<std::uint8_t>(code)};
    const std::uint32_t extruder = code & 0xffffffu;
    if (extruder == 0 || extruder > extruder_colors.size())
        throw InputError("setting 'mixing_paint_colors': '" + mesh + "' is painted with extruder " +
                         std::to_string(extruder) + ", which has no colour (" +
                         std::to_string(extruder_colors.size()) + " given)");
    return extruder_colors[extruder - 1];
}

/// mixing_paint_blend in microns.
coord_um blendOf(const Settings& scope) {
    const double blend_mm = parseReal("mixing_paint_blend", scope.text(key::mixing_paint_blend));
    if (!(blend_mm >= 0) || !std::isfinite(blend_mm))
        throw InputError("setting 'mixing_paint_blend': " + scope.text(key::mixing_paint_blend) +
                         " mm is not a width of 0 or more");
    return static_cast<coord_um>(std::llround(blend_mm * 1000.0));
}

}  // namespace

MeshPaint paintOf(const Mesh& mesh, const Settings& scope, const std::vector<Rgb>& channel_colors,
                  const PigmentModel& model) {
    MeshPaint paint;
    if (mesh.face_colors.empty())
        return paint;
    const double depth_mm = parseReal("mixing_paint_depth", scope.text(key::mixing_paint_depth));
    if (!(depth_mm > 0))
        throw InputError("setting 'mixing_paint_depth': " + scope.text(key::mixing_paint_depth) +
                         " mm is not above 0");
    paint.blend_um = blendOf(scope);
    const std::vector<Rgb> extruder_colors = paintColors(scope, channel_colors);
    std::map<Rgb, int> region_of;
    std::vector<int> face_region;
    face_region.reserve(mesh.face_colors.size());
    for (const std::uint32_t code : mesh.face_colors) {
        if (code == 0) {
            face_region.push_back(-1);
            continue;
        }
        const Rgb color = colorOfCode(code, extruder_colors, mesh.name);
        auto [it, added] = region_of.emplace(color, static_cast<int>(paint.colors.size()));
        if (added)
            paint.colors.push_back({color, solveColor(model, color)});
        face_region.push_back(it->second);
    }
    paint.regions = std::make_unique<PaintedRegions>(
        mesh, std::move(face_region), static_cast<coord_um>(std::llround(depth_mm * 1000.0)), paint.blend_um);
    return paint;
}

}  // namespace mixengine
