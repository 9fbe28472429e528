#include "toolpaths/infill/lightning/TreeLines.h"

#include <cmath>

namespace mixengine {
namespace {

/// Appends to polylines[line] the branch under node n ending at n; its other children start
/// polylines of their own.
void drawBranch(const LightningForest& forest, int n, std::size_t line, Paths& polylines) {
    const LightningNode& node = forest.nodes[static_cast<std::size_t>(n)];
    for (std::size_t i = 0; i < node.children.size(); ++i) {
        std::size_t here = line;
        if (i > 0) {
            polylines.emplace_back();
            here = polylines.size() - 1;
        }
        drawBranch(forest, node.children[i], here, polylines);
        if (i > 0)
            polylines[here].push_back(node.p);
    }
    polylines[line].push_back(node.p);
}

/// Shortens the polyline at its end by `cut_um`; false when nothing is left.
bool shortenEnd(Path& line, double cut_um) {
    while (line.size() >= 2) {
        const Point2 end = line.back(), before = line[line.size() - 2];
        const double length = std::sqrt(double(before.X - end.X) * double(before.X - end.X) +
                                        double(before.Y - end.Y) * double(before.Y - end.Y));
        if (length >= cut_um) {
            const double k = length > 0 ? cut_um / length : 0.0;
            line.back() = {end.X + std::llround(double(before.X - end.X) * k),
                           end.Y + std::llround(double(before.Y - end.Y) * k)};
            return true;
        }
        cut_um -= length;
        line.pop_back();
    }
    return false;
}

}  // namespace

std::vector<LightningTreeLines> treeLines(const LightningForest& forest, coord_um line_width_um) {
    std::vector<LightningTreeLines> trees;
    trees.reserve(forest.roots.size());
    for (int root : forest.roots) {
        Paths polylines(1);
        drawBranch(forest, root, 0, polylines);
        LightningTreeLines tree{forest.nodes[static_cast<std::size_t>(root)].p, {}};
        for (Path& line : polylines) {
            if (line.size() < 2 || !shortenEnd(line, double(line_width_um / 2)))
                continue;
            for (std::size_t i = 1; i < line.size(); ++i) {
                if (line[i - 1].X != line[i].X || line[i - 1].Y != line[i].Y)
                    tree.segments.push_back({line[i - 1], line[i]});
            }
        }
        trees.push_back(std::move(tree));
    }
    return trees;
}

}  // namespace mixengine
