#pragma once
// A cross fractal's density from an image (cross_infill_density_image, cross_support_density_image),
// as CuraEngine 4.13's ImageBasedDensityProvider: the image is laid over the model's bounding box
// (x, y), centred on it and scaled so that it just covers it (its own aspect ratio kept), the
// image's top row at the largest y; the density for a box is 1 − the mean of all samples of all
// channels (alpha too) of the pixels it covers, grown by 1 µm each way, / 255 — the nearest
// pixel's when it covers none.
#include <string>

#include "common/ImageReader.h"
#include "geometry/Point.h"
#include "toolpaths/infill/cross/SierpinskiTree.h"

namespace mixengine {

/// The density of `image` laid over `model_box`.
DensityAt imageDensity(DecodedImage image, const Box2& model_box);

/// The density of the image file `file` (common/ImageReader.h) laid over `model_box`; nothing (an
/// empty function: uniform density) when `file` is empty, blank or names no readable file, as
/// CuraEngine, which only logs that. A file that is no image it can decode is an InputError
/// naming `key`.
DensityAt densityImageAt(const std::string& file, const Box2& model_box, const std::string& key);

/// Whether `pattern` (an infill_pattern / support_pattern value) is drawn from a cross fractal (cross,
/// cross_3d) and can be: a positive line distance and width.
bool wantsCrossFill(const std::string& pattern, coord_um line_distance_um, coord_um line_width_um);

}  // namespace mixengine
