// The grain shape library: body frames and their round trip through serialisation.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/common/errors.h"
#include "core/geometry/shape_library.h"

using namespace wiregrain;

// A box of 1 x 2 x 3 added in a rotated, shifted frame: the library stores it with its
// centroid at the origin and its principal moments ascending, m(b²+c²)/12, ...; the
// placement maps the body frame back onto the input vertices.
TEST(ShapeLibrary, BodyFrameAndPlacement) {
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d shift(0.3, -1.0, 2.0);
  const ConvexShape input = ConvexShape::box(1.0, 2.0, 3.0).transformed(rotation, shift);
  ShapeLibrary library(MassModel::sharp_polyhedron);
  ShapeLibrary::Placement placement;
  const int index = library.add(input, &placement);
  ASSERT_EQ(index, 0);
  const GrainShape& g = library[0];
  EXPECT_NEAR(g.volume, 6.0, 1e-12);
  // box a x b x c = 1 x 2 x 3, m = 6: moments m(a²+b²)/12 < m(a²+c²)/12 < m(b²+c²)/12
  EXPECT_NEAR(g.unit_inertia.x(), 6.0 * (1.0 + 4.0) / 12.0, 1e-12);
  EXPECT_NEAR(g.unit_inertia.y(), 6.0 * (1.0 + 9.0) / 12.0, 1e-12);
  EXPECT_NEAR(g.unit_inertia.z(), 6.0 * (4.0 + 9.0) / 12.0, 1e-12);
  EXPECT_NEAR(placement.centroid.x(), shift.x(), 1e-12);
  // every body-frame vertex, placed, is one of the input vertices
  for (const Eigen::Vector3d& v : g.shape.vertices()) {
    const Eigen::Vector3d placed = placement.rotation * v + placement.centroid;
    double nearest = 1e300;
    for (const Eigen::Vector3d& w : input.vertices()) nearest = std::min(nearest, (placed - w).norm());
    EXPECT_LT(nearest, 1e-12);
  }
}

TEST(ShapeLibrary, SerialiseRoundTrip) {
  ShapeLibrary library(MassModel::dilated);
  for (int k = 0; k < 20; ++k) library.add(ConvexShape::random_ellipsoid(1000 + k, 20, 0.9, 0.8, 0.6, 0.1));
  library.add(ConvexShape::cube(1.0, 0.05));
  const ShapeLibrary copy = ShapeLibrary::deserialize(library.serialize());
  ASSERT_EQ(copy.size(), library.size());
  EXPECT_EQ(copy.model(), MassModel::dilated);
  for (int s = 0; s < library.size(); ++s) {
    EXPECT_EQ(copy[s].shape.vertices().size(), library[s].shape.vertices().size());
    EXPECT_EQ(copy[s].shape.faces().size(), library[s].shape.faces().size());
    EXPECT_NEAR(copy[s].volume, library[s].volume, 1e-14 * library[s].volume);
    EXPECT_NEAR((copy[s].unit_inertia - library[s].unit_inertia).norm(), 0.0, 1e-13);
    EXPECT_EQ(copy[s].bounding_radius, library[s].bounding_radius);
  }
  std::vector<double> broken = library.serialize();
  broken.resize(broken.size() / 2);
  EXPECT_THROW(ShapeLibrary::deserialize(broken), InvalidArgument);
}

// Shapes with equal principal moments keep their input orientation in the library, so
// an axis-aligned cube stays axis-aligned (its vertices at (±a/2, ±a/2, ±a/2)).
TEST(ShapeLibrary, IsotropicShapesKeepTheirAxes) {
  ShapeLibrary library(MassModel::sharp_polyhedron);
  ShapeLibrary::Placement placement;
  library.add(ConvexShape::cube(2.0).transformed(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, 2, 3)), &placement);
  EXPECT_NEAR(placement.rotation.angularDistance(Eigen::Quaterniond::Identity()), 0.0, 1e-14);
  for (const Eigen::Vector3d& v : library[0].shape.vertices())
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(std::abs(v[d]), 1.0, 1e-14);
  library.add(ConvexShape::regular_octahedron(1.0), &placement);
  EXPECT_NEAR(placement.rotation.angularDistance(Eigen::Quaterniond::Identity()), 0.0, 1e-14);
}

