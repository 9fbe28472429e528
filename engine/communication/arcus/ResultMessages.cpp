#include "communication/arcus/ResultMessages.h"

#include "Cura.pb.h"

namespace mixengine {
namespace {

void setFeatureTimes(const FeatureSeconds& s, cura::proto::PrintTimeMaterialEstimates& message) {
    const auto at = [&s](TimeFeature feature) {
        return static_cast<float>(s[static_cast<std::size_t>(feature)]);
    };
    message.set_time_none(at(TimeFeature::None));
    message.set_time_inset_0(at(TimeFeature::OuterWall));
    message.set_time_inset_x(at(TimeFeature::InnerWall));
    message.set_time_skin(at(TimeFeature::Skin));
    message.set_time_support(at(TimeFeature::Support));
    message.set_time_skirt(at(TimeFeature::SkirtBrim));
    message.set_time_infill(at(TimeFeature::Infill));
    message.set_time_support_infill(at(TimeFeature::SupportInfill));
    message.set_time_travel(at(TimeFeature::Travel));
    message.set_time_retract(at(TimeFeature::Retraction));
    message.set_time_support_interface(at(TimeFeature::SupportInterface));
    message.set_time_prime_tower(at(TimeFeature::PrimeTower));
}

}  // namespace

MessagePtr progressMessage(double amount) {
    auto message = std::make_shared<cura::proto::Progress>();
    message->set_amount(static_cast<float>(amount));
    return message;
}

MessagePtr gcodeLayerMessage(const std::string& gcode) {
    auto message = std::make_shared<cura::proto::GCodeLayer>();
    message->set_data(gcode);
    return message;
}

MessagePtr gcodePrefixMessage(const std::string& header) {
    auto message = std::make_shared<cura::proto::GCodePrefix>();
    message->set_data(header);
    return message;
}

MessagePtr slicingFinishedMessage() {
    return std::make_shared<cura::proto::SlicingFinished>();
}

MessagePtr estimatesMessage(const PrintSummary& summary) {
    auto message = std::make_shared<cura::proto::PrintTimeMaterialEstimates>();
    setFeatureTimes(summary.time_by_feature_s, *message);
    for (std::size_t i = 0; i < summary.extruders.size(); ++i) {
        cura::proto::MaterialEstimates* estimate = message->add_materialestimates();
        estimate->set_id(static_cast<std::int64_t>(i));
        estimate->set_material_amount(static_cast<float>(summary.extruders[i].volume_used_mm3));
    }
    return message;
}

}  // namespace mixengine
