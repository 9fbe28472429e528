// Fractional voxelisation (orient/VoxelGrid.h) and FFT correlations (orient/Covariogram.h).
#include <gtest/gtest.h>

#include <random>

#include "orient/Covariogram.h"
#include "orient/VoxelGrid.h"
#include "unit/orient/OrientMeshes.h"

namespace mixengine::orient {
namespace {

using test::boxCovariogram;
using test::boxMesh;

TEST(OrientVoxels, BoxOnItsOwnFrameIsExact) {
    const Mesh box = boxMesh({1, 2, 3}, {60, 30, 30});
    const auto [lo, hi] = boundsMm(box);
    const VoxelGrid grid = voxelise(box, frameCovering(lo, hi, 64), 4, 2);
    EXPECT_EQ(grid.frame.cells[0], 64);
    EXPECT_EQ(grid.frame.cells[1], 32);
    EXPECT_NEAR(grid.volumeMm3(), 54000.0, 1e-3);
    EXPECT_EQ(grid.inconsistent_rays, 0u);
    for (const float f : grid.fraction)
        ASSERT_NEAR(f, 1.0f, 1e-5f);
}

TEST(OrientVoxels, BoxOffTheCellsKeepsItsVolume) {
    // A frame larger than the box: cells are cut by the faces, the z extent exactly, xy by sub-rays.
    const Mesh box = boxMesh({0.3, 0.7, 0.45}, {10.1, 7.3, 5.55});
    const VoxelGrid grid = voxelise(box, frameCovering({0, 0, 0}, {12, 9, 7}, 12), 4, 1);
    EXPECT_NEAR(grid.volumeMm3(), 10.1 * 7.3 * 5.55, 0.01 * 10.1 * 7.3 * 5.55);
}

TEST(OrientVoxels, SphereVolumeWithinOnePercent) {
    const Mesh sphere = test::sphereMesh(20, 5);
    const auto [lo, hi] = boundsMm(sphere);
    const VoxelGrid grid = voxelise(sphere, frameCovering(lo, hi, 48), 4, 2);
    const double polyhedron = 4.0 / 3.0 * 3.14159265358979 * 20 * 20 * 20;  // the mesh is slightly inside
    EXPECT_NEAR(grid.volumeMm3(), polyhedron, 0.01 * polyhedron);
    EXPECT_EQ(grid.inconsistent_rays, 0u);
}

TEST(OrientVoxels, OpenMeshIsReportedAndStillMeasured) {
    const Mesh open = test::openBox({0, 0, 0}, {10, 10, 10});
    const VoxelGrid grid = voxelise(open, frameCovering({0, 0, 0}, {10, 10, 10}, 10), 2, 1);
    EXPECT_EQ(grid.inconsistent_rays, grid.rays);  // every ray enters and never leaves
    EXPECT_NEAR(grid.volumeMm3(), 1000.0, 1e-3);   // bridged up to the top of the grid
}

TEST(OrientFft, FastSizes) {
    EXPECT_EQ(fastFftSize(1), 1);
    EXPECT_EQ(fastFftSize(11), 12);
    EXPECT_EQ(fastFftSize(121), 125);
    EXPECT_EQ(fastFftSize(127), 128);
}

/// A random grid on a small frame.
VoxelGrid randomGrid(const GridFrame& frame, unsigned seed) {
    VoxelGrid g;
    g.frame = frame;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0, 1);
    for (std::size_t i = 0; i < frame.cellCount(); ++i)
        g.fraction.push_back(unit(rng) < 0.5f ? 0.0f : unit(rng));
    return g;
}

TEST(OrientFft, CorrelationEqualsTheDirectSum) {
    GridFrame frame;
    frame.cells = {5, 4, 3};
    frame.step_mm = {1, 1.5, 2};
    const VoxelGrid x = randomGrid(frame, 1), y = randomGrid(frame, 2);
    const auto fields = correlate({&x, &y}, {{0, 1}, {0, 0}}, 100.0, 2);
    auto at = [&](const VoxelGrid& g, int i, int j, int k) -> double {
        if (i < 0 || j < 0 || k < 0 || i >= 5 || j >= 4 || k >= 3)
            return 0.0;
        return g.fraction[(i * 4 + j) * 3 + k];
    };
    for (int a = -4; a <= 4; ++a) {
        for (int b = -3; b <= 3; ++b) {
            for (int c = -2; c <= 2; ++c) {
                double xy = 0, xx = 0;  // Σ f(x) g(x − v)
                for (int i = 0; i < 5; ++i) {
                    for (int j = 0; j < 4; ++j) {
                        for (int k = 0; k < 3; ++k) {
                            xy += at(x, i, j, k) * at(y, i - a, j - b, k - c);
                            xx += at(x, i, j, k) * at(x, i - a, j - b, k - c);
                        }
                    }
                }
                ASSERT_NEAR(fields[0].atCell(a, b, c), xy * 3.0, 1e-4) << a << " " << b << " " << c;
                ASSERT_NEAR(fields[1].atCell(a, b, c), xx * 3.0, 1e-4);
                ASSERT_NEAR(fields[0].at({a * 1.0, b * 1.5, c * 2.0}), xy * 3.0, 1e-4);
            }
        }
    }
}

TEST(OrientFft, BoxCovariogramMatchesTheAnalyticFormula) {
    const Vec3 size{60, 30, 30};
    const Mesh box = boxMesh({0, 0, 0}, size);
    const VoxelGrid grid = voxelise(box, frameCovering({0, 0, 0}, size, 96), 4, 2);
    const auto fields = correlate({&grid}, {{0, 0}}, 35.0, 2);
    for (const Vec3& v : {Vec3{35, 0, 0}, Vec3{30.3109, 17.5, 0}, Vec3{20, -20, 20.6155},
                          Vec3{-3, 12.2, 31.5}, Vec3{0, 0, 35}, Vec3{34.9, 2, 1}}) {
        const double analytic = boxCovariogram(size, v);
        const double fft = fields[0].at(v);
        EXPECT_NEAR(fft, analytic, std::max(0.01 * analytic, 1e-6 * 54000.0))
            << v.x << " " << v.y << " " << v.z;
    }
    EXPECT_NEAR(fields[0].at({35, 0, 0}), 25.0 * 30 * 30, 1e-2);
}

TEST(OrientFft, ValuesBeyondTheReachAreZero) {
    const Mesh box = boxMesh({0, 0, 0}, {10, 10, 10});
    const VoxelGrid grid = voxelise(box, frameCovering({0, 0, 0}, {10, 10, 10}, 10), 2, 1);
    const auto fields = correlate({&grid}, {{0, 0}}, 4.0, 1);
    EXPECT_NEAR(fields[0].at({4, 0, 0}), 600.0, 1e-3);
    EXPECT_EQ(fields[0].reachCells()[0], 5);
    EXPECT_EQ(fields[0].at({9, 0, 0}), 0.0);
}

}  // namespace
}  // namespace mixengine::orient
