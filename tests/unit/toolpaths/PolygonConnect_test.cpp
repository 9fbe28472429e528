// Joining infill loops that lie side by side (toolpaths/infill/PolygonConnect.h).
#include "toolpaths/infill/PolygonConnect.h"

#include <gtest/gtest.h>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

using test::square;

double totalLength(const Paths& loops) {
    double total = 0;
    for (const Path& loop : loops)
        total += lengthUm(loop, true);
    return total;
}

TEST(PolygonConnect, ConcentricSquaresOneLineWidthApartBecomeOneLoop) {
    const Paths rings{square(0, 0, 10'000), square(400, 400, 9'200), square(800, 800, 8'400)};
    const Paths joined = connectLoops(rings, 400);
    ASSERT_EQ(joined.size(), 1U);
    // Each join cuts a line width out of both loops and adds two bridges of about a line width.
    EXPECT_NEAR(totalLength(joined), totalLength(rings), 4.0 * 400);
}

TEST(PolygonConnect, LoopsFarApartStayAndTinyOnesGo) {
    const Paths loops{square(0, 0, 5'000), square(20'000, 0, 5'000), square(40'000, 0, 150)};
    const Paths joined = connectLoops(loops, 400);
    EXPECT_EQ(joined.size(), 2U);  // the 150 µm square is shorter than two line widths
}

}  // namespace
}  // namespace mixengine
