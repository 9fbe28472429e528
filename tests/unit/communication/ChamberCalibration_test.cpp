// The numbers of `mixengine calibrate-chamber` (communication/ChamberCalibration.h) against the analytic step
// response of stirred tanks in series, solved here by its own bisection: for N = 3 the share of the new
// filament after v mm³ is 1 − e^−t (1 + t + t²/2), t = v·N/V.
#include "communication/ChamberCalibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace mixengine {
namespace {

double threeTankResponse(double t) {
    return 1 - std::exp(-t) * (1 + t + t * t / 2);
}

/// The volume after which three tanks of `volume` together let out `fraction` of the new filament.
double analyticThreeTankVolume(double volume, double fraction) {
    double lo = 0, hi = 100;  // in tank volumes
    for (int i = 0; i < 200; ++i) {
        const double mid = (lo + hi) / 2;
        (threeTankResponse(mid) < fraction ? lo : hi) = mid;
    }
    return (lo + hi) / 2 * volume / 3;
}

CalibrationTower tower(double per_mm) {
    CalibrationTower t;
    t.switch1_mm = 10;
    t.switch2_mm = 25;
    t.per_mm_mm3 = per_mm;
    t.filament_a = "filament 1 (#ffffff)";
    t.filament_b = "filament 2 (#000000)";
    return t;
}

/// The table row "N V h10 h50 h90" of the guide, as numbers (empty when absent).
std::vector<double> tableRow(const std::vector<std::string>& guide, int stages, double volume) {
    char key[32];
    std::snprintf(key, sizeof key, "  %4d  %5.0f ", stages, volume);
    for (const std::string& line : guide) {
        if (line.rfind(key, 0) != 0)
            continue;
        std::istringstream in(line);
        std::vector<double> numbers;
        double x = 0;
        while (in >> x)
            numbers.push_back(x);
        return numbers;
    }
    return {};
}

TEST(ChamberCalibration, ThreeStagePointsAreTheAnalyticStepResponse) {
    for (double volume : {10.0, 40.0, 75.0, 120.0}) {
        const StepPoints p = stepPoints(ChamberSpec{volume, 3});
        EXPECT_NEAR(p.v10, analyticThreeTankVolume(volume, 0.1), 1e-5) << volume;
        EXPECT_NEAR(p.v50, analyticThreeTankVolume(volume, 0.5), 1e-5) << volume;
        EXPECT_NEAR(p.v90, analyticThreeTankVolume(volume, 0.9), 1e-5) << volume;
        // and the response at the found volumes is the fraction asked for
        EXPECT_NEAR(threeTankResponse(p.v10 * 3 / volume), 0.1, 1e-6);
        EXPECT_NEAR(threeTankResponse(p.v90 * 3 / volume), 0.9, 1e-6);
    }
    // Gamma(3) quantiles from tables: 1.1021 (10 %), 2.6741 (50 %), 5.3223 (90 %) tank volumes.
    const StepPoints unit = stepPoints(ChamberSpec{3.0, 3});
    EXPECT_NEAR(unit.v10, 1.1021, 1e-4);
    EXPECT_NEAR(unit.v50, 2.6741, 1e-4);
    EXPECT_NEAR(unit.v90, 5.3223, 1e-4);
}

TEST(ChamberCalibration, OneStageIsTheExponential) {
    const StepPoints p = stepPoints(ChamberSpec{40, 1});
    EXPECT_NEAR(p.v10, -40 * std::log(0.9), 1e-5);
    EXPECT_NEAR(p.v50, 40 * std::log(2.0), 1e-5);
    EXPECT_NEAR(p.v90, 40 * std::log(10.0), 1e-5);
}

TEST(ChamberCalibration, TableHeightsAreVolumesOverTheExtrusionPerMm) {
    const double per_mm = 12.16;
    const std::vector<std::string> guide = calibrationGuide(tower(per_mm));
    for (double volume : {10.0, 40.0, 100.0}) {
        const std::vector<double> row = tableRow(guide, 3, volume);
        ASSERT_EQ(row.size(), 5u) << volume;
        EXPECT_NEAR(row[2], analyticThreeTankVolume(volume, 0.1) / per_mm, 0.006) << volume;
        EXPECT_NEAR(row[3], analyticThreeTankVolume(volume, 0.5) / per_mm, 0.006) << volume;
        EXPECT_NEAR(row[4], analyticThreeTankVolume(volume, 0.9) / per_mm, 0.006) << volume;
    }
    // every candidate is in the table
    for (int n : candidateStages())
        for (double v : candidateVolumesMm3())
            EXPECT_FALSE(tableRow(guide, n, v).empty()) << n << " " << v;
}

TEST(ChamberCalibration, HeightsBeyondTheBandAreMarked) {
    // one stage of 120 mm³ reaches 90 % after 276 mm³: 22.7 mm at 12.16 mm³/mm, more than the 15 mm band
    const std::vector<std::string> guide = calibrationGuide(tower(12.16));
    bool marked = false;
    for (const std::string& line : guide)
        marked = marked || (line.rfind("     1    120 ", 0) == 0 && line.find(">15.0") != std::string::npos);
    EXPECT_TRUE(marked);
}

TEST(ChamberCalibration, RuleOfThumbHoldsOnTheModel) {
    // the 50 % point near V (1 − 1/(3N)): within 4 % at N = 1, 1 % at N = 2, 0.3 % from N = 3
    double previous_width = 1e9, previous_ratio = 1e9;
    for (int n : candidateStages()) {
        const StepPoints p = stepPoints(ChamberSpec{1.0, n});
        const double rule = 1 - 1.0 / (3 * n);
        const double bound = n == 1 ? 0.04 : n == 2 ? 0.01 : 0.003;
        EXPECT_LT(std::abs(p.v50 / rule - 1), bound) << n;
        // the 10–90 % width narrows with N, as about 2.2..2.6 V / sqrt(N); 90/10 identifies N
        const double width = p.v90 - p.v10;
        EXPECT_LT(width, previous_width) << n;
        EXPECT_GT(width * std::sqrt(n), 2.1) << n;
        EXPECT_LT(width * std::sqrt(n), 2.6) << n;
        EXPECT_LT(p.v90 / p.v10, previous_ratio) << n;
        previous_width = width;
        previous_ratio = p.v90 / p.v10;
    }
}

TEST(ChamberCalibration, IdealChamberAndFullChange) {
    EXPECT_EQ(volumeToFraction(ChamberSpec{0, 3}, 0.5), 0.0);
    EXPECT_EQ(volumeToFraction(ChamberSpec{40, 3}, 0.0), 0.0);
    EXPECT_TRUE(std::isinf(volumeToFraction(ChamberSpec{40, 3}, 1.0)));
}

TEST(ChamberCalibration, GuideNamesTheProfilesPrediction) {
    CalibrationTower t = tower(10.0);
    t.current = ChamberSpec{40, 3};
    const std::vector<std::string> guide = calibrationGuide(t);
    char expected[128];
    std::snprintf(expected, sizeof expected, "%.2f / %.2f / %.2f mm", analyticThreeTankVolume(40, 0.1) / 10,
                  analyticThreeTankVolume(40, 0.5) / 10, analyticThreeTankVolume(40, 0.9) / 10);
    bool found = false;
    for (const std::string& line : guide)
        found = found || line.find(expected) != std::string::npos;
    EXPECT_TRUE(found) << expected;
}

}  // namespace
}  // namespace mixengine
