// The input checks of the contact queries name the C++ argument.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/common/errors.h"
#include "core/geometry/contact_manifold.h"
#include "core/geometry/core_distance.h"
#include "core/geometry/posed_shape.h"
#include "core/geometry/segment_contact.h"
#include "core/geometry/convex_shape.h"
#include "contact_reference.h"

using namespace contact_reference;  // wiregrain and the Eigen types as well

namespace {

TEST(ContactGeometryErrors, BadInputsNameTheArgument) {
  const ConvexShape cube = ConvexShape::cube(1.0, 0.1);
  const auto argument_of = [](auto&& call) {
    try {
      call();
    } catch (const InvalidArgument& e) {
      return e.argument();
    }
    return std::string("(none)");
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const PosedShape a(cube, Vector3d::Zero(), kIdentity);
  const PosedShape b(cube, Vector3d(0, 0, 1.3), kIdentity);
  EXPECT_EQ(argument_of([&] { PosedShape(cube, Vector3d(nan, 0, 0), kIdentity); }), "position");
  EXPECT_EQ(argument_of([&] { PosedShape(cube, Vector3d::Zero(), Quaterniond(0, 0, 0, 0)); }),
            "orientation");
  EXPECT_EQ(argument_of([&] { contact_manifold(a, b, nan); }), "activation_distance");
  EXPECT_EQ(argument_of([&] { core_distance(a, b, -1.0); }), "early_exit_distance");
  ContactOptions bad;
  bad.angle_tolerance = -1;
  EXPECT_EQ(argument_of([&] { contact_manifold(a, b, 0.1, bad); }), "angle_tolerance");
  bad = ContactOptions();
  bad.max_points = -2;
  EXPECT_EQ(argument_of([&] { contact_manifold(a, b, 0.1, bad); }), "max_points");
  EXPECT_EQ(argument_of([&] { plane_contact(Plane{Vector3d::Zero(), Vector3d::Zero()}, a, 0.1); }),
            "wall.normal");
  EXPECT_EQ(argument_of([&] { segment_contact(a, Vector3d::Zero(), Vector3d::UnitX(), -0.1); }),
            "wire_radius");
  EXPECT_EQ(argument_of([&] { segment_contact(a, Vector3d(nan, 0, 0), Vector3d::UnitX(), 0.1); }),
            "end0");
  // a non-unit quaternion is normalised
  const PosedShape scaled(cube, Vector3d(0, 0, 1.3), Quaterniond(2, 0, 0, 0));
  EXPECT_NEAR(contact_manifold(a, scaled, 0.1).gap, 0.1, 1e-12);
}

}  // namespace
