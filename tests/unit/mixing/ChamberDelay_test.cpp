// Mixing-chamber delay (mixing/chamber/ChamberDelay.h): the schedule shifted earlier by the chamber volume
// along the cumulative extruded volume.
#include "mixing/chamber/ChamberDelay.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

TEST(MixingChamberDelay, NoChamberKeepsTheTargets) {
    const std::vector<int> target = {0, 0, 1, 1, 2};
    EXPECT_EQ(delayCompensated(target, {1, 1, 1, 1, 1}, 0.0), target);
}

TEST(MixingChamberDelay, ShiftsEarlierByTheChamberVolume) {
    // Ten 1 mm³ extrusions; the target changes from mix 0 to mix 1 at extrusion 6 (volume 6..7).
    std::vector<int> target(10, 0);
    for (int i = 6; i < 10; ++i)
        target[static_cast<std::size_t>(i)] = 1;
    const std::vector<double> volume(10, 1.0);
    // A 2.5 mm³ chamber: extrusion i (midpoint i + 0.5) commands the target at i + 3.0, so the switch
    // moves three extrusions earlier, to extrusion 3 (its material leaves the nozzle at volume 6..7).
    const std::vector<int> commanded = delayCompensated(target, volume, 2.5);
    EXPECT_EQ(commanded, (std::vector<int>{0, 0, 0, 1, 1, 1, 1, 1, 1, 1}));
}

TEST(MixingChamberDelay, PastTheEndTheLastTargetHolds) {
    const std::vector<int> commanded = delayCompensated({0, 1, 2}, {1, 1, 1}, 100.0);
    EXPECT_EQ(commanded, (std::vector<int>{2, 2, 2}));
}

TEST(MixingChamberDelay, FollowsVolumeNotStepCount) {
    // Small and large extrusions: the look-up walks by volume.
    const std::vector<int> target = {0, 1, 2, 3, 4};
    const std::vector<double> volume = {0.1, 0.1, 5.0, 0.1, 0.1};
    // Extrusion 0: 0.05 + 1.0 = 1.05 → inside extrusion 2 (0.2..5.2).
    // Extrusion 2: 0.2 + 2.5 + 1.0 = 3.7 → still extrusion 2. Extrusion 3: 5.25 + 1.0 → beyond: 4.
    EXPECT_EQ(delayCompensated(target, volume, 1.0), (std::vector<int>{2, 2, 2, 4, 4}));
}

}  // namespace
}  // namespace mixengine
