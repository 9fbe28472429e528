#include "slicing/SlicingParams.h"

#include <string>

namespace mixengine {

SlicingTolerance slicingToleranceOf(const Settings& group) {
    const std::string& text = group.text(key::slicing_tolerance);
    if (text == "inclusive")
        return SlicingTolerance::Inclusive;
    if (text == "exclusive")
        return SlicingTolerance::Exclusive;
    return SlicingTolerance::Middle;
}

AdaptiveLayerParams adaptiveLayerParams(const Settings& group, SlicingTolerance tolerance) {
    AdaptiveLayerParams params;
    params.layer_height_um = group.lengthMicrons(key::layer_height);
    params.layer_height_0_um = group.lengthMicrons(key::layer_height_0);
    params.variation_um = group.lengthMicrons(key::adaptive_layer_height_variation);
    params.step_um = group.lengthMicrons(key::adaptive_layer_height_variation_step);
    params.threshold_um = group.lengthMicrons(key::adaptive_layer_height_threshold);
    params.middle = tolerance == SlicingTolerance::Middle;
    return params;
}

coord_um stitchDistanceUm(const Settings& mesh) {
    constexpr coord_um kStitchUm = 10'000;
    constexpr coord_um kSurfaceModeGapUm = 100;
    const bool normal = mesh.text(key::magic_mesh_surface_mode) == "normal";
    return normal ? kStitchUm : kSurfaceModeGapUm;
}

void setOutlineCleanup(SliceOptions& options, const Settings& group, bool simplify) {
    options.min_circumference_um = group.lengthMicrons(key::minimum_polygon_circumference);
    // CuraEngine 4.13's slicer simplifies with its fixed 10 µm / 5 µm; meshfix_maximum_resolution and
    // _deviation act on the walls (and skin, infill, support) only.
    constexpr coord_um kSlicerResolutionUm = 10, kSlicerDeviationUm = 5;
    options.simplify_resolution_um = simplify ? kSlicerResolutionUm : 0;
    options.simplify_deviation_um = simplify ? kSlicerDeviationUm : 0;
    options.curaengine_crossings = simplify;
}

VolumeRole volumeRoleOf(const Settings& s, const Mesh& mesh) {
    VolumeRole role;
    role.infill_mesh = s.boolean(key::infill_mesh);
    role.cutting_mesh = s.boolean(key::cutting_mesh);
    role.support_mesh = s.boolean(key::support_mesh);
    role.anti_overhang_mesh = s.boolean(key::anti_overhang_mesh);
    role.surface_only = s.text(key::magic_mesh_surface_mode) == "surface";
    role.union_all = s.boolean(key::meshfix_union_all);
    role.infill_mesh_order = static_cast<int>(s.integer(key::infill_mesh_order));
    role.overlap_um = s.lengthMicrons(key::multiple_mesh_overlap);
    role.bounds = mesh.bounds();
    return role;
}

VolumeParams volumeParams(const Settings& group) {
    return {group.boolean(key::carve_multiple_volumes), group.boolean(key::alternate_carve_order)};
}

}  // namespace mixengine
