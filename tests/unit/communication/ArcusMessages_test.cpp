// Cura's socket messages ↔ plain data (communication/arcus/): the connect command line as Cura
// writes it, the Slice message → SliceRequest, and a plan → the LayerOptimized preview.
#include <gtest/gtest.h>

#include <cstring>

#include "Cura.pb.h"
#include "communication/arcus/ConnectArgs.h"
#include "communication/arcus/PreviewLayers.h"
#include "communication/arcus/ResultMessages.h"
#include "communication/arcus/SliceMessage.h"
#include "unit/settings/ScratchDir.h"

namespace mixengine {
namespace {

using unit::contains;
using unit::inputErrorOf;

TEST(ConnectArgs, CurasOwnCommandLine) {
    const ConnectArgs args = parseConnectArguments({"127.0.0.1:49677", ""});
    EXPECT_EQ(args.host, "127.0.0.1");
    EXPECT_EQ(args.port, 49677);
    EXPECT_EQ(args.verbosity, 0);
    EXPECT_TRUE(args.ignored.empty());
}

TEST(ConnectArgs, DebugVerbosityThreadsAndUnknownFlags) {
    const ConnectArgs args = parseConnectArguments({"localhost", "", "-vvv", "-m2", "-j", "x.def.json"});
    EXPECT_EQ(args.host, "localhost");
    EXPECT_EQ(args.port, 49674);  // CuraEngine's default port
    EXPECT_EQ(args.verbosity, 3);
    EXPECT_EQ(args.threads, 2);
    EXPECT_EQ(args.ignored, (std::vector<std::string>{"-j", "x.def.json"}));
}

TEST(ConnectArgs, BadAddressesNameTheWord) {
    EXPECT_TRUE(contains(inputErrorOf([] { parseConnectArguments({"127.0.0.1:0"}); }), "'127.0.0.1:0'"));
    EXPECT_TRUE(contains(inputErrorOf([] { parseConnectArguments({"127.0.0.1:port"}); }), "port from 1"));
    EXPECT_TRUE(contains(inputErrorOf([] { parseConnectArguments({""}); }), "missing <host>"));
    EXPECT_TRUE(contains(inputErrorOf([] { parseConnectArguments({"h:1", "-m0"}); }), "'-m0'"));
}

std::string floatBytes(const std::vector<float>& values) {
    std::string bytes(values.size() * sizeof(float), '\0');
    std::memcpy(bytes.data(), values.data(), bytes.size());
    return bytes;
}

void addSetting(google::protobuf::RepeatedPtrField<cura::proto::Setting>* list, const std::string& key,
                const std::string& value) {
    cura::proto::Setting* setting = list->Add();
    setting->set_name(key);
    setting->set_value(value);
}

cura::proto::Slice twoExtruderSlice() {
    cura::proto::Slice slice;
    addSetting(slice.mutable_global_settings()->mutable_settings(), "layer_height", "0.2");
    addSetting(slice.mutable_global_settings()->mutable_settings(), "support_angle", "50");
    for (int id : {0, 1}) {
        cura::proto::Extruder* extruder = slice.add_extruders();
        extruder->set_id(id);
        addSetting(extruder->mutable_settings()->mutable_settings(), "support_angle", id == 0 ? "40" : "60");
    }
    cura::proto::SettingExtruder* limit = slice.add_limit_to_extruder();
    limit->set_name("support_angle");
    limit->set_extruder(1);
    cura::proto::ObjectList* group = slice.add_object_lists();
    addSetting(group->mutable_settings(), "print_sequence", "one_at_a_time");
    cura::proto::Object* object = group->add_objects();
    object->set_name("tri.stl");
    object->set_vertices(floatBytes({0, 0, 0, 10, 0, 0, 0, 10, 5}));
    addSetting(object->mutable_settings(), "extruder_nr", "1");
    return slice;
}

TEST(SliceMessage, EveryScopeLandsInTheRequest) {
    const SliceRequest request = requestFromSlice(twoExtruderSlice());
    EXPECT_TRUE(request.settings_from_frontend);
    EXPECT_EQ(request.user.global.at("layer_height"), "0.2");
    ASSERT_EQ(request.user.extruders.size(), 2U);
    EXPECT_EQ(request.user.extruders.at(0).at("support_angle"), "40");
    // limit_to_extruder: the global lookup of support_angle reads extruder 1's value
    EXPECT_EQ(request.user.global.at("support_angle"), "60");
    ASSERT_EQ(request.groups.size(), 1U);
    EXPECT_EQ(request.groups[0].settings.at("print_sequence"), "one_at_a_time");
    const MeshInput& mesh = request.groups[0].meshes.at(0);
    EXPECT_EQ(mesh.name, "tri.stl");
    EXPECT_EQ(mesh.default_extruder, 1);
    EXPECT_FALSE(mesh.file.has_value());
    ASSERT_EQ(mesh.soups.size(), 1U);
    ASSERT_EQ(mesh.soups[0].triangles.size(), 1U);
    EXPECT_EQ(mesh.soups[0].triangles[0][2], (Vec3{0, 10, 5}));
}

TEST(SliceMessage, BrokenVertexBuffersNameTheObject) {
    EXPECT_TRUE(contains(inputErrorOf([] { soupFromVertexBytes(std::string(35, '\0'), "a.stl"); }),
                         "object 'a.stl' has 35 vertex bytes"));
    const std::string nan = floatBytes({0, 0, 0, 1, 0, 0, 0, 1, std::numeric_limits<float>::quiet_NaN()});
    EXPECT_TRUE(contains(inputErrorOf([&] { soupFromVertexBytes(nan, "b.stl"); }), "not finite"));
    cura::proto::Slice slice = twoExtruderSlice();
    slice.mutable_object_lists(0)->mutable_objects(0)->mutable_settings(0)->set_value("one");
    EXPECT_TRUE(contains(inputErrorOf([&] { requestFromSlice(slice); }), "extruder_nr 'one'"));
}

PlanStep step(PlanStep::Kind kind, Point2 to = {}) {
    PlanStep s;
    s.kind = kind;
    s.to = to;
    s.speed_mm_s = 50;
    return s;
}

TEST(PreviewLayers, LinesAreTypedSizedAndSplitByExtruder) {
    PrintPlan plan;
    PlannedLayer layer;
    layer.z = 300;
    PlanStep wall = step(PlanStep::Kind::SetFeature);
    wall.feature = Feature::WallOuter;
    PlanStep line = step(PlanStep::Kind::Extrude, {10000, 0});
    line.volume_mm3 = 10.0 * 0.4 * 0.3;  // 10 mm of a 0.4 mm line, 0.3 mm thick
    PlanStep travel = step(PlanStep::Kind::Travel, {10000, 5000});
    travel.retract = true;
    PlanStep tool = step(PlanStep::Kind::SetExtruder);
    tool.extruder = 1;
    layer.steps = {wall, line, travel, tool, step(PlanStep::Kind::Travel, {0, 5000})};
    plan.layers.push_back(layer);
    Point2 head{0, 0};
    int extruder = 0;
    const auto messages = previewLayers(plan, 7, head, extruder);
    ASSERT_EQ(messages.size(), 1U);
    const cura::proto::LayerOptimized& out = *messages[0];
    EXPECT_EQ(out.id(), 7);
    EXPECT_FLOAT_EQ(out.height(), 300.0F);  // microns
    EXPECT_FLOAT_EQ(out.thickness(), 300.0F);
    ASSERT_EQ(out.path_segment_size(), 2);
    const cura::proto::PathSegment& first = out.path_segment(0);
    EXPECT_EQ(first.extruder(), 0);
    EXPECT_EQ(first.line_type(), std::string({1, 9}));  // outer wall, retracted travel
    ASSERT_EQ(first.points().size(), 3 * 2 * sizeof(float));
    float width = 0;
    std::memcpy(&width, first.line_width().data(), sizeof width);
    EXPECT_NEAR(width, 0.4F, 1e-6);
    EXPECT_EQ(out.path_segment(1).extruder(), 1);
    EXPECT_EQ(out.path_segment(1).line_type(), std::string({8}));  // combing travel
    EXPECT_EQ(extruder, 1);
    EXPECT_EQ(head, (Point2{0, 5000}));
}

TEST(PreviewLayers, RaftLayersKeepTheirNegativeIdsAndEveryLayerItsThickness) {
    // A raft layer (−2) and the model's first layer lifted above an air gap: ids as CuraEngine sends them,
    // thickness the layer's own (not the 0.5 mm from the raft's top), so the line widths come out right.
    PrintPlan plan;
    PlannedLayer raft;
    raft.index = -2;
    raft.z = 240;
    raft.thickness = 240;
    PlannedLayer model;
    model.index = 0;
    model.z = 740;
    model.thickness = 200;
    PlanStep line = step(PlanStep::Kind::Extrude, {10000, 0});
    line.volume_mm3 = 10.0 * 0.4 * 0.2;
    model.steps = {line};
    plan.layers = {raft, model};
    Point2 head{0, 0};
    int extruder = 0;
    const auto messages = previewLayers(plan, 0, head, extruder);
    ASSERT_EQ(messages.size(), 2U);
    EXPECT_EQ(messages[0]->id(), -2);
    EXPECT_EQ(messages[1]->id(), 0);
    EXPECT_FLOAT_EQ(messages[0]->thickness(), 240.0F);
    EXPECT_FLOAT_EQ(messages[1]->thickness(), 200.0F);
    float width = 0;
    std::memcpy(&width, messages[1]->path_segment(0).line_width().data(), sizeof width);
    EXPECT_NEAR(width, 0.4F, 1e-6);
    EXPECT_EQ(curaLineType(Feature::RaftInterface), 7);  // raft lines typed as CuraEngine types them
    EXPECT_EQ(curaLineType(Feature::RaftBase), 10);
    EXPECT_EQ(curaLineType(Feature::Ironing), 3);
}

TEST(ResultMessages, MaterialIsSentInCubicMillimetresPerExtruder) {
    PrintSummary summary;
    summary.print_time_s = 100;
    summary.extruders.resize(2);
    summary.extruders[0].volume_used_mm3 = 2405.28;
    summary.extruders[1].volume_used_mm3 = 0.0;  // an unused train still gets its entry
    const auto message = estimatesMessage(summary);
    const auto& estimates = dynamic_cast<const cura::proto::PrintTimeMaterialEstimates&>(*message);
    ASSERT_EQ(estimates.materialestimates_size(), 2);
    EXPECT_FLOAT_EQ(estimates.materialestimates(0).material_amount(), 2405.28F);
    EXPECT_EQ(estimates.materialestimates(1).id(), 1);
    EXPECT_EQ(estimates.materialestimates(1).material_amount(), 0.0F);
}

TEST(ResultMessages, PrintTimeGoesIntoTheFeatureFieldsAsCuraEngineBooksIt) {
    PrintSummary summary;
    summary.print_time_s = 78;
    for (std::size_t i = 0; i < kTimeFeatureCount; ++i)
        summary.time_by_feature_s[i] = static_cast<double>(i + 1);  // 1 + 2 + ... + 12 = 78
    const auto message = estimatesMessage(summary);
    const auto& e = dynamic_cast<const cura::proto::PrintTimeMaterialEstimates&>(*message);
    EXPECT_FLOAT_EQ(e.time_none(), 1.0F);
    EXPECT_FLOAT_EQ(e.time_inset_0(), 2.0F);
    EXPECT_FLOAT_EQ(e.time_inset_x(), 3.0F);
    EXPECT_FLOAT_EQ(e.time_skin(), 4.0F);
    EXPECT_FLOAT_EQ(e.time_support(), 5.0F);
    EXPECT_FLOAT_EQ(e.time_skirt(), 6.0F);
    EXPECT_FLOAT_EQ(e.time_infill(), 7.0F);
    EXPECT_FLOAT_EQ(e.time_support_infill(), 8.0F);
    EXPECT_FLOAT_EQ(e.time_travel(), 9.0F);
    EXPECT_FLOAT_EQ(e.time_retract(), 10.0F);
    EXPECT_FLOAT_EQ(e.time_support_interface(), 11.0F);
    EXPECT_FLOAT_EQ(e.time_prime_tower(), 12.0F);
    const float sum = e.time_none() + e.time_inset_0() + e.time_inset_x() + e.time_skin() + e.time_support() +
                      e.time_skirt() + e.time_infill() + e.time_support_infill() + e.time_travel() +
                      e.time_retract() + e.time_support_interface() + e.time_prime_tower();
    EXPECT_FLOAT_EQ(sum, static_cast<float>(summary.print_time_s));
}

}  // namespace
}  // namespace mixengine
