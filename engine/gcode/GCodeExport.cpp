#include "gcode/GCodeExport.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "gcode/format/NumberFormat.h"

namespace mixengine {

GCodeExport::GCodeExport(const ExportParams& params)
    : params_(params),
      dialect_(makeMixDialect(params.mixing, params.relative_extrusion)),
      mix_(MixVector::only(0, params.mixing.channels)),
      time_(params.kinematics),
      retraction_{params.retraction_amount_mm, params.retraction_speed_mm_s, params.prime_speed_mm_s,
                  params.retraction_extra_prime_mm3},
      retraction_hop_um_(params.retraction_hop_um),
      fan_number_(params.fan_number),
      motion_(params.flavor.motion),
      temperatures_(params.temperatures, params.flavor.m105_before_wait) {
    state().prime_speed_mm_s = params.prime_speed_mm_s;
    dialect_->setAxisLetter(axisLetter(0));
}

char GCodeExport::axisLetter(int extruder) const {
    const FlavorTraits& flavor = params_.flavor;
    return flavor.axis_per_extruder ? static_cast<char>(flavor.axis + extruder) : flavor.axis;
}

GCodeExport::ExtruderState& GCodeExport::state() {
    const auto index = static_cast<std::size_t>(extruder_);
    if (states_.size() <= index)
        states_.resize(index + 1, ExtruderState{0, retraction_.prime_speed_mm_s, 0, 0, false});
    return states_[index];
}

void GCodeExport::timeMove(const Point2& to, coord_um z, double filament_mm, double speed_mm_s,
                           TimeFeature feature) {
    time_.addMove(
        {micronsToMm(to.X - position_.X), micronsToMm(to.Y - position_.Y), micronsToMm(z - z_), filament_mm},
        speed_mm_s, feature);
}

void GCodeExport::appendXy(const Point2& to) {
    out_ += " X";
    appendMicronsAsMm(out_, to.X - offset_.X);
    out_ += " Y";
    appendMicronsAsMm(out_, to.Y - offset_.Y);
}

void GCodeExport::appendZ(coord_um z) {
    out_ += " Z";
    appendMicronsAsMm(out_, z);
}

void GCodeExport::startMove(const char* command, double speed_mm_s) {
    out_ += command;
    if (speed_mm_s == feedrate_mm_s_)
        return;
    feedrate_mm_s_ = speed_mm_s;
    out_ += " F";
    appendFeedrate(out_, speed_mm_s);
}

void GCodeExport::startHop(double speed_mm_s) {
    feedrate_mm_s_ = speed_mm_s;
    out_ += "G1 F";
    appendFeedrate(out_, speed_mm_s);
}

void GCodeExport::endMove(std::string_view words) {
    out_ += ' ';
    out_ += words;
    out_ += '\n';
}

void GCodeExport::selectExtruder(const ToolChange& change) {
    if (change.extruder == extruder_)
        return;
    if (params_.flavor.rpm_extrusion)
        out_ += bfb_.stop();
    line("T" + std::to_string(change.extruder));
    extruder_ = change.extruder;
    params_.filament_diameter_mm = change.filament_diameter_mm;
    offset_ = change.nozzle_offset_um;
    retraction_ = change.retraction;
    retraction_hop_um_ = change.retraction_hop_um;
    if (change.fan_number != fan_number_) {  // another fan: its speed is written again
        fan_number_ = change.fan_number;
        fan_ratio_ = -1;
    }
    state();  // a first use starts with nothing retracted, primed at its own prime speed
    dialect_->setAxisLetter(axisLetter(change.extruder));
    resetExtrusionAxis();
}

bool GCodeExport::markPrimed() {
    const bool was = state().primed;
    state().primed = true;
    return !was;
}

void GCodeExport::assumePrimed(int extruder, double retracted_mm) {
    const int active = extruder_;
    extruder_ = extruder;
    state().primed = true;
    state().retracted_mm = retracted_mm;
    extruder_ = active;
}

std::vector<double> GCodeExport::filamentPerExtruder() const {
    std::vector<double> out;
    for (const ExtruderState& s : states_)
        out.push_back(s.extruded);
    return out;
}

void GCodeExport::line(std::string_view text) {
    out_ += text;
    out_ += '\n';
}

void GCodeExport::comment(std::string_view text) {
    out_ += ';';
    line(text);
}

double GCodeExport::filamentOnAxis(double filament_mm) const {
    if (!params_.flavor.volumetric_e)
        return filament_mm;
    const double radius = params_.filament_diameter_mm / 2.0;
    return filament_mm * std::numbers::pi * radius * radius;
}

double GCodeExport::filamentMm(double volume_mm3) const {
    const double radius = params_.filament_diameter_mm / 2.0;
    return volume_mm3 / (std::numbers::pi * radius * radius);
}

double GCodeExport::volumeOnAxis(double volume_mm3) const {
    return params_.flavor.volumetric_e ? volume_mm3 : filamentMm(volume_mm3);
}

void GCodeExport::bfbTravel(const Point2& to, coord_um z, double speed_mm_s) {
    out_ += bfb_.stop();
    line(bfbMove({to.X - offset_.X, to.Y - offset_.Y}, z, static_cast<float>(speed_mm_s * 60.0)));
    timeMove(to, z, 0, speed_mm_s, moveFeature());
    position_ = to;
    z_ = z;
}

void GCodeExport::bfbExtrude(const Point2& to, double volume_mm3, double speed_mm_s) {
    const double filament_mm = filamentMm(volume_mm3);
    const double length_mm = distanceMm(position_, to);
    std::string before;
    const double feedrate =
        bfb_.extrude(length_mm > 0 ? filament_mm / length_mm : 0.0, speed_mm_s, extruder_, before);
    out_ += before;
    state().extruded += volumeOnAxis(volume_mm3);
    line(bfbMove({to.X - offset_.X, to.Y - offset_.Y}, z_, feedrate));
    timeMove(to, z_, filament_mm, speed_mm_s, extrusion_feature_);
    position_ = to;
}

double GCodeExport::offsetExtra() {
    const double extra = params_.relative_extrusion ? e_offset_ : e_offset_ - offset_applied_;
    if (!params_.relative_extrusion)
        offset_applied_ = e_offset_;
    return extra;
}

double GCodeExport::dropOffset() {
    const double applied = offset_applied_;
    offset_applied_ = 0;
    return applied;
}

void GCodeExport::updateOffset(const Point2& to, double volume_mm3, double speed_mm_s) {
    if (!offset_update_ || to == position_)
        return;
    offset_update_ = false;
    const double length_mm = distanceMm(position_, to);
    const double offset =
        std::min(speed_mm_s * volume_mm3 / length_mm * params_.flow_offset_factor, params_.flow_offset_max);
    if (offset == e_offset_)
        return;
    e_offset_ = offset;
    char text[64];
    std::snprintf(text, sizeof text, "FLOW_RATE_COMPENSATED_OFFSET = %.6f", offset);
    comment(text);
}

void GCodeExport::travel(const Point2& to, double speed_mm_s) {
    if (to == position_)
        return;
    if (params_.flavor.rpm_extrusion)
        return bfbTravel(to, z_, speed_mm_s);

    if (e_offset_ != 0) {  // flow-rate compensation: travel writes E too (newExtrusionConfig)
        std::string before;
        const std::string words = dialect_->extrude(offsetExtra(), mix_, before);
        out_ += before;
        startMove("G0", speed_mm_s);
        appendXy(to);
        endMove(words);
        timeMove(to, z_, 0, speed_mm_s, moveFeature());
        position_ = to;
        return;
    }
    startMove("G0", speed_mm_s);
    appendXy(to);
    endLine();
    timeMove(to, z_, 0, speed_mm_s, moveFeature());
    position_ = to;
}

void GCodeExport::moveZ(coord_um z, double speed_mm_s) {
    writeZ(z, speed_mm_s, false);
}

void GCodeExport::writeZ(coord_um z, double speed_mm_s, bool hop) {
    layer_z_ = z - hop_um_;
    if (z == z_)
        return;
    if (params_.flavor.rpm_extrusion) {  // every BFB move carries Z: the next one goes there (as CuraEngine)
        timeMove(position_, z, 0, speed_mm_s, moveFeature());
        z_ = z;
        return;
    }
    timeMove(position_, z, 0, speed_mm_s, moveFeature());
    if (hop)
        startHop(speed_mm_s);
    else
        startMove("G0", speed_mm_s);
    appendZ(z);
    endLine();
    z_ = z;
}

void GCodeExport::hopTo(coord_um hop_um, bool rewrite, double speed_mm_s) {
    if (hop_um == hop_um_ && !(rewrite && hop_um > 0))
        return;
    const double speed = speed_mm_s > 0 ? speed_mm_s : params_.z_hop_speed_mm_s;
    const coord_um layer = layer_z_;
    hop_um_ = hop_um;
    if (z_ == layer + hop_um) {  // up already: the line again, without a move to time
        if (params_.flavor.rpm_extrusion)
            return;
        startHop(speed);
        appendZ(z_);
        endLine();
        return;
    }
    writeZ(layer + hop_um, speed, true);
}

void GCodeExport::extrude(const Point2& to, double volume_mm3, double speed_mm_s) {
    if (params_.flavor.rpm_extrusion)
        return bfbExtrude(to, volume_mm3, speed_mm_s);
    if (retracted() || hop_um_ > 0 || state().extra_prime_mm3 > 0)
        unretract();
    updateOffset(to, volume_mm3, speed_mm_s);
    const double e = volumeOnAxis(volume_mm3);
    state().extruded += e;
    std::string before;
    const std::string words = dialect_->extrude(e + (e_offset_ != 0 ? offsetExtra() : 0.0), mix_, before);
    out_ += before;
    startMove("G1", speed_mm_s);
    appendXy(to);
    endMove(words);
    timeMove(to, z_, filamentMm(volume_mm3), speed_mm_s, extrusion_feature_);
    position_ = to;
}

void GCodeExport::extrudeRising(const Point2& to, coord_um z_um, double volume_mm3, double speed_mm_s) {
    if (volume_mm3 > 0) {
        if (retracted() || hop_um_ > 0 || state().extra_prime_mm3 > 0)
            unretract();
    }
    double filament_mm = 0;
    std::string extrusion;
    if (volume_mm3 > 0) {
        const double e = volumeOnAxis(volume_mm3);
        state().extruded += e;
        std::string before;
        extrusion = dialect_->extrude(e, mix_, before);
        out_ += before;
        filament_mm = filamentMm(volume_mm3);
    }
    startMove("G1", speed_mm_s);
    appendXy(to);
    if (z_um != z_)
        appendZ(z_um);
    if (volume_mm3 > 0)
        endMove(extrusion);
    else
        endLine();
    timeMove(to, z_um, filament_mm, speed_mm_s, extrusion_feature_);
    position_ = to;
    z_ = z_um;
    layer_z_ = z_um - hop_um_;
}

void GCodeExport::retract() {
    const bool was_retracted = retracted();
    retractTo(retraction_);
    if (!was_retracted && retracted() && retraction_hop_um_ > 0)
        hopTo(retraction_hop_um_);
}

void GCodeExport::retractTo(const RetractionConfig& config) {
    if (params_.flavor.rpm_extrusion)
        return;  // the firmware retracts when the motor stops (M103)
    ExtruderState& s = state();
    const double change_mm = config.amount_mm - s.retracted_mm;
    if (std::abs(change_mm) < 1e-6)
        return;
    if (params_.firmware_retract) {
        if (s.retracted_mm <= 0)
            line("G10");  // the firmware retracts; the E axis does not move
    } else {
        const double speed = change_mm > 0 ? config.retract_speed_mm_s : s.prime_speed_mm_s;
        std::string before;
        const double applied = dropOffset();
        const std::string words = change_mm > 0
                                      ? dialect_->retract(filamentOnAxis(change_mm) + applied, before)
                                      : dialect_->prime(filamentOnAxis(-change_mm) - applied, before);
        out_ += before;
        startMove("G1", speed);
        endMove(words);
        timeMove(position_, z_, -change_mm, speed, TimeFeature::Retraction);
    }
    s.retracted_mm = config.amount_mm;
    s.prime_speed_mm_s = config.prime_speed_mm_s;
    s.extra_prime_mm3 += config.extra_prime_mm3;
}

void GCodeExport::unretract() {
    hopTo(0);
    writePrime();
}

void GCodeExport::primeInPlace() {
    if (params_.flavor.rpm_extrusion) {
        if (params_.firmware_retract)
            out_ += bfb_.prime();
        return;
    }
    writePrime();
}

void GCodeExport::writePrime() {
    ExtruderState& s = state();
    const double prime_mm = s.retracted_mm + filamentMm(s.extra_prime_mm3);
    if (params_.firmware_retract && s.retracted_mm > 0)
        line("G11");
    const double moved_mm = params_.firmware_retract ? filamentMm(s.extra_prime_mm3) : prime_mm;
    if (moved_mm > 0) {
        std::string before;
        const std::string words = dialect_->prime(filamentOnAxis(moved_mm) - dropOffset(), before);
        out_ += before;
        startMove("G1", s.prime_speed_mm_s);
        endMove(words);
    }
    if (prime_mm > 0)
        timeMove(position_, z_, prime_mm, s.prime_speed_mm_s, TimeFeature::Retraction);
    s.extruded += volumeOnAxis(s.extra_prime_mm3);  // material out of the nozzle
    s.retracted_mm = 0;
    s.extra_prime_mm3 = 0;
}

void GCodeExport::dwell(double seconds) {
    line("G4 P" + std::to_string(static_cast<long long>(seconds * 1000)));
    time_.addDelay(seconds);
}

void GCodeExport::resetExtrusionAxis() {
    // A flow-rate offset already applied stays applied: the reset moves the coordinate, not the filament.
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

void GCodeExport::setNozzleTemperature(int extruder, double celsius, bool wait) {
    for (const std::string& text :
         temperatures_.set(extruder < 0 ? extruder_ : extruder, celsius, wait, extruder_))
        line(text);
}

void GCodeExport::setFan(double ratio) {
    if (ratio == fan_ratio_)
        return;
    fan_ratio_ = ratio;
    const std::string fan = fan_number_ != 0 ? " P" + std::to_string(fan_number_) : "";
    if (params_.flavor.fan_on_off) {
        line(ratio > 0 ? "M126 T0" : "M127 T0");  // Makerbot: the fan is on or off, no speed
    } else if (ratio <= 0) {
        line("M107" + fan);
    } else {
        // as CuraEngine 4.13 scales it, from the percentage: percent · 255 / 100 (1 % is 2.5499…, "S2.5")
        const double percent = std::min(ratio, 1.0) * 100.0;
        line("M106 S" + formatDecimal(percent * 255.0 / 100.0, 1) + fan);
    }
}

}  // namespace mixengine
