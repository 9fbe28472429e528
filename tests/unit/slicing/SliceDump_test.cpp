#include "slicing/SliceDump.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace mixengine {
namespace {

SlicedLayer sampleLayer() {
    SlicedLayer layer;
    layer.print_z = 300;
    layer.slice_z = 250;
    layer.outlines = {{{0, 0}, {20'000, 0}, {20'000, 20'000}, {0, 20'000}},
                      {{5'000, 5'000}, {5'000, 15'000}, {15'000, 15'000}, {15'000, 5'000}}};
    layer.open_polylines = {{{25'000, 0}, {25'000, 10'000}}};
    return layer;
}

TEST(SliceDump, JsonHoldsMeshesHeightsAreaAndOutlinesInMillimetres) {
    const auto json = nlohmann::json::parse(layersToJson({sampleLayer(), SlicedLayer{}}, {"a.stl", "b.stl"}));
    EXPECT_EQ(json["meshes"], nlohmann::json::array({"a.stl", "b.stl"}));
    ASSERT_EQ(json["layers"].size(), 2U);
    const auto& layer = json["layers"][0];
    EXPECT_EQ(layer["index"], 0);
    EXPECT_DOUBLE_EQ(layer["print_z_mm"].get<double>(), 0.3);
    EXPECT_DOUBLE_EQ(layer["slice_z_mm"].get<double>(), 0.25);
    EXPECT_DOUBLE_EQ(layer["area_mm2"].get<double>(), 400.0 - 100.0);  // the hole counts negative
    ASSERT_EQ(layer["outlines"].size(), 2U);
    EXPECT_EQ(layer["outlines"][0][1], nlohmann::json::array({20.0, 0.0}));
    EXPECT_EQ(layer["open_polylines"], 1);
    EXPECT_EQ(json["layers"][1]["index"], 1);
    EXPECT_TRUE(json["layers"][1]["outlines"].empty());
    EXPECT_EQ(json["layers"][1]["area_mm2"], 0.0);
}

TEST(SliceDump, JsonWithoutLayersOrMeshes) {
    EXPECT_EQ(layersToJson({}, {}), R"({"layers":[],"meshes":[]})");
}

TEST(SliceDump, SvgFillsEvenOddShowsOpenPiecesInRedAndHasAScale) {
    const std::string svg = layerToSvg(sampleLayer(), {10.0, 2.0, "cube <a>"});
    EXPECT_EQ(svg.rfind("<?xml", 0), 0U);
    EXPECT_NE(svg.find("fill-rule=\"evenodd\""), std::string::npos);
    EXPECT_NE(svg.find("stroke=\"red\""), std::string::npos);
    EXPECT_NE(svg.find("5.000 mm</text>"), std::string::npos);  // 29 mm wide drawing → 5 mm bar
    EXPECT_NE(svg.find("cube &lt;a&gt;"), std::string::npos);
    EXPECT_NE(svg.find("M2.000 22.000 L22.000 22.000"), std::string::npos);  // y flipped, margin 2 mm
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

TEST(SliceDump, EmptyLayerStillGivesAFrame) {
    const std::string svg = layerToSvg(SlicedLayer{});
    EXPECT_NE(svg.find("viewBox=\"0 0 14.000"), std::string::npos);
    EXPECT_NE(svg.find("0 outlines"), std::string::npos);
}

}  // namespace
}  // namespace mixengine
