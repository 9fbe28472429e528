// Writing planned layers (gcode/PlanWriter.h): one chunk per layer, ;LAYER:n first and
// ;TIME_ELAPSED: (6 decimals, cumulative) last.
#include "gcode/PlanWriter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <regex>

namespace mixengine {
namespace {

PlanStep step(PlanStep::Kind kind) {
    PlanStep s;
    s.kind = kind;
    return s;
}

PlanStep travel(Point2 to, bool retract = false) {
    PlanStep s = step(PlanStep::Kind::Travel);
    s.to = to;
    s.speed_mm_s = 150;
    s.retract = retract;
    return s;
}

PlanStep extrude(Point2 to, double volume) {
    PlanStep s = step(PlanStep::Kind::Extrude);
    s.to = to;
    s.speed_mm_s = 30;
    s.volume_mm3 = volume;
    return s;
}

PrintPlan twoLayerPlan() {
    PrintPlan plan;
    plan.mesh_names = {"cube.stl"};
    PlannedLayer first;
    first.index = 0;
    first.z = 300;
    PlanStep fan = step(PlanStep::Kind::SetFan);
    fan.fan_ratio = 1.0;
    PlanStep mesh = step(PlanStep::Kind::SetMesh);
    mesh.mesh_index = 0;
    PlanStep feature = step(PlanStep::Kind::SetFeature);
    feature.feature = Feature::WallOuter;
    first.steps = {fan, mesh, feature, travel({10'000, 10'000}), extrude({20'000, 10'000}, 0.5)};
    PlannedLayer second;
    second.index = 1;
    second.z = 500;
    PlanStep nonmesh = step(PlanStep::Kind::SetMesh);
    nonmesh.mesh_index = -1;
    second.steps = {nonmesh, travel({20'000, 30'000}, true), extrude({5'000, 30'000}, 0.25)};
    plan.layers = {first, second};
    return plan;
}

ExportParams params() {
    ExportParams p;
    p.filament_diameter_mm = 1.75;
    p.flavor = flavorTraits(Flavor::MarlinVolumetric);  // E equals the volume: easy to read
    p.retraction_amount_mm = 1.0;
    p.retraction_speed_mm_s = 25;
    p.prime_speed_mm_s = 25;
    p.z_hop_speed_mm_s = 10;
    // Acceleration and jerk so high that every move takes distance / speed: easy to check.
    p.kinematics.acceleration_mm_s2 = 1e12;
    p.kinematics.max_acceleration_mm_s2 = {1e12, 1e12, 1e12, 1e12};
    p.kinematics.jerk_xy_mm_s = p.kinematics.jerk_z_mm_s = p.kinematics.jerk_e_mm_s = 1e9;
    return p;
}

TEST(GCodePlanWriter, ExactFirstChunk) {
    GCodeExport gcode(params());
    const WrittenLayers written = writePlan(twoLayerPlan(), PlanWriterParams{}, gcode);
    ASSERT_EQ(written.chunks.size(), 2U);
    // 0.3 mm Z at 10 mm/s + √200 mm travel at 150 mm/s + 10 mm extrusion at 30 mm/s.
    char elapsed[64];
    std::snprintf(elapsed, sizeof elapsed, "%.6f", 0.03 + std::sqrt(200.0) / 150.0 + 10.0 / 30.0);
    EXPECT_STREQ(elapsed, "0.457614");
    EXPECT_EQ(written.chunks[0],
              ";LAYER:0\n"
              "G92 E0\n"
              "G0 F600 Z0.3\n"
              "M106 S255\n"
              ";MESH:cube.stl\n"
              ";TYPE:WALL-OUTER\n"
              "G0 F9000 X10 Y10\n"
              "G1 F1800 X20 Y10 E0.5\n"
              ";TIME_ELAPSED:0.457614\n");
}

TEST(GCodePlanWriter, LayerFirstTimeLastInEveryChunk) {
    GCodeExport gcode(params());
    const WrittenLayers written = writePlan(twoLayerPlan(), PlanWriterParams{}, gcode);
    const std::regex time_line(";TIME_ELAPSED:[0-9]+\\.[0-9]{6}\n$");
    double previous = -1;
    for (std::size_t i = 0; i < written.chunks.size(); ++i) {
        const std::string& chunk = written.chunks[i];
        EXPECT_EQ(chunk.rfind(";LAYER:" + std::to_string(i) + "\n", 0), 0U) << chunk;
        EXPECT_TRUE(std::regex_search(chunk, time_line)) << chunk;
        const double time = std::stod(chunk.substr(chunk.rfind(":") + 1));
        EXPECT_GT(time, previous);
        previous = time;
    }
    EXPECT_NE(written.chunks[1].find(";MESH:NONMESH\n"), std::string::npos) << written.chunks[1];
    EXPECT_NE(written.chunks[1].find("G0 F600 Z0.5\n"), std::string::npos) << written.chunks[1];
}

TEST(GCodePlanWriter, LayerWithNothingToPrintIsLeftOut) {
    // As CuraEngine 4.13: no ;LAYER: line, Z move or time for it; its chunk is empty, and the next
    // layer keeps its number and moves to its own height.
    PrintPlan plan = twoLayerPlan();
    PlannedLayer empty;
    empty.index = 1;
    empty.z = 500;
    PlanStep mesh = step(PlanStep::Kind::SetMesh);
    mesh.mesh_index = 0;
    empty.steps = {step(PlanStep::Kind::SetFan), mesh, step(PlanStep::Kind::SetFeature)};
    plan.layers.insert(plan.layers.begin() + 1, empty);
    plan.layers[2].index = 2;
    plan.layers[2].z = 700;
    GCodeExport gcode(params());
    const WrittenLayers written = writePlan(plan, PlanWriterParams{}, gcode);
    ASSERT_EQ(written.chunks.size(), 3U);
    EXPECT_TRUE(written.chunks[1].empty()) << written.chunks[1];
    EXPECT_EQ(written.chunks[2].rfind(";LAYER:2\n", 0), 0U) << written.chunks[2];
    EXPECT_NE(written.chunks[2].find("G0 F600 Z0.7\n"), std::string::npos) << written.chunks[2];
}

TEST(GCodePlanWriter, BoundsOfExtrudedMoves) {
    GCodeExport gcode(params());
    const WrittenLayers written = writePlan(twoLayerPlan(), PlanWriterParams{}, gcode);
    EXPECT_EQ(written.min, (Point3{5'000, 10'000, 300}));
    EXPECT_EQ(written.max, (Point3{20'000, 30'000, 500}));
}

TEST(GCodePlanWriter, NegativeLayerNumbersAndNoReset) {
    PrintPlan plan;
    PlannedLayer raft;
    raft.index = -2;
    raft.z = 200;
    raft.steps = {extrude({1'000, 0}, 0.1)};
    plan.layers = {raft};
    ExportParams no_reset = params();
    no_reset.flavor.resets_e_each_layer = false;
    GCodeExport gcode(no_reset);
    PlanWriterParams p;
    const WrittenLayers written = writePlan(plan, p, gcode);
    ASSERT_EQ(written.chunks.size(), 1U);
    EXPECT_EQ(written.chunks[0].rfind(";LAYER:-2\nG0 F600 Z0.2\nG1 F1800 X1 Y0 E0.1\n;TIME_ELAPSED:", 0), 0U)
        << written.chunks[0];
}

TEST(GCodePlanWriter, RetractedTravelAndResetAcrossLayers) {
    GCodeExport gcode(params());
    const WrittenLayers written = writePlan(twoLayerPlan(), PlanWriterParams{}, gcode);
    const std::string& second = written.chunks[1];
    // E is reset at the layer start, then the retraction, the travel and the prime follow.
    const auto reset = second.find("G92 E0\n");
    const auto retract = second.find("G1 F1500 E-2.40528\n");  // 1 mm of 1.75 mm filament, in mm³
    const auto move = second.find("G0 F9000 X20 Y30\n");
    const auto prime = second.find("G1 F1500 E0\n");
    ASSERT_NE(prime, std::string::npos) << second;
    EXPECT_LT(reset, retract) << second;
    EXPECT_LT(retract, move) << second;
    EXPECT_LT(move, prime) << second;
    EXPECT_NE(second.find("G1 F1800 X5 Y30 E0.25\n"), std::string::npos) << second;
}

PlanStep nozzle(int extruder, double celsius, bool wait) {
    PlanStep s = step(PlanStep::Kind::SetNozzleTemperature);
    s.extruder = extruder;
    s.temperature_c = celsius;
    s.wait = wait;
    return s;
}

// A tool change as CuraEngine 4.13 writes it: the old extruder's switch retraction (2 mm at 20 mm/s,
// E in mm³ here), E reset, its end code, T1, E reset, the new one's start code; then the temperature
// steps the planner put after the switch (wait for T1, T0 to standby). X/Y are then relative to the new
// nozzle (offset subtracted), its first extrusion primes the switch's extra prime at its own prime
// speed, and filament is counted per extruder.
TEST(GCodePlanWriter, ToolChangeWithNozzleOffset) {
    PrintPlan plan;
    PlannedLayer layer;
    layer.z = 300;
    PlanStep change = step(PlanStep::Kind::SetExtruder);
    change.extruder = 1;
    layer.steps = {extrude({1'000, 0}, 0.5), change,
                   nozzle(1, 210, true),     nozzle(0, 150, false),
                   travel({11'000, 0}),      extrude({12'000, 0}, 0.25)};
    plan.layers = {layer};
    PlanWriterParams p;
    p.extruders.resize(2);
    p.extruders[0].end_code = "G91";
    p.extruders[0].switch_retraction = {2.0, 20, 15, 0};
    p.extruders[1].change = {1, 1.75, {10'000, 0}, {1.0, 25, 25, 0}, 0};
    p.extruders[1].start_code = "G90\n";
    p.extruders[1].switch_extra_prime_mm3 = 0.5;
    GCodeExport gcode(params());
    const std::string chunk = writePlan(plan, p, gcode).chunks.at(0);
    const std::string expected =
        "G1 F1800 X1 Y0 E0.5\nG1 F1200 E-4.31056\nG92 E0\nG91\nT1\nG92 E0\nG90\nM109 S210\nM104 T0 S150\n"
        "G0 F9000 X1 Y0\nG1 F1500 E0.5\nG1 F1800 X2 Y0 E0.75\n";
    EXPECT_NE(chunk.find(expected), std::string::npos) << chunk;
    const std::vector<double> filament = gcode.filamentPerExtruder();
    ASSERT_EQ(filament.size(), 2U);
    EXPECT_NEAR(filament[0], 0.5, 1e-9);
    EXPECT_NEAR(filament[1], 0.75, 1e-9);  // the extra prime is material out of the nozzle too
}

// Coming back to an extruder left with a longer switch retraction: its next travel retraction primes the
// difference back at the switch's prime speed (CuraEngine's "G1 F900 E1.5" on the Ultimaker S5), and
// its next extrusion primes the rest at its own prime speed.
TEST(GCodePlanWriter, BackToAnExtruderLeftWithTheSwitchRetraction) {
    ExportParams e = params();
    e.flavor = flavorTraits(Flavor::Marlin);
    e.retraction_amount_mm = 6.5;
    e.retraction_speed_mm_s = 25;
    e.prime_speed_mm_s = 15;
    PlanStep to1 = step(PlanStep::Kind::SetExtruder);
    to1.extruder = 1;
    PlanStep to0 = step(PlanStep::Kind::SetExtruder);
    to0.extruder = 0;
    PlannedLayer layer;
    layer.z = 300;
    layer.steps = {extrude({1'000, 0}, 0.5), to1, extrude({2'000, 0}, 0.5), to0, travel({9'000, 0}, true),
                   extrude({10'000, 0}, 0.5)};
    PrintPlan plan;
    plan.layers = {layer};
    PlanWriterParams p;
    p.extruders.resize(2);
    for (int i = 0; i < 2; ++i) {
        p.extruders[static_cast<std::size_t>(i)].change = {i, 1.75, {0, 0}, {6.5, 25, 15, 0}, 0};
        p.extruders[static_cast<std::size_t>(i)].switch_retraction = {8.0, 20, 15, 0};
    }
    GCodeExport gcode(e);
    const std::string chunk = writePlan(plan, p, gcode).chunks.at(0);
    const auto back = chunk.find("T0\nG92 E0\nG1 F900 E1.5\n");
    ASSERT_NE(back, std::string::npos) << chunk;
    EXPECT_NE(chunk.find("G0 F9000 X9 Y0\nG1 F900 E8\n", back), std::string::npos) << chunk;
}

}  // namespace
}  // namespace mixengine
