// Load curves (model/curve.cpp): the factor by linear interpolation with flat ends, and its
// integral from 0 to t, exact for the piecewise-linear curve (reference: the areas of the
// trapezoids and rectangles worked out by hand below).
#include <gtest/gtest.h>

#include "fpmshell/model/model.hpp"

using namespace fpmshell;

TEST(Curve, ValueInterpolatesAndIsFlatOutside) {
    const Curve c{"ramp", {{1.0, 0.0}, {3.0, 4.0}}};
    EXPECT_DOUBLE_EQ(c.value(0.0), 0.0);
    EXPECT_DOUBLE_EQ(c.value(2.0), 2.0);
    EXPECT_DOUBLE_EQ(c.value(5.0), 4.0);
}

TEST(Curve, IntegralIsTheAreaUnderThePolyline) {
    // 0 on [0, 1], the ramp to 4 on [1, 3] (area 4), then flat at 4.
    const Curve c{"ramp", {{1.0, 0.0}, {3.0, 4.0}}};
    EXPECT_DOUBLE_EQ(c.integral(0.5), 0.0);
    EXPECT_DOUBLE_EQ(c.integral(2.0), 1.0);  // the triangle under the ramp up to t = 2
    EXPECT_DOUBLE_EQ(c.integral(3.0), 4.0);
    EXPECT_DOUBLE_EQ(c.integral(4.5), 4.0 + 1.5 * 4.0);
    // A curve starting at a nonzero factor before its first point: a rectangle from t = 0.
    const Curve step{"step", {{0.5, 2.0}, {1.0, 2.0}}};
    EXPECT_DOUBLE_EQ(step.integral(0.25), 0.5);
}

TEST(Curve, NoCurveMeansFactorOne) {
    const std::vector<Curve> curves{{"half", {{0.0, 0.5}}}};
    EXPECT_DOUBLE_EQ(curve_factor(curves, -1, 7.0), 1.0);
    EXPECT_DOUBLE_EQ(curve_factor_integral(curves, -1, 7.0), 7.0);
    EXPECT_DOUBLE_EQ(curve_factor(curves, 0, 7.0), 0.5);
    EXPECT_DOUBLE_EQ(curve_factor_integral(curves, 0, 7.0), 3.5);
}
