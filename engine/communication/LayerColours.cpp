#include "communication/LayerColours.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <optional>
#include <sstream>

namespace mixengine {
namespace {

bool movesHead(PlanStep::Kind kind) {
    return kind == PlanStep::Kind::Travel || kind == PlanStep::Kind::Extrude ||
           kind == PlanStep::Kind::LiftHead;
}

void addLength(ColouredLayer& layer, int color, double mm) {
    for (std::pair<int, double>& entry : layer.lengths_mm) {
        if (entry.first == color) {
            entry.second += mm;
            return;
        }
    }
    layer.lengths_mm.emplace_back(color, mm);
}

void addExtrusion(ColouredLayer& layer, const Point2& from, const PlanStep& step) {
    addLength(layer, step.outlet_color, distanceMm(from, step.to));
    if (!layer.runs.empty()) {
        ColourRun& last = layer.runs.back();
        if (last.color == step.outlet_color && last.width_um == step.width_um && last.points.back() == from) {
            last.points.push_back(step.to);
            return;
        }
    }
    layer.runs.push_back({step.outlet_color, step.width_um, Path{from, step.to}});
}

struct Bounds {
    coord_um min_x = 0, min_y = 0, max_x = 0, max_y = 0;
    bool empty = true;
    void add(const Point2& p, coord_um pad = 0) {
        if (empty) {
            *this = {p.X - pad, p.Y - pad, p.X + pad, p.Y + pad, false};
            return;
        }
        min_x = std::min(min_x, p.X - pad);
        min_y = std::min(min_y, p.Y - pad);
        max_x = std::max(max_x, p.X + pad);
        max_y = std::max(max_y, p.Y + pad);
    }
};

Bounds drawingBounds(const SlicedLayer& layer, const ColouredLayer* printed) {
    Bounds bounds;
    for (const Paths* paths : {&layer.outlines, &layer.open_polylines}) {
        for (const Path& path : *paths) {
            for (const Point2& p : path)
                bounds.add(p);
        }
    }
    if (printed != nullptr) {
        for (const ColourRun& run : printed->runs) {
            for (const Point2& p : run.points)
                bounds.add(p, run.width_um / 2);
        }
    }
    if (bounds.empty)
        bounds = {0, 0, 10'000, 10'000, false};
    return bounds;
}

/// The frame of the drawing: millimetres from the top left corner, y growing downwards.
struct Frame {
    coord_um left = 0, top = 0;
    double width = 0, drawing_height = 0, stroke = 0;

    void point(std::ostringstream& out, char command, const Point2& p) const {
        out << command << micronsToMm(p.X - left) << ' ' << micronsToMm(top - p.Y) << ' ';
    }
};

std::string pathData(const Paths& paths, const Frame& frame, bool closed) {
    std::ostringstream d;
    d << std::fixed << std::setprecision(3);
    for (const Path& path : paths) {
        for (std::size_t i = 0; i < path.size(); ++i)
            frame.point(d, i == 0 ? 'M' : 'L', path[i]);
        if (closed && !path.empty())
            d << "Z ";
    }
    return d.str();
}

void writeRuns(std::ostringstream& svg, const ColouredLayer& printed, const std::vector<Rgb8>& colors,
               const Frame& frame) {
    svg << "<g class=\"extrusions\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
    for (const ColourRun& run : printed.runs) {
        svg << "<path stroke=\"" << colourHex(colors.at(static_cast<std::size_t>(run.color)))
            << "\" stroke-width=\"" << micronsToMm(run.width_um) << "\" d=\""
            << pathData(Paths{run.points}, frame, false) << "\"/>\n";
    }
    svg << "</g>\n";
}

std::string printedCaption(const ColouredLayer* printed) {
    if (printed == nullptr)
        return "not printed (an empty bottom layer)";
    double total = 0;
    for (const auto& entry : printed->lengths_mm)
        total += entry.second;
    std::ostringstream text;
    const std::size_t colours = printed->lengths_mm.size();
    text << std::fixed << std::setprecision(1) << ";LAYER:" << printed->index << " — " << total
         << " mm extruded in " << colours << " predicted colour" << (colours == 1 ? "" : "s");
    return text.str();
}

void writeCaptions(std::ostringstream& svg, const SlicedLayer& layer, const ColouredLayer* printed,
                   const SvgOptions& options, const Frame& frame) {
    const double margin = std::max(options.margin_mm, 0.0);
    const double stroke = frame.stroke;
    writeSvgScaleBar(svg, margin, frame.drawing_height + 12 * stroke, frame.width - 2 * margin, stroke);
    svg << "<text x=\"" << margin << "\" y=\"" << frame.drawing_height + 32 * stroke << "\" font-size=\""
        << 12 * stroke << "\">" << escapeXml(options.caption) << (options.caption.empty() ? "" : " — ")
        << "print z " << micronsToMm(layer.print_z) << " mm, cut z " << micronsToMm(layer.slice_z) << " mm, "
        << layer.outlines.size() << " outlines, " << layer.open_polylines.size() << " open</text>\n";
    svg << "<text x=\"" << margin << "\" y=\"" << frame.drawing_height + 48 * stroke << "\" font-size=\""
        << 12 * stroke << "\">" << escapeXml(printedCaption(printed)) << "</text>\n";
}

nlohmann::json colourList(const ColouredLayer* printed, const std::vector<Rgb8>& colors) {
    nlohmann::json list = nlohmann::json::array();
    if (printed == nullptr)
        return list;
    for (const auto& [color, mm] : printed->lengths_mm) {
        list.push_back({{"color", colourHex(colors.at(static_cast<std::size_t>(color)))},
                        {"length_mm", std::round(mm * 1000.0) / 1000.0}});
    }
    return list;
}

}  // namespace

std::vector<ColouredLayer> colouredLayers(const PrintPlan& plan) {
    std::vector<ColouredLayer> out;
    std::optional<Point2> head;
    for (const PlannedLayer& layer : plan.layers) {
        ColouredLayer coloured;
        coloured.index = layer.index;
        coloured.z = layer.z;
        for (const PlanStep& step : layer.steps) {
            const bool extrudes =
                step.kind == PlanStep::Kind::Extrude && step.volume_mm3 > 0 && step.outlet_color >= 0;
            if (extrudes && head)
                addExtrusion(coloured, *head, step);
            if (movesHead(step.kind))
                head = step.to;
        }
        out.push_back(std::move(coloured));
    }
    return out;
}

std::string colourHex(const Rgb8& rgb) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
    return text;
}

