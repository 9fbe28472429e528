#pragma once
// The G-code writer's core: turns moves into lines, keeping only what the text needs — the head
// position, the feedrate last written, the extrusion axis and the retraction state. Formatting
// lives in NumberFormat, E bookkeeping in ExtrusionAxis, headers in Header, time in TimeEstimate
// (acceleration and jerk). Coordinates are written relative to the active nozzle: a tool change
// sets the nozzle offset that is subtracted from every X/Y (machine_use_extruder_offset_to_offset_coords).
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "gcode/ExtrusionAxis.h"
#include "gcode/MixDialect.h"
#include "gcode/MotionCommands.h"
#include "gcode/TimeEstimate.h"
#include "geometry/Point.h"

namespace mixengine {

struct ExportParams {
    double filament_diameter_mm = 2.85;
    bool volumetric = false;          ///< E in mm³ of material (RepRap (Volumetric), UltiGCode)
    bool relative_extrusion = false;  ///< M83
    double retraction_amount_mm = 6.5;
    double retraction_speed_mm_s = 25;
    double prime_speed_mm_s = 25;
    coord_um retraction_hop_um = 0;  ///< z-hop while retracted (0 = off)
    bool firmware_retract = false;   ///< G10/G11 instead of E moves (machine_firmware_retract)
    /// retraction_extra_prime_amount: material pushed out on top of the prime after each retraction
    /// (not after an extruder switch), as its own E move at the prime speed; mm³.
    double extra_prime_mm3 = 0;
    Kinematics kinematics;
    MixingOutput mixing;  ///< colour mixing dialect (gcode/MixDialect.h); default: single colour
    MotionFlavor motion_flavor = MotionFlavor::Marlin;  ///< M204/M205 dialect (gcode/MotionCommands.h)
};

/// A tool change: the new extruder's filament diameter and nozzle offset (subtracted from X/Y).
struct ToolChange {
    int extruder = 0;
    double filament_diameter_mm = 2.85;
    Point2 nozzle_offset_um{0, 0};
};

class GCodeExport {
  public:
    explicit GCodeExport(const ExportParams& params);

    void line(std::string_view text);     ///< a raw line
    void comment(std::string_view text);  ///< ";text"
    void travel(const Point2& to, double speed_mm_s);
    void moveZ(coord_um z, double speed_mm_s);
    void extrude(const Point2& to, double volume_mm3, double speed_mm_s);
    void retract();
    void unretract();            ///< primes what was retracted, then any extra prime (ExportParams)
    void resetExtrusionAxis();   ///< G92 E0 in absolute mode
    void dwell(double seconds);  ///< G4 P<milliseconds>, counted in the time estimate
    void setFan(double ratio);   ///< M106 S0..255 / M107
    /// Acceleration (mm/s²) and XY jerk (mm/s) of the following moves, 0 = unchanged: writes
    /// M204/M205 (gcode/MotionCommands.h) when they change and uses them for the time estimate.
    void setMotion(double acceleration_mm_s2, double jerk_mm_s, bool travel);
    /// The mix of the following extrusions (mixing dialects only; ignored in single mode).
    void setMix(const MixVector& mix) { mix_ = mix; }
    /// Retracts, writes T<n>, resets E (absolute mode); filament is then counted for the new one.
    void selectExtruder(const ToolChange& change);
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
    std::vector<double> filamentPerExtruder();
    int extruder() const { return extruder_; }
    coord_um z() const { return z_; }
    bool retracted() const { return retracted_; }

  private:
    std::string feedrateWord(double speed_mm_s);
    double filamentMm(double volume_mm3) const;  ///< length of the active filament holding the volume
    double volumeOnAxis(
        double volume_mm3) const;     ///< the volume in the axis unit (mm, or mm³ when volumetric)
    double retractionOnAxis() const;  ///< the retraction in the axis unit
    /// Adds a move to the time estimate, whose E axis is always mm of filament (as CuraEngine's
    /// estimate and the firmware's E limits: machine_max_feedrate_e, _jerk_e, _acceleration_e).
    void timeMove(const Point2& to, coord_um z, double filament_mm, double speed_mm_s, TimeFeature feature);
    TimeFeature moveFeature() const { return retracted_ ? TimeFeature::Retraction : TimeFeature::Travel; }
    std::string xyWords(const Point2& to) const;  ///< " X.. Y..", relative to the active nozzle
    void noteFilamentOfActiveExtruder();

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
    std::vector<double> filament_by_extruder_;
    double total_at_last_change_ = 0;
    bool retracted_ = false;
    double pending_prime_mm3_ = 0;  ///< extra prime owed by the retractions since the last prime
    double fan_ratio_ = -1;
    MotionCommands motion_;
};

}  // namespace mixengine
