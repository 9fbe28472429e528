// Feathered paint (mixing/fields/FeatheredPaint.h): a 20 × 20 × 10 mm box whose faces are split at x = 0, the
// left half painted region 0 (filament A), the right half region 1 (B), paint reaching the whole box. The
// boundary is the plane x = 0, so the asked share of B at x is the ramp (x + blend/2) / blend.
#include "mixing/fields/FeatheredPaint.h"

#include <gtest/gtest.h>

#include "../SettingsTestSupport.h"

#include <cmath>

#include "common/Error.h"
#include "mixing/fields/PaintSchedule.h"

namespace mixengine {
namespace {

constexpr coord_um kDepthUm = 30000;

/// The box (x −10..10 mm, y −10..10 mm, z 0..10 mm) in two halves; `right_region` paints the right half.
Mesh halves(std::vector<int>& face_region, int right_region = 1) {
    Mesh m;
    const auto vertex = [&m](double x, double y, double z) {
        m.vertices.push_back({mmToMicrons(x), mmToMicrons(y), mmToMicrons(z)});
        return static_cast<std::uint32_t>(m.vertices.size() - 1);
    };
    const auto quad = [&](std::array<std::uint32_t, 4> q, int region) {
        m.faces.push_back({{q[0], q[1], q[2]}});
        m.faces.push_back({{q[0], q[2], q[3]}});
        face_region.insert(face_region.end(), {region, region});
    };
    for (int half = 0; half < 2; ++half) {
        const double x0 = half == 0 ? -10 : 0, x1 = half == 0 ? 0 : 10;
        const int region = half == 0 ? 0 : right_region;
        quad({vertex(x0, -10, 0), vertex(x0, 10, 0), vertex(x1, 10, 0), vertex(x1, -10, 0)}, region);
        quad({vertex(x0, -10, 10), vertex(x1, -10, 10), vertex(x1, 10, 10), vertex(x0, 10, 10)}, region);
        quad({vertex(x0, -10, 0), vertex(x1, -10, 0), vertex(x1, -10, 10), vertex(x0, -10, 10)}, region);
        quad({vertex(x0, 10, 0), vertex(x0, 10, 10), vertex(x1, 10, 10), vertex(x1, 10, 0)}, region);
    }
    quad({vertex(-10, -10, 0), vertex(-10, -10, 10), vertex(-10, 10, 10), vertex(-10, 10, 0)}, 0);
    quad({vertex(10, -10, 0), vertex(10, 10, 0), vertex(10, 10, 10), vertex(10, -10, 10)}, right_region);
    return m;
}

const std::vector<MixVector> kAB = {MixVector::only(0, 2), MixVector::only(1, 2)};

Point3 at(double x_mm, double y_mm, double z_mm) {
    return {mmToMicrons(x_mm), mmToMicrons(y_mm), mmToMicrons(z_mm)};
}

double shareB(const FeatheredPaint& paint, const Point3& p) {
    const std::optional<MixVector> mix = paint.exactMixAt(p);
    EXPECT_TRUE(mix.has_value());
    return mix ? (*mix)[1] : -1;
}

TEST(FeatheredPaint, TheBlendIsTheLinearRampAcrossTheBoundary) {
    std::vector<int> face_region;
    const Mesh mesh = halves(face_region);
    const PaintedRegions regions(mesh, face_region, kDepthUm, 6000);
    const FeatheredPaint paint(regions, kAB, 6000, 0.1);
    // an outer wall's centre line 0.2 mm inside the front face, and the middle of the box
    for (const double y : {-9.8, 0.0}) {
        EXPECT_NEAR(shareB(paint, at(0, y, 5)), 0.5, 1e-3) << y;      // the boundary: 50/50
        EXPECT_NEAR(shareB(paint, at(-1.5, y, 5)), 0.25, 1e-3) << y;  // 1.5 mm into A's side: 75/25
        EXPECT_NEAR(shareB(paint, at(1.5, y, 5)), 0.75, 1e-3) << y;
        EXPECT_NEAR(shareB(paint, at(2.7, y, 5)), 0.95, 1e-3) << y;
        EXPECT_EQ(shareB(paint, at(-3.2, y, 5)), 0.0) << y;  // beyond blend/2: the region's own mix
        EXPECT_EQ(shareB(paint, at(-8, y, 5)), 0.0) << y;
        EXPECT_EQ(shareB(paint, at(3.2, y, 5)), 1.0) << y;
    }
    EXPECT_NEAR(shareB(paint, at(-1, -9.8, 9.8)), 1.0 / 3, 1e-3);  // under the top skin
}

TEST(FeatheredPaint, BandsStepMonotonicallyInHalfTheToleranceAtLeastHalfAMillimetreWide) {
    std::vector<int> face_region;
    const Mesh mesh = halves(face_region);
    const PaintedRegions regions(mesh, face_region, kDepthUm, 6000);
    const FeatheredPaint paint(regions, kAB, 6000, 0.1);
    // a change of 1 in steps of 0.05 would be 20 bands of 0.3 mm: held at 0.5 mm, 12 bands
    EXPECT_EQ(paint.bands(), 2 + 12);
    EXPECT_NEAR(paint.blendMm(), 6.0, 1e-12);
    EXPECT_EQ(paint.regionAt(at(-5, -9.8, 5)), 0);
    EXPECT_EQ(paint.regionAt(at(5, -9.8, 5)), 1);
    EXPECT_EQ(paint.regionAt(at(-1.6, -9.8, 5)), 2 + 2);  // 1.4 mm from the zone's edge: the third step
    EXPECT_NEAR(paint.bandMix(2 + 2)[1], 2.5 / 12, 1e-12);
    double last = -1;
    int steps = 0, previous = -1;
    for (double x = -5; x <= 5; x += 0.05) {
        const int band = paint.regionAt(at(x, -9.8, 5));
        const double share = paint.bandMix(band)[1];
        EXPECT_GE(share, last) << x;
        EXPECT_NEAR(share, std::clamp((x + 3) / 6, 0.0, 1.0), 0.5 / 12 + 1e-3) << x;  // within half a step
        steps += band != previous;
        previous = band;
        last = share;
    }
    EXPECT_EQ(steps, 14);  // each band once, left to right
    // a tolerance of 0.4 needs only 5 steps of 0.2
    EXPECT_EQ(FeatheredPaint(regions, kAB, 6000, 0.4).bands(), 2 + 5);
}

TEST(FeatheredPaint, NoBlendGivesThePaintedRegions) {
    std::vector<int> face_region;
    const Mesh mesh = halves(face_region);
    const PaintedRegions plain(mesh, face_region, 3000);
    const PaintedRegions reaching(mesh, face_region, 3000, 6000);
    const FeatheredPaint none(reaching, kAB, 0, 0.1);
    int painted = 0;
    for (double x = -11; x <= 11; x += 0.7)
        for (double y = -11; y <= 11; y += 0.9)
            for (double z = -1; z <= 11; z += 1.1) {
                const int region = plain.regionAt(at(x, y, z));
                EXPECT_EQ(reaching.regionAt(at(x, y, z)), region);
                EXPECT_EQ(none.regionAt(at(x, y, z)), region);
                painted += region >= 0;
            }
    EXPECT_GT(painted, 1000);
}

TEST(FeatheredPaint, AnEdgeAgainstUnpaintedSurfaceStaysHard) {
    std::vector<int> face_region;
    const Mesh mesh = halves(face_region, -1);
    const PaintedRegions regions(mesh, face_region, kDepthUm, 6000);
    const FeatheredPaint paint(regions, {MixVector::only(0, 2)}, 6000, 0.1);
    EXPECT_EQ(paint.bands(), 1);
    EXPECT_EQ(paint.regionAt(at(-0.5, -9.8, 5)), 0);
    EXPECT_EQ(shareB(paint, at(-0.5, -9.8, 5)), 0.0);
    EXPECT_EQ(paint.regionAt(at(0.5, -9.8, 5)), -1);
    EXPECT_FALSE(paint.exactMixAt(at(0.5, -9.8, 5)).has_value());
}

TEST(FeatheredPaint, ANegativeBlendIsAnInputErrorNamingTheKey) {
    std::vector<int> face_region;
    Mesh mesh = halves(face_region);
    for (const int r : face_region)
        mesh.face_colors.push_back(Mesh::kPaintedRgb | (r == 0 ? 0xffff00u : 0x0000ffu));
    const PigmentModel model({{255, 255, 0}, {0, 0, 255}});
    const Settings scope = test::defaultsWith("mesh", SettingValues{{"mixing_paint_blend", "-2"}});
    try {
        paintOf(mesh, scope, {{255, 255, 0}, {0, 0, 255}}, model);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("'mixing_paint_blend'"), std::string::npos) << e.what();
    }
    const Settings fine = test::defaultsWith("mesh", SettingValues{{"mixing_paint_blend", "6"}});
    EXPECT_EQ(paintOf(mesh, fine, {{255, 255, 0}, {0, 0, 255}}, model).blend_um, 6000);
}

}  // namespace
}  // namespace mixengine
