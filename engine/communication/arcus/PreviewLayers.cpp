#include "communication/arcus/PreviewLayers.h"

#include <cmath>
#include <cstring>

#include "Cura.pb.h"

namespace mixengine {
namespace {

constexpr int kMoveCombing = 8;
constexpr int kMoveRetraction = 9;

/// Accumulates the moves of one extruder into a PathSegment's byte arrays.
class SegmentBuilder {
  public:
    SegmentBuilder(cura::proto::LayerOptimized& layer, double thickness_mm)
        : layer_(layer), thickness_mm_(thickness_mm) {}

    void start(int extruder, const Point2& from) {
        flush();
        extruder_ = extruder;
        points_.clear();
        types_.clear();
        widths_.clear();
        feedrates_.clear();
        addPoint(from);
    }

    void line(const Point2& to, int type, double width_mm, double speed_mm_s) {
        addPoint(to);
        types_.push_back(static_cast<char>(type));
        widths_.push_back(static_cast<float>(width_mm));
        feedrates_.push_back(static_cast<float>(speed_mm_s));
    }

    void flush() {
        if (types_.empty())
            return;
        cura::proto::PathSegment* segment = layer_.add_path_segment();
        segment->set_extruder(extruder_);
        segment->set_point_type(cura::proto::PathSegment::Point2D);
        segment->set_points(bytesOf(points_));
        segment->set_line_type(types_);
        segment->set_line_width(bytesOf(widths_));
        segment->set_line_thickness(
            bytesOf(std::vector<float>(widths_.size(), static_cast<float>(thickness_mm_))));
        segment->set_line_feedrate(bytesOf(feedrates_));
        types_.clear();
    }

  private:
    void addPoint(const Point2& p) {
        points_.push_back(static_cast<float>(static_cast<double>(p.X) / 1000.0));
        points_.push_back(static_cast<float>(static_cast<double>(p.Y) / 1000.0));
    }
    static std::string bytesOf(const std::vector<float>& values) {
        std::string bytes(values.size() * sizeof(float), '\0');
        std::memcpy(bytes.data(), values.data(), bytes.size());  // x86/ARM: little-endian as Cura reads
        return bytes;
    }

    cura::proto::LayerOptimized& layer_;
    double thickness_mm_;
    int extruder_ = 0;
    std::vector<float> points_, widths_, feedrates_;
    std::string types_;
};

void addLayerSegments(const PlannedLayer& planned, double thickness_mm, cura::proto::LayerOptimized& layer,
                      Point2& head, int& extruder) {
    SegmentBuilder segment(layer, thickness_mm);
    segment.start(extruder, head);
    Feature feature = Feature::Fill;  // the extrusions' type comes from the last SetFeature step
    for (const PlanStep& step : planned.steps) {
        switch (step.kind) {
            case PlanStep::Kind::SetFeature:
                feature = step.feature;
                break;
            case PlanStep::Kind::SetExtruder:
                if (step.extruder != extruder) {
                    extruder = step.extruder;
                    segment.start(extruder, head);
                }
                break;
            case PlanStep::Kind::Travel:
                segment.line(step.to, step.retract ? kMoveRetraction : kMoveCombing, 0.1, step.speed_mm_s);
                head = step.to;
                break;
            case PlanStep::Kind::Extrude: {
                const double length = distanceMm(head, step.to);
                const double width =
                    length > 0 && thickness_mm > 0 ? step.volume_mm3 / (length * thickness_mm) : 0.0;
                segment.line(step.to, curaLineType(feature), width, step.speed_mm_s);
                head = step.to;
                break;
            }
            default:
                break;
        }
    }
    segment.flush();
}

}  // namespace

int curaLineType(Feature feature) {
    switch (markedFeature(feature)) {
        case Feature::WallOuter:
            return 1;
        case Feature::WallInner:
            return 2;
        case Feature::Skin:
            return 3;
        case Feature::Skirt:
            return 5;
        case Feature::Fill:
            return 6;
        case Feature::Support:
            return 7;  // support infill, as CuraEngine types support lines
        case Feature::SupportInterface:
            return 10;
        case Feature::PrimeTower:
            return 11;
        default:
            return 0;
    }
}

std::shared_ptr<cura::proto::LayerOptimized> previewLayer(const PlannedLayer& planned, int id,
                                                          PreviewCursor& cursor) {
    auto layer = std::make_shared<cura::proto::LayerOptimized>();
    const coord_um thickness_um = planned.thickness > 0 ? planned.thickness : planned.z - cursor.previous_z;
    cursor.previous_z = planned.z;
    layer->set_id(id);
    layer->set_height(static_cast<float>(planned.z));
    layer->set_thickness(static_cast<float>(thickness_um));
    addLayerSegments(planned, static_cast<double>(thickness_um) / 1000.0, *layer, cursor.head,
                     cursor.extruder);
    return layer;
}

std::vector<std::shared_ptr<cura::proto::LayerOptimized>> previewLayers(const PrintPlan& plan,
                                                                        int index_offset, Point2& start,
                                                                        int& start_extruder) {
    std::vector<std::shared_ptr<cura::proto::LayerOptimized>> layers;
    PreviewCursor cursor{start, start_extruder, 0};
    for (const PlannedLayer& planned : plan.layers)
        layers.push_back(previewLayer(planned, planned.index + index_offset, cursor));
    start = cursor.head;
    start_extruder = cursor.extruder;
    return layers;
}

}  // namespace mixengine
