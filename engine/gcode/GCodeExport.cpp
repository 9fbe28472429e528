#include "gcode/GCodeExport.h"

#include <cmath>
#include <numbers>

#include "gcode/NumberFormat.h"

namespace mixengine {

GCodeExport::GCodeExport(const ExportParams& params)
    : params_(params), axis_('E', params.relative_extrusion) {}

void GCodeExport::line(std::string_view text) {
    out_ += text;
    out_ += '\n';
}

void GCodeExport::comment(std::string_view text) {
    out_ += ';';
    line(text);
}

std::string GCodeExport::feedrateWord(double speed_mm_s) {
    if (speed_mm_s == feedrate_mm_s_)
        return "";
    feedrate_mm_s_ = speed_mm_s;
    return " F" + formatFeedrate(speed_mm_s);
}

double GCodeExport::retractionOnAxis() const {
    if (!params_.volumetric)
        return params_.retraction_amount_mm;
    const double radius = params_.filament_diameter_mm / 2.0;
    return params_.retraction_amount_mm * std::numbers::pi * radius * radius;
}

double GCodeExport::volumeToAxisMm(double volume_mm3) const {
    if (params_.volumetric)
        return volume_mm3;
    const double radius = params_.filament_diameter_mm / 2.0;
    return volume_mm3 / (std::numbers::pi * radius * radius);
}

void GCodeExport::travel(const Point2& to, double speed_mm_s) {
    if (to == position_)
        return;
    const double distance_mm =
        std::hypot(double(to.X - position_.X), double(to.Y - position_.Y)) / kMicronsPerMm;
    line("G0" + feedrateWord(speed_mm_s) + " X" + formatCoordMm(micronsToMm(to.X)) + " Y" +
         formatCoordMm(micronsToMm(to.Y)));
    position_ = to;
    elapsed_s_ += distance_mm / speed_mm_s;
}

void GCodeExport::moveZ(coord_um z, double speed_mm_s) {
    if (z == z_)
        return;
    elapsed_s_ += std::fabs(micronsToMm(z - z_)) / speed_mm_s;
    line("G0" + feedrateWord(speed_mm_s) + " Z" + formatCoordMm(micronsToMm(z)));
    z_ = z;
}

void GCodeExport::extrude(const Point2& to, double volume_mm3, double speed_mm_s) {
    if (retracted_)
        unretract();
    const double distance_mm =
        std::hypot(double(to.X - position_.X), double(to.Y - position_.Y)) / kMicronsPerMm;
    line("G1" + feedrateWord(speed_mm_s) + " X" + formatCoordMm(micronsToMm(to.X)) + " Y" +
         formatCoordMm(micronsToMm(to.Y)) + " " + axis_.move(volumeToAxisMm(volume_mm3)));
    position_ = to;
    elapsed_s_ += distance_mm / speed_mm_s;
}

void GCodeExport::retract() {
    if (retracted_ || params_.retraction_amount_mm <= 0)
        return;
    line("G1" + feedrateWord(params_.retraction_speed_mm_s) + " " + axis_.move(-retractionOnAxis()));
    elapsed_s_ += params_.retraction_amount_mm / params_.retraction_speed_mm_s;
    retracted_ = true;
    if (params_.retraction_hop_um > 0)
        moveZ(z_ + params_.retraction_hop_um, params_.retraction_speed_mm_s);
}

void GCodeExport::unretract() {
    if (!retracted_)
        return;
    if (params_.retraction_hop_um > 0)
        moveZ(z_ - params_.retraction_hop_um, params_.retraction_speed_mm_s);
    line("G1" + feedrateWord(params_.prime_speed_mm_s) + " " + axis_.move(retractionOnAxis()));
    elapsed_s_ += params_.retraction_amount_mm / params_.prime_speed_mm_s;
    retracted_ = false;
}

void GCodeExport::resetExtrusionAxis() {
    std::string reset = axis_.reset();
    if (!reset.empty())
        line(reset);
}

void GCodeExport::setFan(double ratio) {
    if (ratio == fan_ratio_)
        return;
    fan_ratio_ = ratio;
    if (ratio <= 0) {
        line("M107");
    } else {
        line("M106 S" + formatDecimal(std::min(ratio, 1.0) * 255.0, 1));
    }
}

}  // namespace mixengine
