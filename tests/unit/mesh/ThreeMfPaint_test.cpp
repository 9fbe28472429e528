// PrusaSlicer/OrcaSlicer painted facets (mesh/formats/ThreeMfPaint.h): the attribute's encoding.
#include "mesh/formats/ThreeMfPaint.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

TEST(ThreeMfPaint, WholeFacets) {
    EXPECT_EQ(paintedExtruder(""), 0);
    EXPECT_EQ(paintedExtruder("0"), 0);
    EXPECT_EQ(paintedExtruder("4"), 1);
    EXPECT_EQ(paintedExtruder("8"), 2);
    EXPECT_EQ(paintedExtruder("0C"), 3);  // 3 + the next digit (read from the end)
    EXPECT_EQ(paintedExtruder("1C"), 4);
    EXPECT_EQ(paintedExtruder("Dc"), 16);
}

TEST(ThreeMfPaint, SplitFacetsTakeMostOfTheirSubFacets) {
    EXPECT_EQ(paintedExtruder("441"), 1);    // split in two, both extruder 1
    EXPECT_EQ(paintedExtruder("48883"), 2);  // split in four (3 sides): 2, 2, 2 and 1
    EXPECT_EQ(paintedExtruder("41"), 0);     // a child missing: malformed
    EXPECT_EQ(paintedExtruder("xyz"), 0);
}

}  // namespace
}  // namespace mixengine