std::string colouredLayerSvg(const SlicedLayer& layer, const ColouredLayer* printed,
                             const std::vector<Rgb8>& colors, const SvgOptions& options) {
    const Bounds bounds = drawingBounds(layer, printed);
    const double margin = std::max(options.margin_mm, 0.0);
    Frame frame;
    frame.width = micronsToMm(bounds.max_x - bounds.min_x) + 2 * margin;
    frame.drawing_height = micronsToMm(bounds.max_y - bounds.min_y) + 2 * margin;
    frame.stroke = std::max(frame.width, frame.drawing_height) / 500.0;
    frame.left = bounds.min_x - mmToMicrons(margin);
    frame.top = bounds.max_y + mmToMicrons(margin);
    const double height =
        frame.drawing_height + 56 * frame.stroke;  // room for the scale bar and two captions
    std::ostringstream svg;
    svg << std::fixed << std::setprecision(3);
    svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << frame.width * options.pixels_per_mm
        << "\" height=\"" << height * options.pixels_per_mm << "\" viewBox=\"0 0 " << frame.width << ' '
        << height << "\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    const std::string outline = pathData(layer.outlines, frame, true);
    svg << "<path class=\"outline\" d=\"" << outline
        << "\" fill=\"#e4e4e4\" fill-rule=\"evenodd\" stroke=\"none\"/>\n";
    if (printed != nullptr)
        writeRuns(svg, *printed, colors, frame);
    svg << "<path class=\"outline-edge\" d=\"" << outline
        << "\" fill=\"none\" stroke=\"#1f4e79\" stroke-width=\"" << frame.stroke << "\"/>\n";
    svg << "<path d=\"" << pathData(layer.open_polylines, frame, false) << "\" fill=\"none\" stroke=\"red\" "
        << "stroke-width=\"" << 2 * frame.stroke << "\"/>\n";
    writeCaptions(svg, layer, printed, options, frame);
    svg << "</svg>\n";
    return svg.str();
}

std::string colouredLayersToJson(const std::vector<SlicedLayer>& layers,
                                 const std::vector<std::string>& mesh_names,
                                 const std::vector<const ColouredLayer*>& printed,
                                 const std::vector<const ColouredLayer*>& raft,
                                 const std::vector<Rgb8>& colors) {
    nlohmann::json doc = nlohmann::json::parse(layersToJson(layers, mesh_names));
    nlohmann::json& list = doc["layers"];
    for (std::size_t i = 0; i < list.size(); ++i) {
        const ColouredLayer* layer = i < printed.size() ? printed[i] : nullptr;
        list[i]["gcode_layer"] = layer != nullptr ? nlohmann::json(layer->index) : nlohmann::json(nullptr);
        list[i]["predicted_colors"] = colourList(layer, colors);
    }
    doc["raft_layers"] = nlohmann::json::array();
    for (const ColouredLayer* layer : raft) {
        doc["raft_layers"].push_back({{"gcode_layer", layer->index},
                                      {"z_mm", micronsToMm(layer->z)},
                                      {"predicted_colors", colourList(layer, colors)}});
    }
    return doc.dump();
}

}  // namespace mixengine
