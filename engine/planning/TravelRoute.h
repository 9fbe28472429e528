#pragma once
// The way one travel goes and whether it retracts, as CuraEngine 4.13 decides (LayerPlan::addTravel
// with its Comb), in outline:
//   - a travel longer than retraction_min_travel that stays inside the comb area (the combing
//     mode's area, planning/PrintPlanner.h; ends up to comb_move_inside_um outside it are first
//     moved in) combs along it without retracting — unless the combed way is longer than
//     retraction_combing_max_distance;
//   - a mesh travel between two islands of the comb area (or from or to a point outside it) goes as
//     CuraEngine's Comb between parts: combed inside the part it starts in to where it leaves it —
//     the point of that part's boundary near the straight way that is nearest to the other end —
//     then with travel_avoid_other_parts out of the grown outlines (travel_avoid_distance, `free`
//     below) there, around the parts through `free` and in again (straight across when that is
//     shorter than the two crossings, or when the leaving and entering points lie closer than
//     twice the comb offset plus the avoid distance), then combed inside the part it ends in; it
//     retracts;
//   - otherwise it goes through the air: with travel_avoid_other_parts around the parts, leaving
//     the part it starts on and entering the one it ends on straight; and it retracts when longer
//     than retraction_min_travel — except, with limit_support_retractions, a travel that neither
//     starts nor ends in a part and crosses none (support to support);
//   - a retracting travel to a mesh path whose end lies outside the comb area (an outer wall's
//     start) goes to that end moved into the comb area first and primes there, before its last move
//     (CuraEngine's unretract_before_last_travel_move; through the air: after entering the part);
//   - a travel no longer than retraction_min_travel never retracts; it goes straight when shorter
//     than short_comb_min_um (CuraEngine's comb ignores travels shorter than the nozzle tip's outer
//     diameter), else the way it would go if longer (combed, or between parts), without retracting;
//   - meshfix_maximum_travel_resolution: a way point of a combed or around-the-parts travel closer
//     than that to the way point kept before it is left out (the travel's end is always kept).
#include <optional>

#include "geometry/Point.h"
#include "planning/CombBoundary.h"

namespace mixengine {

struct TravelParams {
    double travel_speed_mm_s = 150;
    bool retraction_enable = true;
    coord_um retraction_min_travel_um = 1500;
    /// Travels shorter than this go straight (CuraEngine: machine_nozzle_tip_outer_diameter, an
    /// even number of microns); longer ones follow the comb area even when too short to retract.
    coord_um short_comb_min_um = 1000;
    coord_um layer_thickness_um = 200;
    const CombBoundary* comb = nullptr;  ///< mesh travels: where they comb; nullptr for the rest
    /// How far outside the comb area a travel's end may lie and still comb, moved straight to the
    /// nearest point inside (CuraEngine: twice its comb offset, 4 innermost wall widths).
    coord_um comb_move_inside_um = 0;
    /// travel_avoid_other_parts: the space outside every part grown by travel_avoid_distance
    /// (nullptr: through-air travel goes straight).
    const CombBoundary* free = nullptr;
    coord_um avoid_distance_um = 0;  ///< travel_avoid_distance
    bool limit_support_retractions = false;
    coord_um combing_max_distance_um = 0;  ///< 0 = a combed travel never retracts
    coord_um wall_0_wipe_um = 0;           ///< wall_0_wipe_dist: travel on along an outer wall loop's start
    coord_um infill_wipe_um = 0;           ///< infill_wipe_dist: travel on past the end of an infill line
    /// The nearest path is first looked for from here instead of the head (the travel still starts
    /// at the head): infill_randomize_start_location.
    std::optional<Point2> order_from;
    /// infill_enable_travel_optimization: a path whose end cannot be reached straight inside the
    /// comb boundary counts at the length of its comb route (100 × the straight distance when there
    /// is none), as CuraEngine's line order optimizer with a combing boundary.
    bool comb_aware_order = false;
    coord_um max_travel_resolution_um = 0;  ///< meshfix_maximum_travel_resolution (0: every point)
};

struct TravelRoute {
    Path points;  ///< after `from`, ending with `to`
    bool retract = false;
    bool prime_before_last = false;  ///< prime (unretract) before the move to points.back()
};

TravelRoute planTravel(const Point2& from, const Point2& to, const TravelParams& params);

/// Around the parts: `from` → where the way to `to` leaves the part it starts in (if any) → around
/// the other parts inside `free` → where it enters the part `to` is in → `to`; nothing when no such
/// way is found.
std::optional<Path> aroundParts(const CombBoundary& free, const Point2& from, const Point2& to);

/// `points` (a travel's way after `from`, its end last) without the way points no farther than
/// `resolution_um` from the point kept before them (`from` first); a first point `first_kept` (a
/// start moved into the comb area) and the end are always kept.
Path thinTravel(const Point2& from, const Path& points, coord_um resolution_um, bool first_kept);

}  // namespace mixengine
