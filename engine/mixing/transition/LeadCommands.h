#pragma once
// Commands that lead the chamber (issue 27). A field that changes along a layer (a gradient along X, Y
// or radially, a feathered edge) asks the chamber for a mix that changes every few mm³, far faster than
// the tens of mm³ it smears a change over. Commanding each extrusion the mix it asks for leaves the
// outlet a chamber volume behind the field; commanding ahead of it, and overshooting in the hidden
// extrusions in between, lets the outlet follow the field where it shows.
//
// The chamber is linear in what is commanded (mixing/chamber/ChamberModel.h: a push maps the tanks' contents
// and the inlet affinely), so the commands solve a convex problem:
//
//   minimise   Σ over asked cells  weight · Σ over channels  max(0, |outlet − asked| − margin)²
//   over       commands that are mixes (each cell's shares ≥ 0 and adding up to 1),
//
// the outlet being the average of what leaves the nozzle over the cell. It is solved by accelerated
// projected gradient (FISTA): each iteration is one pass forward through the chamber and one backward
// through its adjoint, O(cells × the pushes' reach) — no matrices. Within the margin a cell costs
// nothing, so the solution keeps the outlet near the field and spends the freedom where it is needed.
//
// A cell is one extrusion, or one piece of a purge, printed with one command. A cell with weight 0 (a
// hidden extrusion, the purge) asks for nothing: it takes whatever command helps the asked ones.
#include <vector>

#include "mixing/chamber/ChamberModel.h"

namespace mixengine {

struct FlowCell {
    double volume_mm3 = 0;
    double weight = 0;   ///< how much its outlet counts (its volume, say); 0: free
    MixVector asked;     ///< the mix it should leave the nozzle in (read when weight > 0)
    double margin = -1;  ///< share distance it may be off at no cost; < 0: LeadSettings::margin
};

struct LeadSettings {
    ChamberSpec chamber;
    double margin = 0.05;  ///< share distance an asked cell may be off at no cost
    int iterations = 300;
};

/// The command of every cell. `tanks`: the chamber's contents before the first cell, inlet first
/// (ChamberSpec::stages of them); `start`: a first guess, one mix per cell (leadingGuess).
std::vector<MixVector> leadCommands(const std::vector<FlowCell>& cells, const std::vector<MixVector>& tanks,
                                    std::vector<MixVector> start, const LeadSettings& settings);

/// The average mix that leaves the nozzle over each cell when it is commanded `commands`.
std::vector<MixVector> outletsOf(const std::vector<FlowCell>& cells, const std::vector<MixVector>& tanks,
                                 const std::vector<MixVector>& commands, const ChamberSpec& chamber);

/// A first guess: each cell commanded the mix asked `lead_mm3` of flow after its middle (the nearest
/// asked cell at or after that point; the last asked mix beyond the end; `fallback` when none is asked).
std::vector<MixVector> leadingGuess(const std::vector<FlowCell>& cells, double lead_mm3,
                                    const MixVector& fallback);

}  // namespace mixengine
