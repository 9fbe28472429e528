#include "gcode/GCodeExport.h"

#include <cmath>
#include <numbers>

#include "gcode/NumberFormat.h"

namespace mixengine {

GCodeExport::GCodeExport(const ExportParams& params)
    : params_(params),
      dialect_(makeMixDialect(params.mixing, params.relative_extrusion)),
      mix_(MixVector::only(0, params.mixing.channels)),
      time_(params.kinematics),
      motion_(params.motion_flavor) {}

void GCodeExport::timeMove(const Point2& to, coord_um z, double filament_mm, double speed_mm_s,
                           TimeFeature feature) {
    time_.addMove(
        {micronsToMm(to.X - position_.X), micronsToMm(to.Y - position_.Y), micronsToMm(z - z_), filament_mm},
        speed_mm_s, feature);
}

std::string GCodeExport::xyWords(const Point2& to) const {
    return " X" + formatCoordMm(micronsToMm(to.X - offset_.X)) + " Y" +
           formatCoordMm(micronsToMm(to.Y - offset_.Y));
}

void GCodeExport::selectExtruder(const ToolChange& change) {
    if (change.extruder == extruder_)
        return;
    retract();
    pending_prime_mm3_ = 0;  // as CuraEngine: an extruder switch primes nothing extra
    line("T" + std::to_string(change.extruder));
    noteFilamentOfActiveExtruder();
    extruder_ = change.extruder;
    params_.filament_diameter_mm = change.filament_diameter_mm;
    offset_ = change.nozzle_offset_um;
    resetExtrusionAxis();
}

void GCodeExport::noteFilamentOfActiveExtruder() {
    const std::size_t index = static_cast<std::size_t>(extruder_);
    if (filament_by_extruder_.size() <= index)
        filament_by_extruder_.resize(index + 1, 0.0);
    const double total = dialect_->totalExtruded();
    filament_by_extruder_[index] += total - total_at_last_change_;
    total_at_last_change_ = total;
}

std::vector<double> GCodeExport::filamentPerExtruder() {
    noteFilamentOfActiveExtruder();
    return filament_by_extruder_;
}

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

double GCodeExport::filamentMm(double volume_mm3) const {
    const double radius = params_.filament_diameter_mm / 2.0;
    return volume_mm3 / (std::numbers::pi * radius * radius);
}

double GCodeExport::volumeOnAxis(double volume_mm3) const {
    return params_.volumetric ? volume_mm3 : filamentMm(volume_mm3);
}

void GCodeExport::travel(const Point2& to, double speed_mm_s) {
    if (to == position_)
        return;
    line("G0" + feedrateWord(speed_mm_s) + xyWords(to));
    timeMove(to, z_, 0, speed_mm_s, moveFeature());
    position_ = to;
}

void GCodeExport::moveZ(coord_um z, double speed_mm_s) {
    if (z == z_)
        return;
    timeMove(position_, z, 0, speed_mm_s, moveFeature());
    line("G0" + feedrateWord(speed_mm_s) + " Z" + formatCoordMm(micronsToMm(z)));
    z_ = z;
}

void GCodeExport::extrude(const Point2& to, double volume_mm3, double speed_mm_s) {
    if (retracted_)
        unretract();
    const double e = volumeOnAxis(volume_mm3);
    std::string before;
    const std::string words = dialect_->extrude(e, mix_, before);
    out_ += before;
    line("G1" + feedrateWord(speed_mm_s) + xyWords(to) + " " + words);
    timeMove(to, z_, filamentMm(volume_mm3), speed_mm_s, extrusion_feature_);
    position_ = to;
}

void GCodeExport::retract() {
    if (retracted_ || params_.retraction_amount_mm <= 0)
        return;
    pending_prime_mm3_ += params_.extra_prime_mm3;
    if (params_.firmware_retract) {
        line("G10");  // the firmware retracts; the E axis does not move
    } else {
        std::string before;
        const std::string words = dialect_->retract(retractionOnAxis(), before);
        out_ += before;
        line("G1" + feedrateWord(params_.retraction_speed_mm_s) + " " + words);
        timeMove(position_, z_, -params_.retraction_amount_mm, params_.retraction_speed_mm_s,
                 TimeFeature::Retraction);
    }
    retracted_ = true;
    if (params_.retraction_hop_um > 0)
        moveZ(z_ + params_.retraction_hop_um, params_.retraction_speed_mm_s);
}

void GCodeExport::unretract() {
    if (!retracted_)
        return;
    if (params_.retraction_hop_um > 0)
        moveZ(z_ - params_.retraction_hop_um, params_.retraction_speed_mm_s);
    if (params_.firmware_retract) {
        line("G11");
    } else {
        std::string before;
        const std::string words = dialect_->prime(retractionOnAxis(), before);
        out_ += before;
        line("G1" + feedrateWord(params_.prime_speed_mm_s) + " " + words);
        timeMove(position_, z_, params_.retraction_amount_mm, params_.prime_speed_mm_s,
                 TimeFeature::Retraction);
    }
    retracted_ = false;
    if (pending_prime_mm3_ > 0) {
        std::string before;
        const std::string words = dialect_->extrude(volumeOnAxis(pending_prime_mm3_), mix_, before);
        out_ += before;
        line("G1" + feedrateWord(params_.prime_speed_mm_s) + " " + words);
        timeMove(position_, z_, filamentMm(pending_prime_mm3_), params_.prime_speed_mm_s,
                 TimeFeature::Retraction);
    }
    pending_prime_mm3_ = 0;
}

void GCodeExport::dwell(double seconds) {
    line("G4 P" + std::to_string(static_cast<long long>(seconds * 1000)));
    time_.addDelay(seconds);
}

void GCodeExport::resetExtrusionAxis() {
    std::string reset = dialect_->reset();
    if (!reset.empty())
        line(reset);
}

void GCodeExport::setMotion(double acceleration_mm_s2, double jerk_mm_s, bool travel) {
    for (const std::string& text : motion_.acceleration(acceleration_mm_s2, travel))
        line(text);
    for (const std::string& text : motion_.jerk(jerk_mm_s))
        line(text);
    if (acceleration_mm_s2 > 0)
        time_.setAcceleration(acceleration_mm_s2);
    if (jerk_mm_s > 0)
        time_.setJerkXy(jerk_mm_s);
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
