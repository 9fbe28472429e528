#include "gcode/PlanWriter.h"

#include <algorithm>
#include <cstdio>

#include "gcode/format/NumberFormat.h"
#include "mixing/color/ColorSpace.h"

namespace mixengine {
namespace {

void extendBounds(WrittenLayers& out, const Point2& p, coord_um z) {
    out.min = {std::min(out.min.x, p.X), std::min(out.min.y, p.Y), std::min(out.min.z, z)};
    out.max = {std::max(out.max.x, p.X), std::max(out.max.y, p.Y), std::max(out.max.z, z)};
}

void writeCode(const std::string& code, GCodeExport& gcode) {
    if (code.empty())
        return;
    gcode.line(code.back() == '\n' ? std::string_view(code).substr(0, code.size() - 1)
                                   : std::string_view(code));
}

void changeExtruder(int extruder, const PlanWriterParams& params, GCodeExport& gcode) {
    const auto index = static_cast<std::size_t>(extruder);
    const auto current = static_cast<std::size_t>(gcode.extruder());
    if (current < params.extruders.size()) {
        const ExtruderOutput& old = params.extruders[current];
        if (old.retraction_enabled)
            gcode.retractTo(old.switch_retraction);
        if (old.switch_hop_um > 0)
            gcode.hopTo(old.switch_hop_um, true);
        gcode.resetExtrusionAxis();
        writeCode(old.end_code, gcode);
    }
    ToolChange change;
    change.extruder = extruder;
    if (index < params.extruders.size())
        change = params.extruders[index].change;
    gcode.selectExtruder(change);
    if (index < params.extruders.size()) {
        const ExtruderOutput& next = params.extruders[index];
        writeCode(next.start_code, gcode);
        if (next.retraction_enabled)
            gcode.addExtraPrime(next.switch_extra_prime_mm3);
    }
}

/// CuraEngine 4.13's time bucket of a feature (support infill is PrintFeatureType::Support there;
/// ironing and the raft are booked as the type they are marked with).
TimeFeature timeFeature(Feature feature) {
    switch (markedFeature(feature)) {
        case Feature::WallOuter:
            return TimeFeature::OuterWall;
        case Feature::WallInner:
            return TimeFeature::InnerWall;
        case Feature::Skin:
            return TimeFeature::Skin;
        case Feature::Fill:
            return TimeFeature::Infill;
        case Feature::Support:
            return TimeFeature::Support;
        case Feature::SupportInterface:
            return TimeFeature::SupportInterface;
        case Feature::Skirt:
            return TimeFeature::SkirtBrim;
        case Feature::PrimeTower:
            return TimeFeature::PrimeTower;
        default:
            return TimeFeature::None;
    }
}

/// cool_lift_head (planning/Cooling.h), written as CuraEngine 4.13 writes it.
void liftHead(const PlanStep& step, GCodeExport& gcode) {
    gcode.comment("Small layer, adding delay");
    gcode.retract();
    gcode.moveZ(gcode.z() + 3'000, step.speed_mm_s);
    gcode.travel(step.to, step.speed_mm_s);
    gcode.dwell(step.dwell_seconds);
}

void writeTravel(const PlanStep& step, GCodeExport& gcode) {
    if (!step.retract && step.to == gcode.position())
        return;  // as CuraEngine: no move, so no acceleration or jerk change either
    gcode.setMotion(step.acceleration_mm_s2, step.jerk_mm_s, true);
    if (step.retract)
        gcode.retract();
    if (step.prime_first)
        gcode.primeInPlace();
    gcode.travel(step.to, step.speed_mm_s);
}

void writeExtrusion(const PlanStep& step, coord_um layer_z, const PlanTables& plan, GCodeExport& gcode) {
    gcode.setMotion(step.acceleration_mm_s2, step.jerk_mm_s, false);
    if (step.mix >= 0)  // colour mixing (mixing/MixingPass.h)
        gcode.setMix(plan.mixes[static_cast<std::size_t>(step.mix)]);
    if (step.rise_um > 0)  // a spiral (toolpaths/surface/Spiralize.h)
        gcode.extrudeRising(step.to, layer_z + step.rise_um, step.volume_mm3, step.speed_mm_s);
    else
        gcode.extrude(step.to, step.volume_mm3, step.speed_mm_s);
}

void writeFeature(const PlanStep& step, GCodeExport& gcode) {
    gcode.comment("TYPE:" + std::string(featureMarker(step.feature)));
    if (step.bridge)
        gcode.comment("BRIDGE");
    gcode.newExtrusionConfig();
    gcode.setTimeFeature(timeFeature(step.feature));
}

void writeStep(const PlanStep& step, coord_um layer_z, const PlanTables& plan, const PlanWriterParams& params,
               GCodeExport& gcode, WrittenLayers& out) {
    switch (step.kind) {
        case PlanStep::Kind::Travel:
            writeTravel(step, gcode);
            break;
        case PlanStep::Kind::Extrude:
            writeExtrusion(step, layer_z, plan, gcode);
            extendBounds(out, step.to, gcode.z());
            break;
        case PlanStep::Kind::SetFeature:
            writeFeature(step, gcode);
            break;
        case PlanStep::Kind::SetMesh:
            gcode.comment("MESH:" + (step.mesh_index < 0
                                         ? std::string("NONMESH")
                                         : plan.mesh_names[static_cast<std::size_t>(step.mesh_index)]));
            break;
        case PlanStep::Kind::SetFan:
            gcode.setFan(step.fan_ratio);
            break;
        case PlanStep::Kind::SetExtruder:
            changeExtruder(step.extruder, params, gcode);
            break;
        case PlanStep::Kind::SetNozzleTemperature:
            gcode.setNozzleTemperature(step.extruder, step.temperature_c, step.wait);
            break;
        case PlanStep::Kind::Prime:
            if (static_cast<std::size_t>(gcode.extruder()) < params.extruders.size())
                writePrimeTrain(params.extruders[static_cast<std::size_t>(gcode.extruder())].prime, gcode);
            break;
        case PlanStep::Kind::SetBedTemperature:
            gcode.line("M140 S" + formatDecimal(step.temperature_c, 1));
            break;
        case PlanStep::Kind::LiftHead:
            liftHead(step, gcode);
            break;
        case PlanStep::Kind::WipeScript:
            if (static_cast<std::size_t>(step.extruder) < params.extruders.size())
                writeWipeScript(params.extruders[static_cast<std::size_t>(step.extruder)].wipe, gcode);
            break;
    }
}

/// Nothing to print: no step but ;TYPE: and ;MESH: markers and the fan (which every layer sets; CuraEngine
/// 4.13's LayerPlanBuffer drops a layer plan without paths before it is written).
bool printsNothing(const PlannedLayer& layer) {
    return std::all_of(layer.steps.begin(), layer.steps.end(), [](const PlanStep& step) {
        return step.kind == PlanStep::Kind::SetFeature || step.kind == PlanStep::Kind::SetMesh ||
               step.kind == PlanStep::Kind::SetFan;
    });
}

}  // namespace

void writeLayer(const PlannedLayer& layer, int number, const PlanTables& tables,
                const PlanWriterParams& params, GCodeExport& gcode, WrittenLayers& out) {
    gcode.takeText();  // start a fresh chunk
    if (printsNothing(layer)) {
        out.chunks.emplace_back();  // left out, as CuraEngine; still one chunk per layer
        return;
    }
    gcode.comment("LAYER:" + std::to_string(number));
    if (gcode.flavor().resets_e_each_layer && !gcode.retracted())
        gcode.resetExtrusionAxis();
    gcode.startLayer(layer.z, params.layer_change_speed_mm_s);
    gcode.newExtrusionConfig();
    int outlet_color = -1;  // the ;PREDICTED_COLOR: in force in this layer
    for (const PlanStep& step : layer.steps) {
        if (step.kind == PlanStep::Kind::Extrude && step.outlet_color >= 0 &&
            step.outlet_color != outlet_color) {
            outlet_color = step.outlet_color;
            gcode.comment("PREDICTED_COLOR:" +
                          hexOf(tables.outlet_colors[static_cast<std::size_t>(outlet_color)]));
        }
        writeStep(step, layer.z, tables, params, gcode, out);
    }
    gcode.flushTime();
    char elapsed[64];
    std::snprintf(elapsed, sizeof elapsed, "TIME_ELAPSED:%.6f", gcode.elapsedSeconds());
    gcode.comment(elapsed);
    out.chunks.push_back(gcode.takeText());
}

WrittenLayers writePlan(const PrintPlan& plan, const PlanWriterParams& params, GCodeExport& gcode) {
    WrittenLayers out;
    const PlanTables tables{plan.mesh_names, plan.mixes, plan.outlet_colors};
    for (const PlannedLayer& layer : plan.layers)
        writeLayer(layer, layer.index, tables, params, gcode, out);
    return out;
}

}  // namespace mixengine
