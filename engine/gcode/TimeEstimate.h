#pragma once
// Print-time estimate with an acceleration and jerk model, the way the firmware's planner moves:
// every move accelerates from its entry speed to its nominal speed and decelerates to its exit
// speed (a trapezoid), and the speed at a junction between two moves is limited by the jerk —
// the largest instantaneous change of velocity the firmware allows.
//
// Moves are buffered and planned with a backward and a forward pass whenever the buffer is
// flushed (the G-code writer flushes at every layer end and at delays), so the estimate is
// independent of how often it is read. Units: mm, mm/s, mm/s², seconds.
//
// Every move is tagged with what it prints (TimeFeature, CuraEngine's PrintFeatureType numbering),
// and its planned time is added to that feature; delays count as None. The totals per feature add
// up to the total.
#include <array>
#include <cstddef>
#include <vector>

namespace mixengine {

/// What a move's time is booked to: CuraEngine 4.13's PrintFeatureType, in its order (the same
/// numbers as Cura's LayerPolygon line types and the time_* fields of PrintTimeMaterialEstimates).
enum class TimeFeature : std::size_t {
    None,
    OuterWall,
    InnerWall,
    Skin,
    Support,
    SkirtBrim,
    Infill,
    SupportInfill,
    Travel,      ///< travel without retraction (MoveCombing)
    Retraction,  ///< retractions, primes and travel while retracted (MoveRetraction)
    SupportInterface,
    PrimeTower,
};
constexpr std::size_t kTimeFeatureCount = 12;
using FeatureSeconds = std::array<double, kTimeFeatureCount>;

struct Kinematics {
    double acceleration_mm_s2 = 3000;                                      ///< print/travel acceleration
    std::array<double, 4> max_acceleration_mm_s2{9000, 9000, 100, 10000};  ///< X Y Z E
    std::array<double, 4> max_feedrate_mm_s{1e9, 1e9, 1e9, 1e9};           ///< X Y Z E
    double jerk_xy_mm_s = 20;
    double jerk_z_mm_s = 0.4;
    double jerk_e_mm_s = 5;
    double minimum_feedrate_mm_s = 0;
};

class TimeEstimate {
  public:
    explicit TimeEstimate(const Kinematics& kinematics) : k_(kinematics) {}

    /// A straight move by `delta` (X, Y, Z in mm, E in mm of filament — also for volumetric
    /// flavors, whose E words count mm³) at the requested feedrate, booked to `feature`.
    void addMove(const std::array<double, 4>& delta_mm, double feedrate_mm_s,
                 TimeFeature feature = TimeFeature::None);
    /// The acceleration for the following moves (M204), limited as the firmware limits it.
    void setAcceleration(double acceleration_mm_s2) { k_.acceleration_mm_s2 = acceleration_mm_s2; }
    void setJerkXy(double jerk_mm_s) { k_.jerk_xy_mm_s = jerk_mm_s; }
    /// A dwell (G4) or a heating wait: the buffered moves are planned to a stop first.
    void addDelay(double seconds);
    /// Plans the buffered moves (ending at rest) and adds their time to the total.
    void flush();
    /// Total time so far, including moves still buffered (planned as if ending at rest).
    double totalSeconds() const;
    /// The same time split by feature (the entries add up to totalSeconds()).
    FeatureSeconds secondsByFeature() const;

  private:
    struct Block {
        std::array<double, 4> unit{};  ///< direction of travel (of the E axis for E-only moves)
        double distance_mm = 0;
        double nominal_mm_s = 0;
        double acceleration_mm_s2 = 0;
        double max_entry_mm_s = 0;  ///< junction limit with the previous block
        double entry_mm_s = 0;
        TimeFeature feature = TimeFeature::None;
    };
    /// Plans `blocks` to a stop and adds each block's time to its feature in `into`.
    void plan(std::vector<Block>& blocks, FeatureSeconds& into) const;
    double junctionSpeed(const Block& previous, const Block& next) const;

    Kinematics k_;
    std::vector<Block> blocks_;
    FeatureSeconds done_s_{};
};

/// Time of a trapezoid move: from `entry` accelerate (a) towards `nominal`, decelerate to `exit`.
double trapezoidSeconds(double distance_mm, double entry_mm_s, double nominal_mm_s, double exit_mm_s,
                        double acceleration_mm_s2);

}  // namespace mixengine
