#pragma once
// The G-code writer's core: turns moves into lines, keeping only what the text needs — the head
// position, the feedrate last written, the extrusion axis, each extruder's retracted filament (as
// CuraEngine: a switch retraction longer than the travel one is primed back in part at the next
// retraction), the z-hop in force, the fan and the nozzle temperatures set. Formatting
// lives in NumberFormat, E bookkeeping in ExtrusionAxis, headers in Header, time in TimeEstimate
// (acceleration and jerk). Coordinates are written relative to the active nozzle: a tool change
// sets the nozzle offset that is subtracted from every X/Y (machine_use_extruder_offset_to_offset_coords).
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "gcode/Bfb.h"
#include "gcode/Flavor.h"
#include "gcode/MotionCommands.h"
#include "gcode/TemperatureCommands.h"
#include "gcode/TimeEstimate.h"
#include "gcode/format/ExtrusionAxis.h"
#include "gcode/mixdialect/MixDialect.h"
#include "geometry/Point.h"

namespace mixengine {

/// A retraction (CuraEngine's RetractionConfig): how much filament is pulled back, how fast it goes
/// back and forth, and the material primed in addition when it goes forward again.
/// Every value comes from the settings (gcode/OutputParams.cpp); the defaults are the definitions'.
struct RetractionConfig {
    double amount_mm = 0;  ///< filament pulled back (0: no retraction)
    double retract_speed_mm_s = 0;
    double prime_speed_mm_s = 0;  ///< of the prime that undoes this retraction
    double extra_prime_mm3 = 0;   ///< primed in addition after it (retraction_extra_prime_amount)
};

/// What the G-code writer needs, built from the settings by exportParams (gcode/OutputParams.cpp): no
/// value here restates a definition's default (a unit test sets what it relies on).
struct ExportParams {
    /// The firmware flavor's row (gcode/Flavor.h): E in mm³, the extrusion axis letters, BFB's
    /// RPM-driven extrusion, the fan, acceleration/jerk and M105 forms, ...
    FlavorTraits flavor = flavorTraits(Flavor::Marlin);
    double filament_diameter_mm = 0;  ///< material_diameter of the first extruder (0 only in E-free tests)
    bool relative_extrusion = false;  ///< M83
    double retraction_amount_mm = 0;  ///< the first extruder's retraction (ToolChange for the others)
    double retraction_speed_mm_s = 0;
    double prime_speed_mm_s = 0;
    double retraction_extra_prime_mm3 = 0;
    coord_um retraction_hop_um = 0;  ///< z-hop while retracted (0 = off)
    double z_hop_speed_mm_s = 0;     ///< speed_z_hop: the lifts and lowerings of z-hops
    bool firmware_retract = false;   ///< G10/G11 instead of E moves (machine_firmware_retract)
    Kinematics kinematics;
    MixingOutput mixing;  ///< colour mixing dialect (gcode/mixdialect/MixDialect.h); default: single colour
    TemperatureCommandParams temperatures;  ///< nozzle temperature commands (gcode/TemperatureCommands.h)
    int fan_number = 0;  ///< the first extruder's machine_extruder_cooling_fan_number (P<n> when not 0)
    /// Flow-rate compensation (flow_rate_max_extrusion_offset, in the axis unit; 0 = off) and
    /// flow_rate_extrusion_offset_factor (a fraction): see GCodeExport::newExtrusionConfig().
    double flow_offset_max = 0;
    double flow_offset_factor = 1.0;
};

/// A tool change: the new extruder's filament diameter, nozzle offset (subtracted from X/Y) and its
/// own retraction and z-hop for travel.
struct ToolChange {
    int extruder = 0;
    double filament_diameter_mm = 0;  ///< its material_diameter
    Point2 nozzle_offset_um{0, 0};
    RetractionConfig retraction;
    coord_um retraction_hop_um = 0;
    int fan_number = 0;  ///< machine_extruder_cooling_fan_number: M106/M107 P<n> when not 0
};

class GCodeExport {
  public:
    explicit GCodeExport(const ExportParams& params);

