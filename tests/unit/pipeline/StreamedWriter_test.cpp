// Writing a plan while it is being made (pipeline/StreamedWriter.h with planning/PrintPlanner.h's
// FinalLayer): the text is writePlan()'s for the finished plan, layer numbers included, and each
// layer is handed over once, in order, before planning ends.
#include "pipeline/StreamedWriter.h"

#include <gtest/gtest.h>

#include "../toolpaths/ToolpathTestSupport.h"

namespace mixengine {
namespace {

/// A cube on a raft, 20 model layers, the nozzle and bed temperatures changing after the first layer
/// (temperature steps that look one layer ahead).
const SettingValues kCubeOnRaft{{"adhesion_type", "raft"},
                                {"material_print_temperature", "200"},
                                {"material_print_temperature_layer_0", "215"},
                                {"material_bed_temperature", "50"},
                                {"material_bed_temperature_layer_0", "60"},
                                {"machine_heated_bed", "true"},
                                {"retraction_combing", "all"}};

std::string joined(const std::vector<std::string>& chunks) {
    std::string text;
    for (const std::string& chunk : chunks)
        text += chunk;
    return text;
}

std::string joined(const WrittenLayers& written) {
    return joined(written.chunks);
}

TEST(StreamedWriter, WritesWritePlansTextWhileLaterLayersArePlanned) {
    const test::CubePrint p(kCubeOnRaft);
    const PlanWriterParams params;
    PlannerState state;
    const PrintPlan whole = planPrint(p.toolpaths, p.machine.global, p.machine.extruders, state, 2);
    GCodeExport after(ExportParams{});
    const std::string expected = joined(writePlan(whole, params, after));
    ASSERT_NE(expected.find("M140 S50"), std::string::npos);  // the temperature steps are there
    ASSERT_NE(expected.find("M104 S200"), std::string::npos);

    PrintPlan plan;
    GCodeExport during(ExportParams{});
    std::vector<std::string> kept;
    LayerOutput output({}, nullptr, kept);
    StreamedWriter writer(params, during, std::nullopt, output);
    const FinalLayer to_writer = writer.observer();
    std::vector<std::size_t> handed, planned_then;
    PlannerState streamed_state;
    planPrint(plan, p.toolpaths, p.machine.global, p.machine.extruders, streamed_state, 2,
              [&](const PrintPlan& growing, std::size_t layer) {
                  handed.push_back(layer);
                  planned_then.push_back(growing.layers.size());
                  to_writer(growing, layer);
              });
    const WrittenLayers written = writer.finish();
    EXPECT_TRUE(written.chunks.empty());  // they went to the output
    EXPECT_EQ(joined(kept), expected);
    ASSERT_EQ(handed.size(), whole.layers.size());
    for (std::size_t i = 0; i < handed.size(); ++i)
        EXPECT_EQ(handed[i], i);
    EXPECT_EQ(planned_then.front(), 2u);  // the first layer goes once the second is planned
    EXPECT_LT(planned_then[handed.size() / 2], whole.layers.size());
    EXPECT_EQ(written.min.x, writePlan(whole, params, after).min.x);
}

TEST(StreamedWriter, NumbersTheLayersOnFromFirstNumber) {
    const test::CubePrint p(kCubeOnRaft);
    PrintPlan plan;
    GCodeExport gcode(ExportParams{});
    const PlanWriterParams params;
    std::vector<StreamedLayer> streamed;
    LayerStream stream;
    stream.layer = [&streamed](StreamedLayer&& layer) { streamed.push_back(std::move(layer)); };
    std::vector<std::string> kept;
    LayerOutput output(stream, nullptr, kept);
    StreamedWriter writer(params, gcode, 100, output);
    PlannerState state;
    planPrint(plan, p.toolpaths, p.machine.global, p.machine.extruders, state, 2, writer.observer());
    writer.finish();
    EXPECT_TRUE(kept.empty());  // a stream keeps nothing
    ASSERT_EQ(streamed.size(), plan.layers.size());
    EXPECT_LT(plan.layers.front().index, 0);  // raft layers are numbered below 0 in the plan
    EXPECT_EQ(streamed.front().gcode.rfind(";LAYER:100\n", 0), 0u);
    const int last = plan.layers.back().index + 100 - plan.layers.front().index;  // as the pipeline renumbers
    EXPECT_EQ(streamed.back().gcode.rfind(";LAYER:" + std::to_string(last) + "\n", 0), 0u);
    for (std::size_t i = 0; i < streamed.size(); ++i) {
        EXPECT_EQ(streamed[i].number, plan.layers[i].index + 100 - plan.layers.front().index);
        EXPECT_EQ(streamed[i].layer, &plan.layers[i]);
        EXPECT_EQ(streamed[i].first_of_group, i == 0);
    }
}

TEST(StreamedWriter, AStreamThatFailsEndsThePlanOrItsFinish) {
    const test::CubePrint p(kCubeOnRaft);
    PrintPlan plan;
    GCodeExport gcode(ExportParams{});
    const PlanWriterParams params;
    LayerStream stream;
    std::vector<int> numbers;
    stream.layer = [&numbers](StreamedLayer&& layer) {
        numbers.push_back(layer.number);
        if (layer.number == 3)
            throw std::runtime_error("the peer went away");
    };
    std::vector<std::string> kept;
    LayerOutput output(stream, nullptr, kept);
    StreamedWriter writer(params, gcode, std::nullopt, output);
    PlannerState state;
    // The next hand-over after the failure throws it (planning stops there), or finish() does when
    // planning was already done: either way the caller hears of it and no layer follows it.
    EXPECT_THROW(
        {
            planPrint(plan, p.toolpaths, p.machine.global, p.machine.extruders, state, 2, writer.observer());
            writer.finish();
        },
        std::runtime_error);
    ASSERT_FALSE(numbers.empty());
    EXPECT_EQ(numbers.back(), 3);
}

}  // namespace
}  // namespace mixengine
