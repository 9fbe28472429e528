#pragma once
// The pipeline driver (CuraEngine's name for the role): Scene → slices → toolpaths → plan →
// G-code. Each stage is a function of the previous stage's values and the resolved settings.
#include <functional>
#include <string>
#include <vector>

#include "common/Log.h"
#include "gcode/Header.h"
#include "pipeline/Scene.h"
#include "planning/LayerPlan.h"
#include "slicing/Slicer.h"

namespace mixengine {

struct SlicedGroup {
    std::vector<LayerZ> heights;
    std::vector<std::vector<SlicedLayer>> meshes;  ///< [mesh][layer]
};

struct GCodeOutput {
    std::string header;  ///< ;FLAVOR: … or the Griffin block (Cura's GCodePrefix)
    /// Start code + ;LAYER_COUNT: — the model's layers, without the raft's, as CuraEngine counts.
    std::string start;
    /// One per layer, ";LAYER:n" first; under a raft the first group's raft layers are numbered
    /// below 0 as CuraEngine numbers them, and later groups' layers number on.
    std::vector<std::string> layer_chunks;
    std::string suffix;  ///< end code
    PrintSummary summary;

    std::string joined() const;
};

/// Layer heights and outlines of every mesh of `group`.
/// `simplify` false keeps the raw slices (only loops under minimum_polygon_circumference go).
SlicedGroup sliceGroup(const SceneGroup& group, int threads, Log& log, bool simplify = true);

/// Sees each mesh group's plan after planning and mixing (e.g. the --preview picture).
using PlanObserver = std::function<void(const PrintPlan&)>;

/// The whole print.
GCodeOutput runPipeline(const Scene& scene, int threads, Log& log, const PlanObserver& on_plan = {});

}  // namespace mixengine
