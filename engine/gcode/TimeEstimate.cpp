#include "gcode/TimeEstimate.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mixengine {

double trapezoidSeconds(double distance, double entry, double nominal, double exit, double accel) {
    if (distance <= 0)
        return 0;
    if (accel <= 0)
        return distance / std::max(nominal, 1e-9);
    entry = std::min(entry, nominal);
    exit = std::min(exit, nominal);
    const double accel_distance = (nominal * nominal - entry * entry) / (2 * accel);
    const double decel_distance = (nominal * nominal - exit * exit) / (2 * accel);
    if (accel_distance + decel_distance <= distance) {
        const double cruise = distance - accel_distance - decel_distance;
        return (nominal - entry) / accel + cruise / nominal + (nominal - exit) / accel;
    }
    // No cruise: the peak speed where acceleration and deceleration meet.
    const double peak_sq = (2 * accel * distance + entry * entry + exit * exit) / 2;
    const double peak = std::sqrt(std::max(peak_sq, std::max(entry * entry, exit * exit)));
    return (peak - entry) / accel + (peak - exit) / accel;
}

void TimeEstimate::addMove(const std::array<double, 4>& delta, double feedrate, TimeFeature feature) {
    const double xyz = std::sqrt(delta[0] * delta[0] + delta[1] * delta[1] + delta[2] * delta[2]);
    const double distance = xyz > 0 ? xyz : std::fabs(delta[3]);
    if (distance <= 0 || feedrate <= 0)
        return;
    Block block;
    block.distance_mm = distance;
    block.feature = feature;
    double nominal = std::max(feedrate, k_.minimum_feedrate_mm_s);
    double accel = k_.acceleration_mm_s2;
    for (int axis = 0; axis < 4; ++axis) {
        block.unit[axis] = delta[axis] / distance;
        const double share = std::fabs(block.unit[axis]);
        if (share <= 0)
            continue;
        nominal = std::min(nominal, k_.max_feedrate_mm_s[axis] / share);
        accel = std::min(accel, k_.max_acceleration_mm_s2[axis] / share);
    }
    block.nominal_mm_s = nominal;
    block.acceleration_mm_s2 = accel;
    block.max_entry_mm_s =
        blocks_.empty() ? std::min(nominal, k_.jerk_xy_mm_s / 2) : junctionSpeed(blocks_.back(), block);
    blocks_.push_back(block);
}

double TimeEstimate::junctionSpeed(const Block& previous, const Block& next) const {
    // The largest v ≤ both nominal speeds for which the velocity change at the corner stays
    // within the jerk limits of each axis group.
    double v = std::min(previous.nominal_mm_s, next.nominal_mm_s);
    const double dx = next.unit[0] * v - previous.unit[0] * v;
    const double dy = next.unit[1] * v - previous.unit[1] * v;
    const double jump_xy = std::hypot(dx, dy);
    if (jump_xy > k_.jerk_xy_mm_s)
        v *= k_.jerk_xy_mm_s / jump_xy;
    const double jump_z = std::fabs(next.unit[2] - previous.unit[2]) * v;
    if (jump_z > k_.jerk_z_mm_s)
        v *= k_.jerk_z_mm_s / jump_z;
    const double jump_e = std::fabs(next.unit[3] - previous.unit[3]) * v;
    if (jump_e > k_.jerk_e_mm_s)
        v *= k_.jerk_e_mm_s / jump_e;
    return v;
}

void TimeEstimate::plan(std::vector<Block>& blocks, FeatureSeconds& into) const {
    // Backward pass: each block must be able to decelerate to the next block's entry speed.
    double next_entry = 0;  // at rest after the last block
    for (std::size_t i = blocks.size(); i-- > 0;) {
        Block& b = blocks[i];
        const double reachable =
            std::sqrt(next_entry * next_entry + 2 * b.acceleration_mm_s2 * b.distance_mm);
        b.entry_mm_s = std::min(b.max_entry_mm_s, reachable);
        next_entry = b.entry_mm_s;
    }
    // Forward pass: each block's exit is limited by what it can accelerate to.
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        Block& b = blocks[i];
        double exit = i + 1 < blocks.size() ? blocks[i + 1].entry_mm_s : 0;
        const double reachable =
            std::sqrt(b.entry_mm_s * b.entry_mm_s + 2 * b.acceleration_mm_s2 * b.distance_mm);
        exit = std::min(exit, reachable);
        if (i + 1 < blocks.size())
            blocks[i + 1].entry_mm_s = exit;
        into[static_cast<std::size_t>(b.feature)] +=
            trapezoidSeconds(b.distance_mm, b.entry_mm_s, b.nominal_mm_s, exit, b.acceleration_mm_s2);
    }
}

void TimeEstimate::addDelay(double seconds) {
    flush();
    done_s_[static_cast<std::size_t>(TimeFeature::None)] += std::max(seconds, 0.0);
}

void TimeEstimate::flush() {
    plan(blocks_, done_s_);
    blocks_.clear();
}

FeatureSeconds TimeEstimate::secondsByFeature() const {
    FeatureSeconds seconds = done_s_;
    std::vector<Block> copy = blocks_;
    plan(copy, seconds);
    return seconds;
}

double TimeEstimate::totalSeconds() const {
    const FeatureSeconds seconds = secondsByFeature();
    return std::accumulate(seconds.begin(), seconds.end(), 0.0);
}

}  // namespace mixengine
