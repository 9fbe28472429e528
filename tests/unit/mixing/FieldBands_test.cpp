// Gradients along x, y and radially cut into bands (mixing/fields/FieldBands.h).
#include "mixing/fields/FieldBands.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mixengine {
namespace {

/// The eight corners of a box are all FieldBands reads of a mesh (its bounds and vertices).
Mesh corners(double x0, double y0, double sx, double sy, double sz) {
    Mesh mesh;
    for (int i = 0; i < 8; ++i)
        mesh.vertices.push_back({mmToMicrons(x0 + ((i >> 2) & 1) * sx), mmToMicrons(y0 + ((i >> 1) & 1) * sy),
                                 mmToMicrons((i & 1) * sz)});
    return mesh;
}

MeshMixing gradient(GradientAxis axis, double start, double end) {
    MeshMixing m;
    m.mode = MixingMode::Gradient;
    m.axis = axis;
    m.stops = {{start, MixVector::only(0, 2)}, {end, MixVector::only(1, 2)}};
    return m;
}

TEST(MixingFieldBands, AnXGradientOverSixtyMillimetresMakesTwentyBandsAtATenthTolerance) {
    // slope 1 / 60 mm: a band holds a change of half the tolerance, 0.05, so 3 mm
    const FieldBands bands(gradient(GradientAxis::X, 0, 100), corners(10, 0, 60, 12, 10), 0.1);
    EXPECT_EQ(bands.bands(), 20);
    EXPECT_NEAR(bands.bandWidthMm(), 3.0, 1e-9);
    EXPECT_NEAR(bands.bandMix(0)[1], 1.5 / 60, 1e-12);  // the field at the band's middle
    EXPECT_NEAR(bands.bandMix(19)[1], 58.5 / 60, 1e-12);
    EXPECT_EQ(bands.regionAt({mmToMicrons(10.5), 0, 0}), 0);
    EXPECT_EQ(bands.regionAt({mmToMicrons(13.5), 0, 0}), 1);
    EXPECT_EQ(bands.regionAt({mmToMicrons(69.9), 0, 0}), 19);
    EXPECT_EQ(bands.regionAt({mmToMicrons(90), 0, 0}), 19);  // beyond the model: the last band
}

TEST(MixingFieldBands, FlatPartsOfTheFieldNeedNoNarrowBandsAndMillimetresWork) {
    // y from 10 mm (A) to 20 mm (B) above the front side, in mm: slope 0.1 / mm → 0.5 mm, held at 1 mm
    MeshMixing m = gradient(GradientAxis::Y, 10, 20);
    m.unit = HeightUnit::Millimetres;
    const FieldBands bands(m, corners(0, -5, 20, 40, 5), 0.1);
    EXPECT_NEAR(bands.bandWidthMm(), 1.0, 1e-9);
    EXPECT_EQ(bands.bands(), 40);
    EXPECT_EQ(bands.bandMix(5)[1], 0.0);  // 5..6 mm: before the start
    EXPECT_NEAR(bands.bandMix(14)[1], 0.45, 1e-12);
    EXPECT_EQ(bands.bandMix(30)[1], 1.0);  // past the end
}

TEST(MixingFieldBands, RadialMeasuresFromTheVerticalCentreAxisToTheFarthestVertex) {
    const FieldBands bands(gradient(GradientAxis::Radial, 0, 100), corners(-20, -20, 40, 40, 5), 0.1);
    const double radius = 20 * std::sqrt(2.0);  // a box's farthest vertex is a corner
    EXPECT_NEAR(bands.coordinateMm({mmToMicrons(20), mmToMicrons(20), 0}), radius, 1e-3);
    EXPECT_EQ(bands.regionAt({0, 0, 0}), 0);
    EXPECT_EQ(bands.regionAt({mmToMicrons(20), mmToMicrons(20), 0}), bands.bands() - 1);
    EXPECT_NEAR(bands.bandWidthMm(), radius / 20, 1e-3);
}

}  // namespace
}  // namespace mixengine