// A sphere in the library: its vertex at the origin, the ball's volume and moments
// (4π r³/3, 2/5 V r² at density 1), bounding radius r; it survives the round trip
// through serialize/deserialize with the shapes around it. A library of the sharp
// model refuses it (no sharp volume), naming "model".
TEST(ShapeLibrary, SphereRoundTripAndSharpModelRefused) {
  const double pi = 3.14159265358979323846, r = 0.35;
  ShapeLibrary library(MassModel::dilated);
  library.add(ConvexShape::cube(1.0, 0.05));
  ShapeLibrary::Placement placement;
  const int index = library.add(ConvexShape::from_points({Eigen::Vector3d(2, -1, 0.5)}, r), &placement);
  library.add(ConvexShape::sphere(1.5));
  EXPECT_EQ(index, 1);
  EXPECT_LT((placement.centroid - Eigen::Vector3d(2, -1, 0.5)).norm(), 1e-15);
  EXPECT_EQ(placement.rotation.angularDistance(Eigen::Quaterniond::Identity()), 0.0);
  const double volume = 4.0 / 3.0 * pi * r * r * r;
  const GrainShape& g = library[index];
  ASSERT_TRUE(g.shape.is_sphere());
  EXPECT_EQ(g.shape.vertices()[0], Eigen::Vector3d::Zero());
  EXPECT_NEAR(g.volume, volume, 1e-15 * volume);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(g.unit_inertia[d], 0.4 * volume * r * r, 1e-15 * volume * r * r);
  EXPECT_EQ(g.bounding_radius, r);

  const std::vector<double> image = library.serialize();
  const ShapeLibrary copy = ShapeLibrary::deserialize(image);
  ASSERT_EQ(copy.size(), 3);
  for (int s = 0; s < 3; ++s) {
    EXPECT_EQ(copy[s].shape.is_sphere(), s > 0);
    EXPECT_EQ(copy[s].shape.vertices(), library[s].shape.vertices());
    EXPECT_EQ(copy[s].shape.faces().size(), library[s].shape.faces().size());
    EXPECT_EQ(copy[s].shape.sweep_radius(), library[s].shape.sweep_radius());
    EXPECT_NEAR(copy[s].volume, library[s].volume, 1e-14 * library[s].volume);
    EXPECT_NEAR((copy[s].unit_inertia - library[s].unit_inertia).norm(), 0.0, 1e-14 * library[s].unit_inertia.norm());
    EXPECT_EQ(copy[s].bounding_radius, library[s].bounding_radius);
  }
  // a one-vertex shape without a radius, or with 2 vertices, is corrupt data
  std::vector<double> no_radius = {1.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0};
  EXPECT_THROW(ShapeLibrary::deserialize(no_radius), InvalidArgument);
  std::vector<double> two = {1.0, 1.0, 0.5, 2.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0};
  EXPECT_THROW(ShapeLibrary::deserialize(two), InvalidArgument);

  ShapeLibrary sharp(MassModel::sharp_polyhedron);
  try {
    sharp.add(ConvexShape::sphere(1.0));
    ADD_FAILURE() << "a sphere joined a library of the sharp model";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "model");
  }
  EXPECT_EQ(sharp.size(), 0);
}

// The built shapes are a cache over the records: deserialize() keeps none built, operator[]
// builds the entry asked for, release_built_except() drops the others. A shape built again
// has the record's vertices and mass properties to the bit, and a deserialized shape built
// again is the first build to the bit (faces, normals, offsets), so a rank that drops and
// rebuilds a grain's shape sees the same grain.
TEST(ShapeLibrary, BuiltShapesAreReleasedAndRebuiltTheSame) {
  ShapeLibrary made(MassModel::dilated);
  for (int k = 0; k < 6; ++k) made.add(ConvexShape::random_ellipsoid(2000 + k, 20, 0.9, 0.8, 0.6, 0.1));
  EXPECT_EQ(made.built_count(), 6);
  const std::vector<Eigen::Vector3d> vertices = made[2].shape.vertices();
  const double volume = made[2].volume, radius = made[2].bounding_radius;
  const Eigen::Vector3d inertia = made[2].unit_inertia;
  std::vector<char> needed(6, 0);
  needed[4] = 1;
  made.release_built_except(needed);
  EXPECT_EQ(made.built_count(), 1);
  ASSERT_EQ(made.vertices(2).size(), vertices.size());  // the record, read without building
  EXPECT_EQ(made.vertices(2)[5], vertices[5]);
  EXPECT_EQ(made.sweep_radius(2), 0.1);
  EXPECT_EQ(made.built_count(), 1);
  const GrainShape& rebuilt = made[2];
  EXPECT_EQ(made.built_count(), 2);
  ASSERT_EQ(rebuilt.shape.vertices().size(), vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v) EXPECT_EQ(rebuilt.shape.vertices()[v], vertices[v]);
  EXPECT_EQ(rebuilt.volume, volume);
  EXPECT_EQ(rebuilt.unit_inertia, inertia);
  EXPECT_EQ(rebuilt.bounding_radius, radius);

  const ShapeLibrary read = ShapeLibrary::deserialize(made.serialize());
  EXPECT_EQ(read.built_count(), 0);
  std::vector<ConvexShape::Face> first = read[3].shape.faces();
  const double first_volume = read[3].volume;
  EXPECT_EQ(read.built_count(), 1);
  ShapeLibrary again = ShapeLibrary::deserialize(made.serialize());
  again.release_built_except({});
  ASSERT_EQ(again[3].shape.faces().size(), first.size());
  for (std::size_t f = 0; f < first.size(); ++f) {
    EXPECT_EQ(again[3].shape.faces()[f].vertices, first[f].vertices);
    EXPECT_EQ(again[3].shape.faces()[f].normal, first[f].normal);
    EXPECT_EQ(again[3].shape.faces()[f].offset, first[f].offset);
  }
  EXPECT_EQ(again[3].volume, first_volume);
  again.release_built_except({});
  EXPECT_EQ(again.built_count(), 0);
  EXPECT_EQ(again[3].shape.faces().size(), first.size());
}
