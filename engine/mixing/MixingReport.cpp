#include "mixing/MixingReport.h"

#include <algorithm>
#include <cstdio>

namespace mixengine {
namespace {

std::string fixed(double value, int decimals) {
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

std::string percent(double part, double whole) {
    return whole > 0 ? fixed(100.0 * part / whole, 1) + "%" : std::string("n/a");
}

std::string worstText(const VisiblePlace& w) {
    if (w.delta_e00 < 0)
        return "none";
    return "dE00 " + fixed(w.delta_e00, 1) + " (share off by " + fixed(w.share_distance, 3) + ") at layer " +
           std::to_string(w.layer) + " X" + fixed(micronsToMm(w.at.X), 2) + " Y" +
           fixed(micronsToMm(w.at.Y), 2) + " " + std::string(featureMarker(w.feature));
}

std::string chamberText(const ChamberSpec& c) {
    if (c.ideal())
        return "ideal (mixing_chamber_volume 0)";
    return fixed(c.volume_mm3, 1) + " mm3 in " + std::to_string(c.stages) + " stages";
}

}  // namespace

void MixingReport::add(const MixingReport& group) {
    if (!mixing) {
        *this = group;
        return;
    }
    planned = planned || group.planned;
    transitions.changes += group.transitions.changes;
    transitions.layers_with_changes += group.transitions.layers_with_changes;
    transitions.purge_mm3 += group.transitions.purge_mm3;
    transitions.needed_mm3 += group.transitions.needed_mm3;
    transitions.unpurged_mm3 += group.transitions.unpurged_mm3;
    transitions.full_change_mm3 = std::max(transitions.full_change_mm3, group.transitions.full_change_mm3);
    if (!transitions.tower)
        transitions.tower = group.transitions.tower;
    transitions.looser_needed_mm3 += group.transitions.looser_needed_mm3;
    visible.add(group.visible);
    if (sequence_hint.empty())
        sequence_hint = group.sequence_hint;
}

std::vector<std::string> MixingReport::headerLines() const {
    if (!mixing)
        return {};
    std::vector<std::string> lines{
        "MIXING.CHAMBER:" + chamberText(chamber),
        "MIXING.VISIBLE_WITHIN_DE00_3:" + percent(visible.within_de_mm, visible.visible_mm),
        "MIXING.VISIBLE_WITHIN_TOLERANCE:" + percent(visible.within_share_mm, visible.visible_mm) + " (" +
            fixed(tolerance, 3) + ")",
        "MIXING.WORST:" + worstText(visible.worst),
        "MIXING.PURGE_MM3:" + fixed(transitions.purge_mm3, 1),
        "MIXING.CHANGES:" + std::to_string(transitions.changes),
    };
    if (planned)
        lines.push_back("MIXING.PURGE_MM3_AT_TOLERANCE_" + fixed(2 * tolerance, 3) + ":" +
                        fixed(transitions.looser_needed_mm3, 1) + " (needed at " + fixed(tolerance, 3) +
                        ": " + fixed(transitions.needed_mm3, 1) + ")");
    if (transitions.unpurged_mm3 > 0.5)
        lines.push_back("MIXING.UNPURGED_MM3:" + fixed(transitions.unpurged_mm3, 1));
    if (!sequence_hint.empty())
        lines.push_back("MIXING.HINT:" + sequence_hint.substr(sequence_hint.find(':') + 2));
    return lines;
}

std::vector<std::string> MixingReport::summaryLines() const {
    if (!mixing)
        return {};
    std::vector<std::string> lines;
    lines.push_back(
        "mixing: chamber " + chamberText(chamber) + "; " + percent(visible.within_de_mm, visible.visible_mm) +
        " of the visible surface (outer walls, skin) leaves the nozzle within dE00 3 of its colour, " +
        percent(visible.within_share_mm, visible.visible_mm) + " within " + fixed(tolerance, 3) +
        " of its mix; worst: " + worstText(visible.worst));
    if (planned && transitions.changes == 0) {
        lines.push_back(
            "mixing: the mixes inside layers needed no purge: the hidden extrusions (infill, inner "
            "walls, support, raft) absorbed every change");
    } else if (planned) {
        std::string purge = "mixing: " + std::to_string(transitions.changes) +
                            " changes of mix inside layers (" +
                            std::to_string(transitions.layers_with_changes) + " layers); purge " +
                            fixed(transitions.purge_mm3, 0) + " mm3";
        if (transitions.tower)
            purge += " into a " + fixed(micronsToMm(transitions.tower->side_um), 1) + " mm purge tower";
        purge += " (one full change is " + fixed(transitions.full_change_mm3, 1) + " mm3; at tolerance " +
                 fixed(2 * tolerance, 3) + " the changes would need " +
                 fixed(transitions.looser_needed_mm3, 0) + " mm3 instead of " +
                 fixed(transitions.needed_mm3, 0) + ")";
        lines.push_back(purge);
        if (transitions.unpurged_mm3 > 0.5)
            lines.push_back(
                "mixing: " + fixed(transitions.unpurged_mm3, 0) +
                " mm3 of the changes could not be purged (no purge tower): visible surfaces after "
                "them show the previous mix");
    }
    if (!sequence_hint.empty())
        lines.push_back(sequence_hint);
    return lines;
}

}  // namespace mixengine