    void line(std::string_view text);     ///< a raw line
    void comment(std::string_view text);  ///< ";text"
    void travel(const Point2& to, double speed_mm_s);
    /// A Z move to `z`, which (less the z-hop in force) becomes the layer's height.
    /// BFB: no line of its own; the next move carries the new Z.
    void moveZ(coord_um z, double speed_mm_s);
    /// A new layer at `z`: Z goes there (plus the z-hop in force, kept until the next prime).
    void startLayer(coord_um z, double speed_mm_s) { moveZ(z + hop_um_, speed_mm_s); }
    void extrude(const Point2& to, double volume_mm3, double speed_mm_s);
    /// An extrusion that ends at nozzle height `z_um`, which becomes the layer's height (spiralize:
    /// Z is written with the move when it changes, as CuraEngine). Without volume the move is
    /// written without E (the tapering end of a spiral).
    void extrudeRising(const Point2& to, coord_um z_um, double volume_mm3, double speed_mm_s);
    /// The active extruder's own retraction for travel (and its z-hop).
    void retract();
    /// Changes the retracted filament of the active extruder to `config.amount_mm`, as CuraEngine
    /// does: retracting the difference at the retraction speed when more, priming it back at the
    /// speed of the retraction before when less; nothing when equal. Every retraction made adds its
    /// extra prime for the next prime.
    void retractTo(const RetractionConfig& config);
    /// Lifts the nozzle `hop_um` above the layer (0: back down); nothing when already there, unless
    /// `rewrite` (CuraEngine writes the lift of a switch even when the nozzle is up already). At
    /// `speed_mm_s`, or speed_z_hop when 0.
    void hopTo(coord_um hop_um, bool rewrite = false, double speed_mm_s = 0);
    /// The active extruder's retraction for travel.
    const RetractionConfig& retraction() const { return retraction_; }
    /// Notes that the active extruder is primed; false when it was already.
    bool markPrimed();
    /// Extruder `extruder` starts with `retracted_mm` of filament pulled back and primed
    /// (machine_extruders_share_nozzle: the start code leaves every filament so).
    void assumePrimed(int extruder, double retracted_mm);
    /// Primes what is retracted, plus the extra prime owed (after lowering a z-hop).
    void unretract();
    /// Primes what is retracted and the extra prime owed where the head is, leaving a z-hop up
    /// (CuraEngine's prime before the last travel move onto an outer wall; BFB: G11).
    void primeInPlace();
    /// Material primed in addition at the next prime of the active extruder
    /// (switch_extruder_extra_prime_amount).
    void addExtraPrime(double volume_mm3) { state().extra_prime_mm3 += volume_mm3; }
    void resetExtrusionAxis();   ///< G92 E0 in absolute mode
    void dwell(double seconds);  ///< G4 P<milliseconds>, counted in the time estimate
    void setFan(double ratio);   ///< M106 S0..255 / M107 (P<n> for the active extruder's fan n ≠ 0)
    /// Acceleration (mm/s²) and XY jerk (mm/s) of the following moves, 0 = unchanged: writes
    /// M204/M205 (gcode/MotionCommands.h) when they change and uses them for the time estimate.
    void setMotion(double acceleration_mm_s2, double jerk_mm_s, bool travel);
    /// Nozzle `extruder` (−1: the active one) to `celsius`, M109 when `wait`; nothing when that changes
    /// nothing (gcode/TemperatureCommands.h).
    void setNozzleTemperature(int extruder, double celsius, bool wait);
    /// What the start code set: nozzle `extruder` at `celsius`, waited for or not.
    void assumeNozzleTemperature(int extruder, double celsius, bool waited) {
        temperatures_.assume(extruder, celsius, waited);
    }
    /// The mix of the following extrusions (mixing dialects only; ignored in single mode).
    void setMix(const MixVector& mix) { mix_ = mix; }
    /// Writes T<n> and resets E (absolute mode); filament is then counted for the new one, which
    /// keeps its own retracted filament from when it was last used (the caller retracts before).
    void selectExtruder(const ToolChange& change);
    /// Flow-rate compensation, as CuraEngine 4.13 writes it: the first extrusion after this (a new
    /// ;TYPE:, a new layer) sets the offset to speed × mm³ per mm × flow_offset_factor, at most
    /// flow_offset_max, writing ";FLOW_RATE_COMPENSATED_OFFSET = <offset>" when it changes. While it
    /// is not 0, the E word of every extrusion and travel carries it on top of the filament:
    /// absolute mode writes positions that far ahead (retractions and primes write the plain
    /// position, so the next move adds it again), relative mode adds it to every such move. On a
    /// mixing printer the extra is split like the move's filament.
    void newExtrusionConfig() { offset_update_ = true; }
    /// Plans buffered moves to a stop (at layer ends) so the time read next is final.
    void flushTime() { time_.flush(); }
    /// What the following extrusions print, for the time per feature (travel, retractions and
    /// primes are booked by the writer itself: Travel, or Retraction while retracted).
    void setTimeFeature(TimeFeature feature) { extrusion_feature_ = feature; }

