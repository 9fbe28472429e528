#include "communication/arcus/ResultMessages.h"

#include "Cura.pb.h"

namespace mixengine {

Arcus::MessagePtr progressMessage(double amount) {
    auto message = std::make_shared<cura::proto::Progress>();
    message->set_amount(static_cast<float>(amount));
    return message;
}

Arcus::MessagePtr gcodeLayerMessage(const std::string& gcode) {
    auto message = std::make_shared<cura::proto::GCodeLayer>();
    message->set_data(gcode);
    return message;
}

Arcus::MessagePtr gcodePrefixMessage(const std::string& header) {
    auto message = std::make_shared<cura::proto::GCodePrefix>();
    message->set_data(header);
    return message;
}

Arcus::MessagePtr slicingFinishedMessage() {
    return std::make_shared<cura::proto::SlicingFinished>();
}

Arcus::MessagePtr estimatesMessage(const PrintSummary& summary) {
    auto message = std::make_shared<cura::proto::PrintTimeMaterialEstimates>();
    message->set_time_none(static_cast<float>(summary.print_time_s));
    for (std::size_t i = 0; i < summary.extruders.size(); ++i) {
        cura::proto::MaterialEstimates* estimate = message->add_materialestimates();
        estimate->set_id(static_cast<std::int64_t>(i));
        estimate->set_material_amount(static_cast<float>(summary.extruders[i].volume_used_mm3));
    }
    return message;
}

}  // namespace mixengine
