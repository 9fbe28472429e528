#include "slicing/SliceDump.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "geometry/Clip.h"

namespace mixengine {
namespace {

nlohmann::json layerToJson(const SlicedLayer& layer, std::size_t index) {
    nlohmann::json outlines = nlohmann::json::array();
    double area_um2 = 0;
    for (const Path& path : layer.outlines) {
        area_um2 += signedAreaUm2(path);
        nlohmann::json points = nlohmann::json::array();
        for (const Point2& p : path)
            points.push_back({micronsToMm(p.X), micronsToMm(p.Y)});
        outlines.push_back(std::move(points));
    }
    return {{"index", index},
            {"print_z_mm", micronsToMm(layer.print_z)},
            {"slice_z_mm", micronsToMm(layer.slice_z)},
            {"area_mm2", area_um2 / 1.0e6},
            {"outlines", std::move(outlines)},
            {"open_polylines", layer.open_polylines.size()}};
}

struct BoundsUm {
    coord_um min_x = 0, min_y = 0, max_x = 0, max_y = 0;
    bool empty = true;
    void add(const Point2& p) {
        if (empty) {
            *this = {p.X, p.Y, p.X, p.Y, false};
            return;
        }
        min_x = std::min(min_x, p.X);
        min_y = std::min(min_y, p.Y);
        max_x = std::max(max_x, p.X);
        max_y = std::max(max_y, p.Y);
    }
};

BoundsUm layerBounds(const SlicedLayer& layer) {
    BoundsUm bounds;
    for (const Paths* paths : {&layer.outlines, &layer.open_polylines}) {
        for (const Path& path : *paths) {
            for (const Point2& p : path)
                bounds.add(p);
        }
    }
    if (bounds.empty)
        bounds = {0, 0, 10'000, 10'000, false};
    return bounds;
}

/// SVG path data in mm with y flipped about `top_um` (SVG's y grows downwards).
std::string pathData(const Paths& paths, coord_um left_um, coord_um top_um, bool closed) {
    std::ostringstream d;
    d << std::fixed << std::setprecision(3);
    for (const Path& path : paths) {
        for (std::size_t i = 0; i < path.size(); ++i) {
            d << (i == 0 ? 'M' : 'L') << micronsToMm(path[i].X - left_um) << ' '
              << micronsToMm(top_um - path[i].Y) << ' ';
        }
        if (closed && !path.empty())
            d << "Z ";
    }
    return d.str();
}

}  // namespace

namespace {

/// 1, 2 or 5 × 10^k mm, about a fifth of the drawing's width.
double scaleBarMm(double width_mm) {
    const double target = std::max(width_mm / 5.0, 0.001);
    const double decade = std::pow(10.0, std::floor(std::log10(target)));
    for (double factor : {5.0, 2.0, 1.0}) {
        if (factor * decade <= target)
            return factor * decade;
    }
    return decade;
}

}  // namespace

void writeSvgScaleBar(std::ostringstream& svg, double x_mm, double y_mm, double width_mm, double stroke_mm) {
    const double bar = scaleBarMm(width_mm);
    svg << "<g stroke=\"black\" stroke-width=\"" << stroke_mm << "\">"
        << "<line x1=\"" << x_mm << "\" y1=\"" << y_mm << "\" x2=\"" << x_mm + bar << "\" y2=\"" << y_mm
        << "\"/>"
        << "<line x1=\"" << x_mm << "\" y1=\"" << y_mm - 4 * stroke_mm << "\" x2=\"" << x_mm << "\" y2=\""
        << y_mm + 4 * stroke_mm << "\"/>"
        << "<line x1=\"" << x_mm + bar << "\" y1=\"" << y_mm - 4 * stroke_mm << "\" x2=\"" << x_mm + bar
        << "\" y2=\"" << y_mm + 4 * stroke_mm << "\"/></g>\n";
    svg << "<text x=\"" << x_mm + bar + 8 * stroke_mm << "\" y=\"" << y_mm + 3 * stroke_mm
        << "\" font-size=\"" << 12 * stroke_mm << "\">" << bar << " mm</text>\n";
}

std::string escapeXml(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '&':
                out += "&amp;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string layersToJson(const std::vector<SlicedLayer>& layers, const std::vector<std::string>& mesh_names) {
    nlohmann::json doc;
    doc["meshes"] = mesh_names;
    doc["layers"] = nlohmann::json::array();
    for (std::size_t i = 0; i < layers.size(); ++i)
        doc["layers"].push_back(layerToJson(layers[i], i));
    return doc.dump();
}

std::string layerToSvg(const SlicedLayer& layer, const SvgOptions& options) {
    const BoundsUm bounds = layerBounds(layer);
    const double margin = std::max(options.margin_mm, 0.0);
    const double width = micronsToMm(bounds.max_x - bounds.min_x) + 2 * margin;
    const double drawing_height = micronsToMm(bounds.max_y - bounds.min_y) + 2 * margin;
    const double stroke = std::max(width, drawing_height) / 500.0;
    const double footer = 40 * stroke;  // room for the scale bar and the caption
    const double height = drawing_height + footer;
    const coord_um left = bounds.min_x - mmToMicrons(margin);
    const coord_um top = bounds.max_y + mmToMicrons(margin);
    std::ostringstream svg;
    svg << std::fixed << std::setprecision(3);
    svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width * options.pixels_per_mm
        << "\" height=\"" << height * options.pixels_per_mm << "\" viewBox=\"0 0 " << width << ' ' << height
        << "\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg << "<path d=\"" << pathData(layer.outlines, left, top, true)
        << "\" fill=\"#9ec3e6\" fill-rule=\"evenodd\" "
        << "stroke=\"#1f4e79\" stroke-width=\"" << stroke << "\"/>\n";
    svg << "<path d=\"" << pathData(layer.open_polylines, left, top, false)
        << "\" fill=\"none\" stroke=\"red\" "
        << "stroke-width=\"" << 2 * stroke << "\"/>\n";
    writeSvgScaleBar(svg, margin, drawing_height + 12 * stroke, width - 2 * margin, stroke);
    svg << "<text x=\"" << margin << "\" y=\"" << drawing_height + 32 * stroke << "\" font-size=\""
        << 12 * stroke << "\">" << escapeXml(options.caption) << (options.caption.empty() ? "" : " — ")
        << "print z " << micronsToMm(layer.print_z) << " mm, cut z " << micronsToMm(layer.slice_z) << " mm, "
        << layer.outlines.size() << " outlines, " << layer.open_polylines.size() << " open</text>\n";
    svg << "</svg>\n";
    return svg.str();
}

}  // namespace mixengine
