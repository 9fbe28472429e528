#pragma once
// What a user needs to trust a mixing print (issue 26), for the G-code header and the command line:
// the chamber, the share of the visible surface that leaves the nozzle within ΔE00 ≤ 3 of its colour,
// the worst place, the purge planned and what a looser tolerance would save, and whether printing the
// models one at a time would avoid the changes.
#include <string>
#include <vector>

#include "mixing/transition/OutletPrediction.h"
#include "mixing/transition/TransitionPlan.h"

namespace mixengine {

struct MixingReport {
    bool mixing = false;  ///< false: single mode, nothing to report
    ChamberSpec chamber;
    double tolerance = 0.1;
    bool planned = false;  ///< transitions were planned (a mix changes inside a layer)
    TransitionReport transitions;
    VisibleReport visible;
    std::string sequence_hint;  ///< "print_sequence one_at_a_time would …" (empty: nothing to say)

    /// Adds a later mesh group's report.
    void add(const MixingReport& group);
    /// ";MIXING.…" header lines without the ';' (empty when not mixing).
    std::vector<std::string> headerLines() const;
    /// "mixing: …" lines for the command line (empty when not mixing).
    std::vector<std::string> summaryLines() const;
};

}  // namespace mixengine