    const std::string& text() const { return out_; }
    std::string takeText() { return std::move(out_); }
    double elapsedSeconds() const { return time_.totalSeconds(); }
    FeatureSeconds secondsByFeature() const { return time_.secondsByFeature(); }
    /// Forward extrusion so far in the axis unit: mm of filament, or mm³ when volumetric.
    double totalExtruded() const { return dialect_->totalExtruded(); }
    /// Per mixing channel (one entry in single mode), length or mm³ when volumetric.
    std::vector<double> filamentPerChannel() const { return dialect_->channelTotals(); }
    /// Filament per extruder (index = extruder_nr), length or mm³ when volumetric.
    std::vector<double> filamentPerExtruder() const;
    int extruder() const { return extruder_; }
    /// The firmware flavor written (ExportParams::flavor).
    const FlavorTraits& flavor() const { return params_.flavor; }
    Point2 position() const { return position_; }  ///< of the active nozzle, in plan coordinates
    coord_um z() const { return z_; }
    bool retracted() const { return states_[static_cast<std::size_t>(extruder_)].retracted_mm > 0; }
    /// Filament of the active extruder pulled back now (mm).
    double retractedMm() const { return states_[static_cast<std::size_t>(extruder_)].retracted_mm; }

  private:
    /// moveZ; a z-hop (up or down) is written as CuraEngine writes it: G1 with its feedrate always.
    void writeZ(coord_um z, double speed_mm_s, bool hop);
    void startHop(double speed_mm_s);  ///< "G1 F<mm/min>", the feedrate always (it is then in force)
    /// Appends `command` and, when the speed changed, " F<mm/min>" (the feedrate is then in force).
    void startMove(const char* command, double speed_mm_s);
    void appendXy(const Point2& to);       ///< " X.. Y..", relative to the active nozzle
    void appendZ(coord_um z);              ///< " Z.."
    void endMove(std::string_view words);  ///< " <words>" and the line end
    void endLine() { out_ += '\n'; }
    double filamentMm(double volume_mm3) const;  ///< length of the active filament holding the volume
    double volumeOnAxis(
        double volume_mm3) const;  ///< the volume in the axis unit (mm, or mm³ when volumetric)
    /// Adds a move to the time estimate, whose E axis is always mm of filament (as CuraEngine's
    /// estimate and the firmware's E limits: machine_max_feedrate_e, _jerk_e, _acceleration_e).
    void timeMove(const Point2& to, coord_um z, double filament_mm, double speed_mm_s, TimeFeature feature);
    TimeFeature moveFeature() const { return retracted() ? TimeFeature::Retraction : TimeFeature::Travel; }
    /// What an extruder keeps across tool changes.
    struct ExtruderState {
        double retracted_mm = 0;
        double prime_speed_mm_s = 25;  ///< of the next prime: that of the last retraction
        double extra_prime_mm3 = 0;
        double extruded = 0;  ///< forward filament in the axis unit (extra primes included)
        bool primed = false;
    };
    ExtruderState& state();
    char axisLetter(int extruder) const;  ///< the extrusion axis of `extruder` (E, or MACH3's A, B, ...)
    double filamentOnAxis(double filament_mm) const;  ///< filament in the axis unit
    /// BFB: a move without extrusion (the motor stops first).
    void bfbTravel(const Point2& to, coord_um z, double speed_mm_s);
    void bfbExtrude(const Point2& to, double volume_mm3, double speed_mm_s);
    /// Primes the retracted filament and the extra prime owed (no z-hop change).
    void writePrime();

    ExportParams params_;
    std::unique_ptr<MixDialect> dialect_;  ///< extrusion words, retraction, resets, mix commands
    MixVector mix_;
    std::string out_;
    Point2 position_{0, 0};
    coord_um z_ = 0;
    double feedrate_mm_s_ = -1;
    TimeEstimate time_;
    TimeFeature extrusion_feature_ = TimeFeature::None;
    int extruder_ = 0;
    Point2 offset_{0, 0};
    RetractionConfig retraction_;  ///< of the active extruder
    coord_um retraction_hop_um_ = 0;
    std::vector<ExtruderState> states_;  ///< by extruder_nr
    coord_um layer_z_ = 0;
    coord_um hop_um_ = 0;  ///< the nozzle is this far above layer_z_
    double fan_ratio_ = -1;
    int fan_number_ = 0;
    MotionCommands motion_;
    TemperatureCommands temperatures_;
    BfbMotor bfb_;

    double e_offset_ = 0;        ///< flow-rate compensation offset in force (axis unit)
    double offset_applied_ = 0;  ///< absolute mode: how far the written E is ahead of the filament
    bool offset_update_ = false;
    /// The E amount a move writes on top of its filament for the offset (and notes it applied).
    double offsetExtra();
    /// For a retraction or prime: the written E goes back to the plain position (absolute mode).
    double dropOffset();
    void updateOffset(const Point2& to, double volume_mm3, double speed_mm_s);
};

}  // namespace mixengine
