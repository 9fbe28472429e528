#pragma once
// Cubic subdivision infill (Cura's infill_pattern cubicsubdiv), as CuraEngine 4.13 builds it
// (SubDivCube): an octree of cubes standing on a corner, fine near the mesh's walls and coarse
// inside, whose faces, cut by each layer, give the lines.
//
//   cubes    — the smallest side is 2·infill_line_distance, each level doubles it, up to the first
//              side of at least 4·√(machine_height² + (machine_depth/2)² + (machine_width/2)²);
//              the root (the largest) is centred at the pattern origin at z = 0. The cubes are
//              tilted to stand on a corner and turned by the first of infill_angles (0° when there
//              are none).
//   children — a cube of side s has its 8 children, of side s/2, at ±s/4 along its own axes; a
//              child exists when the sphere of radius √3·s/4 + sub_div_rad_add around its centre
//              reaches the boundary, sampled on every third layer of the sphere's height (layer i
//              at z = i·layer_height): the centre is inside the boundary on one sampled layer and
//              outside on another, or nearer the boundary than the sphere's section there. The
//              boundary of a layer is the centre line of its innermost wall up to the second
//              (`boundaries`, one per layer; the caller's).
//   lines    — a cube whose centre is less than s/√3 from the layer's height z gives three lines
//              120° apart: the section of its faces, shorter the further z is from the centre; the
//              children of every cube that reaches z (within √3·s/2) are visited. Lines of the same
//              direction meeting end to end (within 10 µm) are joined.
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

struct SubdivCubeParams {
    coord_um line_distance_um = 0;    ///< infill_line_distance; 0 = no cubes
    coord_um radius_addition_um = 0;  ///< sub_div_rad_add
    double angle_degrees = 0;         ///< infill_angles[0], or 0
    Point2 origin_um{0, 0};           ///< the infill origin
    coord_um layer_height_um = 200;
    Point3 machine_size_um{235'000, 235'000, 250'000};  ///< width, depth, height
};

class SubdivCubes {
  public:
    /// `boundaries[i]`: the boundary of layer i (see above).
    SubdivCubes(const SubdivCubeParams& params, const std::vector<Paths>& boundaries);

    /// The lines at height z (not clipped to the part).
    Paths linesAt(coord_um z_um) const;

    std::size_t cubeCount() const { return cubes_.size(); }

  private:
    struct Level {
        coord_um side = 0, height = 0, square_height = 0, max_draw_z_diff = 0, max_line_offset = 0;
    };
    struct Cube {
        Point3 centre;
        std::size_t depth = 0;  ///< index into levels_ (0 = smallest)
        std::vector<std::size_t> children;
    };
    void subdivide(std::size_t cube, const std::vector<Paths>& boundaries);
    bool reachesBoundary(const Point3& centre, coord_um radius, const std::vector<Paths>& boundaries) const;
    void addLines(const Cube& cube, coord_um z, Paths (&by_direction)[3]) const;

    SubdivCubeParams params_;
    std::vector<Level> levels_;
    std::vector<Cube> cubes_;  ///< cubes_[0] is the root
    double rotation_[9] = {};  ///< turned by the angle after the tilt onto a corner
    double cos_a_ = 1, sin_a_ = 0;
};

}  // namespace mixengine
