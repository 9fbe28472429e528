#pragma once
// The G-code writer's core: turns moves into lines, keeping only what the text needs — the head
// position, the feedrate last written, the extrusion axis and the retraction state. Formatting
// lives in NumberFormat, E bookkeeping in ExtrusionAxis, headers in Header, time in the writer's
// simple kinematic estimate (distance / speed, with a retraction time).
#include <string>
#include <string_view>

#include "gcode/ExtrusionAxis.h"
#include "geometry/Point.h"

namespace mixengine {

struct ExportParams {
    double filament_diameter_mm = 2.85;
    bool volumetric = false;          ///< E in mm³ (RepRap (Volumetric))
    bool relative_extrusion = false;  ///< M83
    double retraction_amount_mm = 6.5;
    double retraction_speed_mm_s = 25;
    double prime_speed_mm_s = 25;
    coord_um retraction_hop_um = 0;  ///< z-hop while retracted (0 = off)
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
    void unretract();
    void resetExtrusionAxis();  ///< G92 E0 in absolute mode
    void setFan(double ratio);  ///< M106 S0..255 / M107

    const std::string& text() const { return out_; }
    std::string takeText() { return std::move(out_); }
    double elapsedSeconds() const { return elapsed_s_; }
    double filamentUsedMm() const { return axis_.totalExtrudedMm(); }  ///< length, or mm³ when volumetric
    coord_um z() const { return z_; }
    bool retracted() const { return retracted_; }

  private:
    std::string feedrateWord(double speed_mm_s);
    double volumeToAxisMm(double volume_mm3) const;
    double retractionOnAxis() const;  ///< the retraction in the axis unit (mm, or mm³ when volumetric)

    ExportParams params_;
    ExtrusionAxis axis_;
    std::string out_;
    Point2 position_{0, 0};
    coord_um z_ = 0;
    double feedrate_mm_s_ = -1;
    double elapsed_s_ = 0;
    bool retracted_ = false;
    double fan_ratio_ = -1;
};

}  // namespace mixengine
