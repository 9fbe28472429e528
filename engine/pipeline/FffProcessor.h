#pragma once
// The pipeline driver (CuraEngine's name for the role): Scene → slices → toolpaths → plan →
// G-code. Each stage is a function of the previous stage's values and the resolved settings.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "common/Log.h"
#include "gcode/Header.h"
#include "pipeline/LayerStream.h"
#include "pipeline/Scene.h"
#include "planning/LayerPlan.h"
#include "slicing/MultiVolumes.h"
#include "slicing/Slicer.h"

namespace mixengine {

struct SlicedGroup {
    std::vector<LayerZ> heights;
    std::vector<std::vector<SlicedLayer>> meshes;  ///< [mesh][layer], combined (slicing/MultiVolumes.h)
    std::vector<VolumeRole> roles;                 ///< [mesh] what each mesh is (a model or a modifier)
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
    std::vector<std::string> notes;  ///< what the command line reports after slicing (the mixing report)

    std::string joined() const;
    /// The text of joined() in its pieces, in order (views into this output).
    std::vector<std::string_view> pieces() const;
};

/// Layer heights and outlines of every mesh of `group`, combined as CuraEngine combines them (cutting
/// meshes, carve_multiple_volumes, multiple_mesh_overlap: slicing/MultiVolumes.h). A group of modifier
/// meshes alone (no mesh that prints layers of its own) has no layers.
/// `simplify` false keeps the raw slices (only loops under minimum_polygon_circumference go).
SlicedGroup sliceGroup(const SceneGroup& group, int threads, Log& log, bool simplify = true);

/// Sees each mesh group's plan after planning and mixing (e.g. the --preview picture).
using PlanObserver = std::function<void(const PrintPlan&)>;

/// The whole print. With a `stream` (pipeline/LayerStream.h) the layers and the start code go to it
/// as they are made and the result's layer_chunks stay empty; the rest of the result is the same.
GCodeOutput runPipeline(const Scene& scene, int threads, Log& log, const PlanObserver& on_plan = {},
                        const LayerStream& stream = {});

}  // namespace mixengine
