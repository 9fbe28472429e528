// `mixengine layers` on a mixing print: the plan's extrusions by predicted colour
// (communication/LayerColours.h).
#include "communication/LayerColours.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace mixengine {
namespace {

PlanStep travel(Point2 to) {
    PlanStep step;
    step.kind = PlanStep::Kind::Travel;
    step.to = to;
    return step;
}

PlanStep extrude(Point2 to, int color, double volume = 0.1, coord_um width = 400) {
    PlanStep step;
    step.kind = PlanStep::Kind::Extrude;
    step.to = to;
    step.outlet_color = color;
    step.volume_mm3 = volume;
    step.width_um = width;
    return step;
}

PrintPlan twoLayerPlan() {
    PrintPlan plan;
    plan.outlet_colors = {{255, 255, 0}, {0, 138, 85}};
    PlannedLayer raft{-1, 300, 0, {}, -1};
    raft.steps = {travel({0, 0}), extrude({10'000, 0}, 0)};
    PlannedLayer first{0, 500, 0, {}, -1};
    // Goes on from where the raft ended; a width change and a colour change start new runs.
    first.steps = {extrude({10'000, 5'000}, 0), extrude({0, 5'000}, 0),          extrude({0, 0}, 0, 0.1, 600),
                   extrude({3'000, 0}, 1),      extrude({3'000, 4'000}, 1, 0.0), travel({6'000, 0}),
                   extrude({6'000, 4'000}, 1)};
    plan.layers = {raft, first};
    return plan;
}

TEST(LayerColours, JoinsRunsAndAddsLengthsPerColourFollowingTheHeadAcrossLayers) {
    const std::vector<ColouredLayer> layers = colouredLayers(twoLayerPlan());
    ASSERT_EQ(layers.size(), 2U);
    EXPECT_EQ(layers[0].index, -1);
    ASSERT_EQ(layers[0].runs.size(), 1U);
    EXPECT_EQ(layers[0].runs[0].points, (Path{{0, 0}, {10'000, 0}}));

    const ColouredLayer& first = layers[1];
    EXPECT_EQ(first.index, 0);
    EXPECT_EQ(first.z, 500);
    ASSERT_EQ(first.runs.size(), 4U);
    EXPECT_EQ(first.runs[0].points, (Path{{10'000, 0}, {10'000, 5'000}, {0, 5'000}}));
    EXPECT_EQ(first.runs[1].width_um, 600);
    EXPECT_EQ(first.runs[1].points, (Path{{0, 5'000}, {0, 0}}));
    EXPECT_EQ(first.runs[2].color, 1);
    EXPECT_EQ(first.runs[2].points, (Path{{0, 0}, {3'000, 0}}));  // the move without volume is no extrusion
    EXPECT_EQ(first.runs[3].points, (Path{{6'000, 0}, {6'000, 4'000}}));
    ASSERT_EQ(first.lengths_mm.size(), 2U);
    EXPECT_EQ(first.lengths_mm[0].first, 0);
    EXPECT_DOUBLE_EQ(first.lengths_mm[0].second, 5 + 10 + 5);
    EXPECT_EQ(first.lengths_mm[1].first, 1);
    EXPECT_DOUBLE_EQ(first.lengths_mm[1].second, 3 + 4);
}

TEST(LayerColours, ExtrusionBeforeAnyKnownHeadPositionIsLeftOut) {
    PrintPlan plan;
    plan.outlet_colors = {{1, 2, 3}};
    PlannedLayer layer{0, 200, 0, {}, -1};
    layer.steps = {extrude({1'000, 0}, 0), extrude({2'000, 0}, 0)};
    plan.layers = {layer};
    const std::vector<ColouredLayer> layers = colouredLayers(plan);
    ASSERT_EQ(layers[0].runs.size(), 1U);
    EXPECT_EQ(layers[0].runs[0].points, (Path{{1'000, 0}, {2'000, 0}}));
    EXPECT_EQ(colourHex(plan.outlet_colors[0]), "#010203");
}

TEST(LayerColours, SvgDrawsEachRunInItsColourAndWidthOverTheOutline) {
    const PrintPlan plan = twoLayerPlan();
    const std::vector<ColouredLayer> layers = colouredLayers(plan);
    SlicedLayer outline;
    outline.outlines = {{{0, 0}, {10'000, 0}, {10'000, 5'000}, {0, 5'000}}};
    const std::string svg = colouredLayerSvg(outline, &layers[1], plan.outlet_colors);
    EXPECT_NE(svg.find("<g class=\"extrusions\""), std::string::npos);
    EXPECT_NE(svg.find("stroke=\"#ffff00\" stroke-width=\"0.600\""), std::string::npos);
    EXPECT_NE(svg.find("stroke=\"#008a55\" stroke-width=\"0.400\""), std::string::npos);
    EXPECT_NE(svg.find(";LAYER:0 — 27.0 mm extruded in 2 predicted colours"), std::string::npos);
    // The drawing holds the lines' half widths: from x −0.3 mm (half of 0.6) to 10.2 mm (half of 0.4), and 2
    // mm margins.
    EXPECT_NE(svg.find("viewBox=\"0 0 14.500 "), std::string::npos);

    const std::string empty = colouredLayerSvg(outline, nullptr, plan.outlet_colors);
    EXPECT_EQ(empty.find("extrusions"), std::string::npos);
    EXPECT_NE(empty.find("not printed"), std::string::npos);
}

TEST(LayerColours, JsonKeepsTheOutlineKeysAndAddsColoursPerLayerAndTheRaft) {
    const PrintPlan plan = twoLayerPlan();
    const std::vector<ColouredLayer> layers = colouredLayers(plan);
    std::vector<SlicedLayer> sliced(2);
    sliced[1].outlines = {{{0, 0}, {10'000, 0}, {10'000, 5'000}, {0, 5'000}}};
    const nlohmann::json doc = nlohmann::json::parse(
        colouredLayersToJson(sliced, {"a.stl"}, {nullptr, &layers[1]}, {&layers[0]}, plan.outlet_colors));
    const nlohmann::json old = nlohmann::json::parse(layersToJson(sliced, {"a.stl"}));
    EXPECT_EQ(doc["meshes"], old["meshes"]);
    for (const char* key : {"index", "print_z_mm", "slice_z_mm", "area_mm2", "outlines", "open_polylines"})
        EXPECT_EQ(doc["layers"][1][key], old["layers"][1][key]) << key;
    EXPECT_TRUE(doc["layers"][0]["gcode_layer"].is_null());
    EXPECT_TRUE(doc["layers"][0]["predicted_colors"].empty());
    EXPECT_EQ(doc["layers"][1]["gcode_layer"], 0);
    EXPECT_EQ(doc["layers"][1]["predicted_colors"],
              nlohmann::json::parse(
                  R"([{"color": "#ffff00", "length_mm": 20.0}, {"color": "#008a55", "length_mm": 7.0}])"));
    EXPECT_EQ(doc["raft_layers"], nlohmann::json::parse(R"([{"gcode_layer": -1, "z_mm": 0.3,
        "predicted_colors": [{"color": "#ffff00", "length_mm": 10.0}]}])"));
}

}  // namespace
}  // namespace mixengine
