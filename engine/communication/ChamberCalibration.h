#pragma once
// `mixengine calibrate-chamber` (issue 26): what the chamber model (mixing/chamber/ChamberModel.h) predicts
// for a tower whose G-code switches hard from filament A to B and back, and the reading guide printed with
// it.
//
// After a hard switch the melt leaving the nozzle is the chamber's step response: with N equal stirred tanks
// of total volume V, the share of the new filament after v mm³ is 1 − e^(−t) Σ_{k<N} t^k / k!, t = v·N / V.
// The points are found on the model itself (Chamber::push from a chamber full of A), not on that formula, so
// the table says what the slicer will assume once mixing_chamber_volume and mixing_chamber_stages are set.
// On a tower that extrudes `per_mm` mm³ per mm of height, v mm³ lie v / per_mm above the switch.
#include <string>
#include <vector>

#include "mixing/chamber/ChamberModel.h"

namespace mixengine {

/// The volumes after a switch at which the outlet is 10 %, 50 % and 90 % of the way to the new filament.
struct StepPoints {
    double v10 = 0, v50 = 0, v90 = 0;
};

/// The volume of the new filament after which a chamber full of the old one lets out `fraction` (0..1) of
/// the new one (bisection on the model's outlet, to 1e-6 mm³). 0 for an ideal chamber.
double volumeToFraction(const ChamberSpec& spec, double fraction);

StepPoints stepPoints(const ChamberSpec& spec);

/// The candidates of the table: V 10..120 mm³, N 1, 2, 3, 4, 6, 10.
std::vector<double> candidateVolumesMm3();
std::vector<int> candidateStages();

/// What the reading guide says about one print.
struct CalibrationTower {
    double side_mm = 8;     ///< the square tower's outside
    double height_mm = 40;  ///< the tower's height
    double first_mm = 10;   ///< the asked switch heights (A → B, then B → A)
    double second_mm = 25;
    double switch1_mm = 10;  ///< where the G-code switches (above the plate), from the sliced plan
    double switch2_mm = 25;
    double per_mm_mm3 = 0;   ///< extrusion per mm of tower height, from the sliced plan
    std::string filament_a;  ///< "filament 1 (#f4f4f4)"
    std::string filament_b;
    ChamberSpec current;  ///< the profile's mixing_chamber_volume / _stages (volume 0: not set)
    double print_time_s = 0;
    double filament_mm3 = 0;  ///< all filament of the print
};

/// The guide, one line per entry (no line ends): the switches, the volume per mm, how to read the tower,
/// the rule of thumb with its numbers, the per-N factors and the table of heights for the candidates.
std::vector<std::string> calibrationGuide(const CalibrationTower& tower);

}  // namespace mixengine
