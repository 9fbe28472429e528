#include <gtest/gtest.h>

#include "geometry/Point.h"

TEST(Geometry, MillimetresToMicronsRounds) {
    EXPECT_EQ(mixengine::mmToMicrons(0.2), 200);
    EXPECT_EQ(mixengine::mmToMicrons(-0.0004), 0);
}
