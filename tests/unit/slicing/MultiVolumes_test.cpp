// How meshes share space (slicing/MultiVolumes.h): cutting meshes, carve_multiple_volumes with
// infill_mesh_order and alternate_carve_order, multiple_mesh_overlap; modifiers take no part.
#include "slicing/MultiVolumes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mixengine {
namespace {

Path square(coord_um x0, coord_um y0, coord_um x1, coord_um y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

double areaOf(const Paths& paths) {
    double sum = 0;
    for (const Path& p : paths)
        sum += ClipperLib::Area(p);
    return sum;
}

/// `layers` layers of the same square.
std::vector<SlicedLayer> prism(const Path& outline, int layers = 2) {
    std::vector<SlicedLayer> out(static_cast<std::size_t>(layers));
    for (SlicedLayer& layer : out)
        layer.outlines = {outline};
    return out;
}

VolumeRole roleAround(const Path& outline) {
    VolumeRole role;
    role.bounds.min = {outline[0].X, outline[0].Y, 0};
    role.bounds.max = {outline[2].X, outline[2].Y, 10'000};
    return role;
}

constexpr double kMm2 = 1e6;

TEST(MultiVolumes, CuttingMeshKeepsItsOverlapAndTheOtherMeshLosesIt) {
    const Path box = square(0, 0, 20'000, 20'000), cutter = square(10'000, 0, 30'000, 20'000);
    std::vector<std::vector<SlicedLayer>> meshes{prism(box), prism(cutter)};
    std::vector<VolumeRole> roles{roleAround(box), roleAround(cutter)};
    roles[1].cutting_mesh = true;
    combineVolumes(meshes, roles, {}, 2);
    for (std::size_t layer = 0; layer < 2; ++layer) {
        EXPECT_NEAR(areaOf(meshes[0][layer].outlines), 200 * kMm2, 1.0);  // the box's left half
        EXPECT_NEAR(areaOf(meshes[1][layer].outlines), 200 * kMm2, 1.0);  // the cutter inside the box only
    }
}

TEST(MultiVolumes, CuttingMeshAloneKeepsNothing) {
    const Path cutter = square(0, 0, 10'000, 10'000);
    std::vector<std::vector<SlicedLayer>> meshes{prism(cutter)};
    std::vector<VolumeRole> roles{roleAround(cutter)};
    roles[0].cutting_mesh = true;
    combineVolumes(meshes, roles, {}, 1);
    EXPECT_TRUE(meshes[0][0].outlines.empty());
}

TEST(MultiVolumes, SupportMeshesAndBlockersAreNotCut) {
    const Path box = square(0, 0, 20'000, 20'000);
    std::vector<std::vector<SlicedLayer>> meshes{prism(box), prism(box), prism(box)};
    std::vector<VolumeRole> roles{roleAround(box), roleAround(box), roleAround(box)};
    roles[0].cutting_mesh = true;
    roles[1].support_mesh = true;
    roles[2].anti_overhang_mesh = true;
    combineVolumes(meshes, roles, {}, 1);
    EXPECT_NEAR(areaOf(meshes[1][0].outlines), 400 * kMm2, 1.0);
    EXPECT_NEAR(areaOf(meshes[2][0].outlines), 400 * kMm2, 1.0);
    EXPECT_TRUE(meshes[0][0].outlines.empty());  // nothing to cut: the cutter keeps nothing
}

TEST(MultiVolumes, CarvingTakesTheOverlapFromTheLaterMeshOrAlternates) {
    const Path a = square(0, 0, 20'000, 10'000), b = square(10'000, 0, 30'000, 10'000);
    for (const bool alternate : {false, true}) {
        std::vector<std::vector<SlicedLayer>> meshes{prism(a), prism(b)};
        std::vector<VolumeRole> roles{roleAround(a), roleAround(b)};
        combineVolumes(meshes, roles, {true, alternate}, 2);
        // layer 1 (odd): the later mesh loses the 100 mm² overlap either way
        EXPECT_NEAR(areaOf(meshes[0][1].outlines), 200 * kMm2, 1.0);
        EXPECT_NEAR(areaOf(meshes[1][1].outlines), 100 * kMm2, 1.0);
        // layer 0 (even): with alternate_carve_order the earlier one loses it
        EXPECT_NEAR(areaOf(meshes[0][0].outlines), alternate ? 100 * kMm2 : 200 * kMm2, 1.0);
        EXPECT_NEAR(areaOf(meshes[1][0].outlines), alternate ? 200 * kMm2 : 100 * kMm2, 1.0);
    }
}

TEST(MultiVolumes, CarvingFollowsInfillMeshOrderAndSkipsInfillMeshes) {
    const Path a = square(0, 0, 20'000, 10'000), b = square(10'000, 0, 30'000, 10'000);
    std::vector<std::vector<SlicedLayer>> meshes{prism(a), prism(b)};
    std::vector<VolumeRole> roles{roleAround(a), roleAround(b)};
    roles[0].infill_mesh_order = 5;  // ranked after b: a loses the overlap on every layer
    combineVolumes(meshes, roles, {true, true}, 2);
    EXPECT_NEAR(areaOf(meshes[0][0].outlines), 100 * kMm2, 1.0);
    EXPECT_NEAR(areaOf(meshes[0][1].outlines), 100 * kMm2, 1.0);

    std::vector<std::vector<SlicedLayer>> with_infill{prism(a), prism(b)};
    roles[0].infill_mesh = true;
    combineVolumes(with_infill, roles, {true, true}, 2);
    EXPECT_NEAR(areaOf(with_infill[0][0].outlines), 200 * kMm2, 1.0);
    EXPECT_NEAR(areaOf(with_infill[1][0].outlines), 200 * kMm2, 1.0);
}

TEST(MultiVolumes, OverlapGrowsTouchingMeshesIntoEachOtherByHalfOfIt) {
    const Path a = square(0, 0, 10'000, 10'000), b = square(10'000, 0, 20'000, 10'000);
    std::vector<std::vector<SlicedLayer>> meshes{prism(a, 1), prism(b, 1)};
    std::vector<VolumeRole> roles{roleAround(a), roleAround(b)};
    roles[0].overlap_um = roles[1].overlap_um = 150;
    combineVolumes(meshes, roles, {}, 1);
    // each reaches 75 µm into the other along the 10 mm seam (the 20 µm merge margin and the second mesh
    // seeing the first one already grown add slivers of a few 1000 µm² at the seam's ends)
    EXPECT_NEAR(areaOf(meshes[0][0].outlines), 100 * kMm2 + 75 * 10'000, 15'000);
    EXPECT_NEAR(areaOf(meshes[1][0].outlines), 100 * kMm2 + 75 * 10'000, 15'000);
    EXPECT_LT(areaOf(meshes[0][0].outlines), areaOf(meshes[1][0].outlines));
}

TEST(MultiVolumes, NoOverlapForFarMeshesOrZeroOverlap) {
    const Path a = square(0, 0, 10'000, 10'000), b = square(10'000, 0, 20'000, 10'000),
               far = square(50'000, 0, 60'000, 10'000);
    std::vector<std::vector<SlicedLayer>> meshes{prism(a, 1), prism(b, 1), prism(far, 1)};
    std::vector<VolumeRole> roles{roleAround(a), roleAround(b), roleAround(far)};
    roles[2].overlap_um = 150;  // a and b: 0
    combineVolumes(meshes, roles, {}, 1);
    EXPECT_NEAR(areaOf(meshes[0][0].outlines), 100 * kMm2, 1.0);
    EXPECT_NEAR(areaOf(meshes[2][0].outlines), 100 * kMm2, 1.0);
}

TEST(MultiVolumes, BoxesMeetWhenTheyTouchOrOverlap) {
    VolumeRole a = roleAround(square(0, 0, 10'000, 10'000)),
               b = roleAround(square(10'000, 0, 20'000, 10'000)),
               c = roleAround(square(10'100, 0, 20'000, 10'000));
    EXPECT_TRUE(boxesMeet(a.bounds, b.bounds));
    EXPECT_FALSE(boxesMeet(a.bounds, c.bounds));
    EXPECT_TRUE(boxesMeet(a.bounds, c.bounds, 100));
    EXPECT_FALSE(boxesMeet(a.bounds, AABB3{}));
}

// A support mesh prints (its support) but not as a model; a cutting mesh is a model's part, not material of
// its own.
TEST(MultiVolumes, PrintedAndPrintsAloneAsCuraEngineTellsThem) {
    const auto role = [](bool VolumeRole::*flag) {
        VolumeRole r;
        if (flag)
            r.*flag = true;
        return std::pair{r.printed(), r.printsAlone()};
    };
    EXPECT_EQ(role(nullptr), std::pair(true, true));
    EXPECT_EQ(role(&VolumeRole::support_mesh), std::pair(true, false));
    EXPECT_EQ(role(&VolumeRole::cutting_mesh), std::pair(false, true));
    EXPECT_EQ(role(&VolumeRole::infill_mesh), std::pair(false, false));
    EXPECT_EQ(role(&VolumeRole::anti_overhang_mesh), std::pair(false, false));
}

}  // namespace
}  // namespace mixengine
