// Convex hulls of grain vertices and their mass properties, against analytic values.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <unistd.h>

#include "core/geometry/convex_shape.h"
#include "core/common/errors.h"

using namespace wiregrain;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

constexpr double kPi = 3.14159265358979323846;

double relative_error(double value, double expected) {
  return std::abs(value - expected) / std::abs(expected);
}

// A uniformly distributed rotation (normalised 4D Gaussian quaternion).
Matrix3d random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  Eigen::Quaterniond q(gauss(rng), gauss(rng), gauss(rng), gauss(rng));
  return q.normalized().toRotationMatrix();
}

// Points on the ellipsoid with semi-axes (a, b, c), drawn in the test itself.
std::vector<Vector3d> ellipsoid_points(std::mt19937_64& rng, int n, const Vector3d& semi_axes) {
  std::normal_distribution<double> gauss;
  std::vector<Vector3d> points;
  for (int i = 0; i < n; ++i) {
    Vector3d d(gauss(rng), gauss(rng), gauss(rng));
    points.push_back(semi_axes.cwiseProduct(d.normalized()));
  }
  return points;
}

double size_of(const ConvexShape& shape) {
  double r = 0.0;
  for (const auto& v : shape.vertices()) r = std::max(r, v.norm());
  return r;
}

// Structural checks of a hull: closed 2-manifold of genus 0 (V − E + F = 2), convex
// (every vertex on the inner side of every face plane), outward unit normals,
// counter-clockwise face loops, planar faces, and the input points inside.
void expect_valid_hull(const ConvexShape& shape, const std::vector<Vector3d>& inputs,
                       const std::string& label) {
  const double scale = size_of(shape);
  const double tol = 1e-12 * scale;
  const auto& v = shape.vertices();
  const long n_v = static_cast<long>(v.size()), n_e = static_cast<long>(shape.edges().size()),
             n_f = static_cast<long>(shape.faces().size());
  EXPECT_EQ(n_v - n_e + n_f, 2) << label;

  Vector3d mean = Vector3d::Zero();
  for (const auto& p : v) mean += p;
  mean /= static_cast<double>(n_v);

  std::set<std::pair<int, int>> directed;
  for (const auto& face : shape.faces()) {
    EXPECT_GE(face.vertices.size(), 3u) << label;
    EXPECT_NEAR(face.normal.norm(), 1.0, 1e-14) << label;
    // outward: the face plane is farther out than the interior point
    EXPECT_GT(face.offset - face.normal.dot(mean), 0.0) << label;
    // planar, and the loop turns counter-clockwise about the outward normal
    const std::size_t m = face.vertices.size();
    for (std::size_t i = 0; i < m; ++i) {
      const Vector3d& a = v[face.vertices[i]];
      const Vector3d& b = v[face.vertices[(i + 1) % m]];
      const Vector3d& c = v[face.vertices[(i + 2) % m]];
      EXPECT_NEAR(face.normal.dot(a), face.offset, tol) << label;
      EXPECT_GT((b - a).cross(c - b).dot(face.normal), 0.0) << label << " corner turns cw";
      directed.insert({face.vertices[i], face.vertices[(i + 1) % m]});
    }
    for (const auto& p : v) EXPECT_LE(face.normal.dot(p), face.offset + tol) << label;
    for (const auto& p : inputs) EXPECT_LE(face.normal.dot(p), face.offset + tol) << label;
  }
  // every edge is traversed once in each direction (closed, consistently oriented)
  EXPECT_EQ(static_cast<long>(directed.size()), 2 * n_e) << label;
  for (const auto& e : shape.edges()) {
    EXPECT_LT(e[0], e[1]);
    EXPECT_EQ(directed.count({e[0], e[1]}), 1u) << label;
    EXPECT_EQ(directed.count({e[1], e[0]}), 1u) << label;
  }
}

void expect_isotropic_inertia(const MassProperties& p, double moment, double tol,
                              const std::string& label) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(p.inertia(i, j), i == j ? moment : 0.0, tol * moment) << label << " I" << i << j;
}

template <class F>
void expect_invalid_argument(F&& f, const std::string& argument, const std::string& text) {
  try {
    f();
    ADD_FAILURE() << "no InvalidArgument for " << argument;
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), argument) << e.what();
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos)
        << "message \"" << e.what() << "\" lacks \"" << text << "\"";
  }
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Regular solids: volume, centroid, inertia (sharp polyhedron)

TEST(ConvexShapeMass, Cube) {
  const double a = 1.7, rho = 2.3;
  const ConvexShape cube = ConvexShape::cube(a);
  EXPECT_EQ(cube.vertices().size(), 8u);
  EXPECT_EQ(cube.edges().size(), 12u);
  ASSERT_EQ(cube.faces().size(), 6u);
  for (const auto& f : cube.faces()) EXPECT_EQ(f.vertices.size(), 4u);
  const MassProperties p = cube.sharp_mass_properties(rho);
  const double m = rho * a * a * a;
  EXPECT_LT(relative_error(p.volume, a * a * a), 1e-12);
  EXPECT_LT(relative_error(p.mass, m), 1e-12);
  EXPECT_LT(p.centroid.norm(), 1e-12 * a);
  expect_isotropic_inertia(p, m * a * a / 6.0, 1e-12, "cube");
  EXPECT_DOUBLE_EQ(cube.bounding_radius(), std::sqrt(3.0) * a / 2.0);
}

TEST(ConvexShapeMass, Box) {
  const double lx = 1.0, ly = 2.0, lz = 3.5, rho = 0.7;
  const Vector3d shift(0.3, -4.0, 10.0);
  std::vector<Vector3d> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back(shift + Vector3d((i & 1 ? 0.5 : -0.5) * lx, (i & 2 ? 0.5 : -0.5) * ly,
                                       (i & 4 ? 0.5 : -0.5) * lz));
  const MassProperties p = ConvexShape::from_points(corners, 0.0).sharp_mass_properties(rho);
  const double m = rho * lx * ly * lz;
  EXPECT_LT(relative_error(p.volume, lx * ly * lz), 1e-12);
  EXPECT_LT((p.centroid - shift).norm(), 1e-12 * shift.norm());
  const Vector3d expected(m * (ly * ly + lz * lz) / 12.0, m * (lx * lx + lz * lz) / 12.0,
                          m * (lx * lx + ly * ly) / 12.0);
  for (int i = 0; i < 3; ++i) {
    EXPECT_LT(relative_error(p.inertia(i, i), expected[i]), 1e-12) << i;
    for (int j = 0; j < 3; ++j)
      if (i != j) {
        EXPECT_NEAR(p.inertia(i, j), 0.0, 1e-12 * expected.maxCoeff());
      }
  }
  const PrincipalAxes axes = principal_axes(p.inertia);
  // ascending: the longest side (z) has the smallest moment
  EXPECT_LT(relative_error(axes.moments[0], expected[2]), 1e-12);
  EXPECT_LT(relative_error(axes.moments[1], expected[1]), 1e-12);
  EXPECT_LT(relative_error(axes.moments[2], expected[0]), 1e-12);
  EXPECT_NEAR(std::abs(axes.axes(2, 0)), 1.0, 1e-12);
  EXPECT_NEAR(axes.axes.determinant(), 1.0, 1e-14);
}

// Regular tetrahedron of edge a: V = a³/(6√2); inertia isotropic, I = m a²/20.
TEST(ConvexShapeMass, RegularTetrahedron) {
  const double a = 0.9, rho = 1.5;
  const ConvexShape t = ConvexShape::regular_tetrahedron(a);
  EXPECT_EQ(t.vertices().size(), 4u);
  EXPECT_EQ(t.edges().size(), 6u);
  EXPECT_EQ(t.faces().size(), 4u);
  for (const auto& e : t.edges())
    EXPECT_LT(relative_error((t.vertices()[e[0]] - t.vertices()[e[1]]).norm(), a), 1e-15);
  const MassProperties p = t.sharp_mass_properties(rho);
  const double volume = a * a * a / (6.0 * std::sqrt(2.0));
  EXPECT_LT(relative_error(p.volume, volume), 1e-12);
  EXPECT_LT(p.centroid.norm(), 1e-12 * a);
  expect_isotropic_inertia(p, rho * volume * a * a / 20.0, 1e-12, "tetrahedron");
}

// Regular octahedron of edge a: V = √2 a³/3; inertia isotropic, I = m a²/10.
TEST(ConvexShapeMass, RegularOctahedron) {
  const double a = 1.3, rho = 0.4;
  const ConvexShape o = ConvexShape::regular_octahedron(a);
  EXPECT_EQ(o.vertices().size(), 6u);
  EXPECT_EQ(o.edges().size(), 12u);
  EXPECT_EQ(o.faces().size(), 8u);
  const MassProperties p = o.sharp_mass_properties(rho);
  const double volume = std::sqrt(2.0) * a * a * a / 3.0;
  EXPECT_LT(relative_error(p.volume, volume), 1e-12);
  EXPECT_LT(p.centroid.norm(), 1e-12 * a);
  expect_isotropic_inertia(p, rho * volume * a * a / 10.0, 1e-12, "octahedron");
}

// A rigid motion of the input points moves the centroid with it and rotates the inertia
// tensor: c' = R c + t, I' = R I Rᵀ, same volume and principal moments.
TEST(ConvexShapeMass, InvariantUnderRigidMotion) {
  std::mt19937_64 rng(42);
  for (int trial = 0; trial < 20; ++trial) {
    const auto points = ellipsoid_points(rng, 30, Vector3d(1.0, 0.8, 0.6));
    const Matrix3d rotation = random_rotation(rng);
    const Vector3d translation(5.0 * trial, -3.0, 0.25 * trial);
    std::vector<Vector3d> moved;
    for (const auto& p : points) moved.push_back(rotation * p + translation);
    const ConvexShape a = ConvexShape::from_points(points, 0.1);
    const ConvexShape b = ConvexShape::from_points(moved, 0.1);
    for (MassModel model : {MassModel::sharp_polyhedron, MassModel::dilated}) {
      const MassProperties pa = a.mass_properties(1.5, model);
      const MassProperties pb = b.mass_properties(1.5, model);
      EXPECT_LT(relative_error(pb.volume, pa.volume), 1e-10);
      EXPECT_LT((pb.centroid - (rotation * pa.centroid + translation)).norm(), 1e-10);
      const Matrix3d rotated = rotation * pa.inertia * rotation.transpose();
      EXPECT_LT((pb.inertia - rotated).norm(), 1e-10 * pa.inertia.norm());
      const Vector3d ma = principal_axes(pa.inertia).moments;
      const Vector3d mb = principal_axes(pb.inertia).moments;
      EXPECT_LT((ma - mb).norm(), 1e-10 * ma.norm());
    }
    EXPECT_EQ(a.faces().size(), b.faces().size());
  }
}

// ---------------------------------------------------------------------------------------
// Hull structure

TEST(ConvexShapeHull, EllipsoidHullsAreValid) {
  std::mt19937_64 rng(7);
  for (int n : {4, 5, 8, 20, 100, 500}) {
    for (int trial = 0; trial < 5; ++trial) {
      const auto points = ellipsoid_points(rng, n, Vector3d(1.0, 0.8, 0.6));
      const ConvexShape shape = ConvexShape::from_points(points, 0.1);
      const std::string label = "N=" + std::to_string(n) + " trial " + std::to_string(trial);
      // points on a strictly convex surface are all extreme
      EXPECT_EQ(shape.vertices().size(), static_cast<std::size_t>(n)) << label;
      expect_valid_hull(shape, points, label);
      for (MassModel model : {MassModel::sharp_polyhedron, MassModel::dilated}) {
        const MassProperties p = shape.mass_properties(1.5, model);
        const Vector3d moments = principal_axes(p.inertia).moments;
        EXPECT_GT(moments[0], 0.0) << label;  // positive definite
        // triangle inequality of a real mass distribution: I_1 + I_2 >= I_3
        EXPECT_GE(moments[0] + moments[1], moments[2]) << label;
      }
    }
  }
}

// The factory's points lie on the ellipsoid surface, every one is a vertex, and a
// fine hull approaches the ellipsoid's volume 4π abc/3 from below.
TEST(ConvexShapeHull, RandomEllipsoidFactory) {
  const double a = 0.9, b = 0.8 * a, c = 0.6 * a;
  std::mt19937_64 rng(2024);
  for (int trial = 0; trial < 10; ++trial) {
    const ConvexShape shape = ConvexShape::random_ellipsoid(rng, 20, a, 0.8, 0.6, 0.1);
    EXPECT_EQ(shape.vertices().size(), 20u);
    EXPECT_DOUBLE_EQ(shape.sweep_radius(), 0.1);
    for (const auto& v : shape.vertices()) {
      const double level = std::pow(v.x() / a, 2) + std::pow(v.y() / b, 2) + std::pow(v.z() / c, 2);
      EXPECT_NEAR(level, 1.0, 1e-14);
    }
    expect_valid_hull(shape, {}, "ellipsoid trial " + std::to_string(trial));
  }
  // same seed, same shape
  const ConvexShape s1 = ConvexShape::random_ellipsoid(std::uint64_t{99}, 20, a, 0.8, 0.6, 0.1);
  const ConvexShape s2 = ConvexShape::random_ellipsoid(std::uint64_t{99}, 20, a, 0.8, 0.6, 0.1);
  ASSERT_EQ(s1.vertices().size(), s2.vertices().size());
  for (std::size_t i = 0; i < s1.vertices().size(); ++i)
    EXPECT_EQ(s1.vertices()[i], s2.vertices()[i]);

  const double ellipsoid_volume = 4.0 * kPi * a * b * c / 3.0;
  const ConvexShape fine = ConvexShape::random_ellipsoid(std::uint64_t{5}, 4000, a, 0.8, 0.6, 0.0);
  const double v = fine.sharp_mass_properties(1.0).volume;
  EXPECT_LT(v, ellipsoid_volume);
  EXPECT_LT(relative_error(v, ellipsoid_volume), 1e-2);
  // a solid ellipsoid has I_x = m (b² + c²)/5, ...
  const Vector3d m = fine.sharp_mass_properties(1.0).inertia.diagonal();
  EXPECT_LT(relative_error(m[0], v * (b * b + c * c) / 5.0), 2e-2);
  EXPECT_LT(relative_error(m[2], v * (a * a + b * b) / 5.0), 2e-2);
}

// Coplanar hull triangles merge: a cube is 6 quadrilaterals even when rotated (rounding
// makes its faces only nearly planar) and when points on its edges and faces are added.
TEST(ConvexShapeHull, CoplanarTrianglesMerge) {
  std::mt19937_64 rng(3);
  std::vector<Vector3d> corners;
  for (int i = 0; i < 8; ++i)
    corners.emplace_back(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5);
  std::vector<Vector3d> decorated = corners;
  decorated.emplace_back(0.0, 0.5, 0.5);   // mid-edge
  decorated.emplace_back(0.5, 0.0, -0.5);  // mid-edge
  decorated.emplace_back(0.5, 0.1, 0.2);   // inside a face
  decorated.emplace_back(0.1, 0.0, 0.2);   // inside the cube
  // a 5 x 5 grid on every face: many coplanar and collinear points
  std::vector<Vector3d> grid;
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-0.5, 0.5})
      for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) {
          Vector3d p;
          p[axis] = side;
          p[(axis + 1) % 3] = -0.5 + 0.25 * i;
          p[(axis + 2) % 3] = -0.5 + 0.25 * j;
          grid.push_back(p);
        }
  // (the grid repeats points on edges shared by two faces: keep one copy)
  std::vector<Vector3d> unique_grid;
  for (const auto& p : grid)
    if (std::none_of(unique_grid.begin(), unique_grid.end(),
                     [&](const Vector3d& q) { return (p - q).norm() < 1e-12; }))
      unique_grid.push_back(p);
  for (const auto& input : {corners, decorated, unique_grid}) {
    for (int trial = 0; trial < 30; ++trial) {
      const Matrix3d rotation = trial == 0 ? Matrix3d::Identity() : random_rotation(rng);
      std::vector<Vector3d> points;
      for (const auto& p : input) points.push_back(rotation * p + Vector3d(1.0, 2.0, 3.0));
      const ConvexShape cube = ConvexShape::from_points(points, 0.0);
      EXPECT_EQ(cube.vertices().size(), 8u);
      EXPECT_EQ(cube.edges().size(), 12u);
      ASSERT_EQ(cube.faces().size(), 6u);
      for (const auto& f : cube.faces()) EXPECT_EQ(f.vertices.size(), 4u);
      expect_valid_hull(cube, points, "cube trial " + std::to_string(trial));
      EXPECT_LT(relative_error(cube.sharp_mass_properties(1.0).volume, 1.0), 1e-12);
    }
  }
}

// ---------------------------------------------------------------------------------------
// Body frame

TEST(ConvexShapeBodyFrame, PrincipalAxesAndCentroid) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 10; ++trial) {
    const ConvexShape shape = ConvexShape::random_ellipsoid(rng, 20, 1.0, 0.8, 0.6, 0.1)
                                  .transformed(random_rotation(rng), Vector3d(3.0, -1.0, 2.0));
    for (MassModel model : {MassModel::sharp_polyhedron, MassModel::dilated}) {
      const BodyFrameShape body = to_body_frame(shape, 1.5, model);
      const MassProperties p = body.shape.mass_properties(1.5, model);
      EXPECT_LT(p.centroid.norm(), 1e-12);
      const double scale = body.principal_moments.maxCoeff();
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          EXPECT_NEAR(p.inertia(i, j), i == j ? body.principal_moments[i] : 0.0, 1e-12 * scale);
      EXPECT_LE(body.principal_moments[0], body.principal_moments[1]);
      EXPECT_LE(body.principal_moments[1], body.principal_moments[2]);
      EXPECT_NEAR(body.rotation.norm(), 1.0, 1e-15);
      // x_input = R x_body + c, vertex by vertex
      ASSERT_EQ(body.shape.vertices().size(), shape.vertices().size());
      for (std::size_t i = 0; i < shape.vertices().size(); ++i)
        EXPECT_LT((body.rotation * body.shape.vertices()[i] + body.centroid - shape.vertices()[i]).norm(),
                  1e-12 * 4.0);
      // bounding sphere about the centroid contains every vertex swept by r
      EXPECT_NEAR(body.shape.bounding_radius(),
                  [&] {
                    double r = 0.0;
                    for (const auto& v : shape.vertices()) r = std::max(r, (v - body.centroid).norm());
                    return r + 0.1;
                  }(),
                  1e-12);
    }
  }
  // a box given rotated comes back with its analytic moments along x, y, z
  const Matrix3d rotation = random_rotation(rng);
  const ConvexShape box = ConvexShape::box(3.0, 1.0, 2.0).transformed(rotation, Vector3d(1, 1, 1));
  const BodyFrameShape body = to_body_frame(box, 1.0);
  const double m = 6.0;
  EXPECT_LT(relative_error(body.principal_moments[0], m * (1.0 + 4.0) / 12.0), 1e-12);
  EXPECT_LT(relative_error(body.principal_moments[1], m * (9.0 + 1.0) / 12.0), 1e-12);
  EXPECT_LT(relative_error(body.principal_moments[2], m * (9.0 + 4.0) / 12.0), 1e-12);
  Vector3d extent = Vector3d::Zero();
  for (const auto& v : body.shape.vertices()) extent = extent.cwiseMax(v.cwiseAbs());
  EXPECT_LT((extent - Vector3d(1.5, 1.0, 0.5)).norm(), 1e-12);  // long axis = smallest moment
}

// ---------------------------------------------------------------------------------------
// Dilated (spheropolyhedron) mass properties

namespace {

// ∫ x² dV over the box [-lx/2, lx/2]×[-ly/2, ly/2]×[-lz/2, lz/2] dilated by r, summed
// piece by piece: core box, 6 slabs, 12 quarter cylinders, 8 sphere octants.
double rounded_box_second_moment_x(double lx, double ly, double lz, double r) {
  const double pi = kPi, x0 = 0.5 * lx;
  const double core = ly * lz * lx * lx * lx / 12.0;
  const double x_slabs = 2.0 * ly * lz * (std::pow(x0 + r, 3) - std::pow(x0, 3)) / 3.0;
  const double yz_slabs = 2.0 * r * lx * lx * lx * (lz + ly) / 12.0;
  const double x_edges = 4.0 * (pi * r * r / 4.0) * lx * lx * lx / 12.0;
  // quarter disc at x0 reaching outward: ∫(x0 + ξ)² dA = A x0² + 2 x0 r³/3 + π r⁴/16
  const double quarter_disc = pi * r * r / 4.0 * x0 * x0 + 2.0 * x0 * r * r * r / 3.0 +
                              pi * std::pow(r, 4) / 16.0;
  const double yz_edges = 4.0 * (ly + lz) * quarter_disc;
  // octant at x0: ∫(x0 + ξ)² dV = (π r³/6) x0² + 2 x0 π r⁴/16 + π r⁵/30
  const double octant = pi * std::pow(r, 3) / 6.0 * x0 * x0 + 2.0 * x0 * pi * std::pow(r, 4) / 16.0 +
                        pi * std::pow(r, 5) / 30.0;
  return core + x_slabs + yz_slabs + x_edges + yz_edges + 8.0 * octant;
}

double rounded_box_volume(double lx, double ly, double lz, double r) {
  return lx * ly * lz + 2.0 * r * (lx * ly + ly * lz + lz * lx) + kPi * r * r * (lx + ly + lz) +
         4.0 * kPi * r * r * r / 3.0;
}

}  // namespace

TEST(ConvexShapeDilated, RoundedBox) {
  const double lx = 1.0, ly = 1.5, lz = 2.2, r = 0.3, rho = 1.5;
  const double volume = rounded_box_volume(lx, ly, lz, r);
  const double sxx = rounded_box_second_moment_x(lx, ly, lz, r);
  const double syy = rounded_box_second_moment_x(ly, lz, lx, r);
  const double szz = rounded_box_second_moment_x(lz, lx, ly, r);
  const Vector3d expected = rho * Vector3d(syy + szz, sxx + szz, sxx + syy);

  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 5; ++trial) {
    const Matrix3d rotation = trial == 0 ? Matrix3d::Identity() : random_rotation(rng);
    const Vector3d shift(0.5 * trial, 1.0, -2.0);
    const ConvexShape box = ConvexShape::box(lx, ly, lz, r).transformed(rotation, shift);
    const MassProperties p = box.dilated_mass_properties(rho);
    EXPECT_LT(relative_error(p.volume, volume), 1e-12);
    EXPECT_LT((p.centroid - shift).norm(), 1e-12 * 3.0);
    const Matrix3d body = rotation.transpose() * p.inertia * rotation;
    for (int i = 0; i < 3; ++i) {
      EXPECT_LT(relative_error(body(i, i), expected[i]), 1e-12) << i;
      for (int j = 0; j < 3; ++j)
        if (i != j) {
          EXPECT_NEAR(body(i, j), 0.0, 1e-12 * expected.maxCoeff());
        }
    }
  }
  // r = 0 gives the sharp values
  const ConvexShape sharp = ConvexShape::box(lx, ly, lz, 0.0);
  EXPECT_EQ(sharp.dilated_mass_properties(rho).inertia, sharp.sharp_mass_properties(rho).inertia);
}

// Steiner's formula: V_r = V + S r + (r²/2) Σ_e L_e α_e + 4π r³/3, with α_e the exterior
// dihedral angle; the regular solids' inertia stays isotropic (cubic symmetry).
TEST(ConvexShapeDilated, SteinerVolumeOfRegularSolids) {
  const double a = 1.1, r = 0.25;
  {
    const double volume = a * a * a / (6.0 * std::sqrt(2.0)), area = std::sqrt(3.0) * a * a;
    const double alpha = kPi - std::acos(1.0 / 3.0);
    const double expected = volume + area * r + 0.5 * r * r * 6.0 * a * alpha + 4.0 * kPi * r * r * r / 3.0;
    const MassProperties p = ConvexShape::regular_tetrahedron(a, r).dilated_mass_properties(1.0);
    EXPECT_LT(relative_error(p.volume, expected), 1e-12);
    EXPECT_LT(p.centroid.norm(), 1e-13);
    expect_isotropic_inertia(p, p.inertia(0, 0), 1e-12, "dilated tetrahedron");
  }
  {
    const double volume = std::sqrt(2.0) * a * a * a / 3.0, area = 2.0 * std::sqrt(3.0) * a * a;
    const double alpha = kPi - std::acos(-1.0 / 3.0);
    const double expected = volume + area * r + 0.5 * r * r * 12.0 * a * alpha + 4.0 * kPi * r * r * r / 3.0;
    const MassProperties p = ConvexShape::regular_octahedron(a, r).dilated_mass_properties(1.0);
    EXPECT_LT(relative_error(p.volume, expected), 1e-12);
    expect_isotropic_inertia(p, p.inertia(0, 0), 1e-12, "dilated octahedron");
  }
}

// Volume and inertia of P ⊕ B_r are polynomials in r (degree 3 and 5); the leading
// coefficients are those of the ball alone, 4π/3 and (2/5)(4π/3) = 8π/15 (isotropic),
// for any polyhedron: the vertex sectors' normal cones tile the sphere.
TEST(ConvexShapeDilated, LeadingCoefficientsAreTheBall) {
  const ConvexShape base = ConvexShape::random_ellipsoid(std::uint64_t{17}, 20, 1.0, 0.8, 0.6, 0.0);
  const int n = 6;
  Eigen::MatrixXd vandermonde(n, n);
  std::vector<Matrix3d> inertia(n);
  Eigen::VectorXd volume(n);
  for (int k = 0; k < n; ++k) {
    const double r = 0.5 * k;
    for (int j = 0; j < n; ++j) vandermonde(k, j) = std::pow(r, j);
    const ConvexShape s = ConvexShape::from_points(base.vertices(), r);
    const MassProperties p = s.dilated_mass_properties(1.0);
    // inertia about a fixed point (the origin), so that it is polynomial in r
    inertia[k] = p.inertia + p.mass * (p.centroid.squaredNorm() * Matrix3d::Identity() -
                                       p.centroid * p.centroid.transpose());
    volume[k] = p.volume;
  }
  const auto lu = vandermonde.fullPivLu();
  const Eigen::VectorXd volume_coeff = lu.solve(volume);
  EXPECT_LT(relative_error(volume_coeff[3], 4.0 * kPi / 3.0), 1e-9);
  EXPECT_NEAR(volume_coeff[4], 0.0, 1e-9);
  EXPECT_NEAR(volume_coeff[5], 0.0, 1e-9);
  EXPECT_LT(relative_error(volume_coeff[0], base.sharp_mass_properties(1.0).volume), 1e-9);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Eigen::VectorXd entry(n);
      for (int k = 0; k < n; ++k) entry[k] = inertia[k](i, j);
      const Eigen::VectorXd coeff = lu.solve(entry);
      EXPECT_NEAR(coeff[5], i == j ? 8.0 * kPi / 15.0 : 0.0, 1e-8) << i << j;
    }
}

// ---------------------------------------------------------------------------------------
// Input files and bad input

TEST(ConvexShapeInput, VertexFile) {
  const std::string path = ::testing::TempDir() + "wiregrain_cube_" + std::to_string(::getpid()) + ".txt";
  {
    std::ofstream out(path);
    out << "# unit cube\n\n";
    for (int i = 0; i < 8; ++i)
      out << (i & 1 ? 0.5 : -0.5) << " " << (i & 2 ? 0.5 : -0.5) << "\t" << (i & 4 ? 0.5 : -0.5)
          << "   # corner " << i << "\n";
  }
  const ConvexShape cube = ConvexShape::from_vertex_file(path, 0.05);
  EXPECT_EQ(cube.faces().size(), 6u);
  EXPECT_LT(relative_error(cube.sharp_mass_properties(1.0).volume, 1.0), 1e-14);
  EXPECT_DOUBLE_EQ(cube.sweep_radius(), 0.05);
  {
    std::ofstream out(path, std::ios::app);
    out << "1.0 2.0\n";
  }
  expect_invalid_argument([&] { ConvexShape::from_vertex_file(path, 0.0); }, "path", "line 11");
  std::remove(path.c_str());
  expect_invalid_argument([&] { ConvexShape::from_vertex_file(path, 0.0); }, "path", path);
  const std::string flat = path + ".flat";
  {
    std::ofstream out(flat);
    out << "0 0 0\n1 0 0\n0 1 0\n1 1 0\n";
  }
  expect_invalid_argument([&] { ConvexShape::from_vertex_file(flat, 0.0); }, "path", flat);
  std::remove(flat.c_str());
}

TEST(ConvexShapeInput, BadInputThrows) {
  const std::vector<Vector3d> tetra = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0),
                                       Vector3d(0, 0, 1)};
  expect_invalid_argument(
      [&] { ConvexShape::from_points({tetra[0], tetra[1], tetra[2]}, 0.0); }, "points",
      "at least 4 points, got 3");
  expect_invalid_argument(
      [&] {
        std::vector<Vector3d> square;
        for (int i = 0; i < 10; ++i) square.emplace_back(std::cos(i), std::sin(i), 2.0);
        ConvexShape::from_points(square, 0.0);
      },
      "points", "one plane");
  expect_invalid_argument(
      [&] {
        ConvexShape::from_points({Vector3d(0, 0, 0), Vector3d(1, 1, 1), Vector3d(2, 2, 2),
                                  Vector3d(-1, -1, -1)},
                                 0.0);
      },
      "points", "one line");
  expect_invalid_argument(
      [&] {
        auto p = tetra;
        p.push_back(Vector3d(1.0 + 1e-13, 0, 0));
        ConvexShape::from_points(p, 0.0);
      },
      "points", "points 1 and 4 are duplicates");
  expect_invalid_argument([&] { ConvexShape::from_points(tetra, -0.1); }, "sweep_radius",
                          "sweep_radius must be a finite number >= 0");

  std::mt19937_64 rng(1);
  expect_invalid_argument([&] { ConvexShape::random_ellipsoid(rng, 3, 1.0, 0.8, 0.6, 0.1); },
                          "n_vertices", "N_v) must be >= 4, got 3");
  expect_invalid_argument([&] { ConvexShape::random_ellipsoid(rng, 20, 1.0, 1.2, 0.6, 0.1); },
                          "b_over_a", "got 1.2");
  expect_invalid_argument([&] { ConvexShape::random_ellipsoid(rng, 20, 1.0, 0.6, 0.8, 0.1); },
                          "c_over_a", "got 0.8");
  expect_invalid_argument([&] { ConvexShape::random_ellipsoid(rng, 20, 0.0, 0.8, 0.6, 0.1); },
                          "a", "must be > 0");
  expect_invalid_argument([&] { ConvexShape::random_ellipsoid(rng, 20, -1.0, 0.8, 0.6, 0.1); },
                          "a", "got -1");
  expect_invalid_argument([&] { ConvexShape::random_ellipsoid(rng, 20, 1.0, 0.8, 0.6, -0.1); },
                          "sweep_radius", "got -0.1");
  expect_invalid_argument([&] { ConvexShape::cube(0.0); }, "edge", "edge must be a finite number > 0");
  expect_invalid_argument([&] { ConvexShape::box(1.0, -2.0, 1.0); }, "ly", "got -2");
  expect_invalid_argument([&] { ConvexShape::cube(1.0).sharp_mass_properties(0.0); }, "density",
                          "density must be a finite number > 0");
}

// ---------------------------------------------------------------------------------------
// Spheres: one vertex, no edges, no faces, the radius as sweep radius

TEST(ConvexShapeSphere, OneVertexNoEdgesNoFaces) {
  const ConvexShape s = ConvexShape::sphere(0.7);
  ASSERT_EQ(s.vertices().size(), 1u);
  EXPECT_EQ(s.vertices()[0], Vector3d::Zero());
  EXPECT_TRUE(s.edges().empty());
  EXPECT_TRUE(s.faces().empty());
  EXPECT_TRUE(s.is_sphere());
  EXPECT_FALSE(ConvexShape::cube(1.0).is_sphere());
  EXPECT_EQ(s.sweep_radius(), 0.7);
  EXPECT_EQ(s.bounding_radius(), 0.7);
  // from_points with one point: the same sphere about that point
  const Vector3d p(1.0, -2.0, 0.5);
  const ConvexShape q = ConvexShape::from_points({p}, 0.3);
  ASSERT_EQ(q.vertices().size(), 1u);
  EXPECT_EQ(q.vertices()[0], p);
  EXPECT_TRUE(q.is_sphere());
  EXPECT_NEAR(q.bounding_radius(), p.norm() + 0.3, 1e-15);
  // a rigid motion moves the vertex
  const Matrix3d rotation = Eigen::AngleAxisd(0.4, Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  const ConvexShape moved = q.transformed(rotation, Vector3d(0, 0, 1));
  EXPECT_LT((moved.vertices()[0] - (rotation * p + Vector3d(0, 0, 1))).norm(), 1e-15);
  EXPECT_TRUE(moved.faces().empty());
}

// The dilated grain of a sphere is the ball: V = 4π r³/3, centroid at the centre,
// inertia 2/5 m r² about every axis.
TEST(ConvexShapeSphere, DilatedMassIsTheBall) {
  for (double r : {0.05, 0.7, 3.0}) {
    const double rho = 2.5;
    const Vector3d centre(0.3, -1.2, 4.0);
    const MassProperties m = ConvexShape::from_points({centre}, r).dilated_mass_properties(rho);
    const double volume = 4.0 / 3.0 * kPi * r * r * r;
    EXPECT_LT(relative_error(m.volume, volume), 1e-15);
    EXPECT_LT(relative_error(m.mass, rho * volume), 1e-15);
    EXPECT_LT((m.centroid - centre).norm(), 1e-15 * centre.norm());
    expect_isotropic_inertia(m, 0.4 * rho * volume * r * r, 1e-14, "ball r = " + std::to_string(r));
    const MassProperties same = ConvexShape::sphere(r).mass_properties(rho, MassModel::dilated);
    EXPECT_EQ(same.volume, m.volume);
  }
}

// No sharp volume: the sharp model is refused, naming "model"; the body frame of the
// dilated model puts the vertex at the origin without turning it.
TEST(ConvexShapeSphere, SharpModelRefusedBodyFrameOfTheBall) {
  const ConvexShape s = ConvexShape::from_points({Vector3d(1, 2, 3)}, 0.5);
  expect_invalid_argument([&] { s.sharp_mass_properties(1.0); }, "model", "dilated mass model");
  expect_invalid_argument([&] { s.mass_properties(1.0, MassModel::sharp_polyhedron); }, "model",
                          "zero volume");
  expect_invalid_argument([&] { to_body_frame(s, 1.0, MassModel::sharp_polyhedron); }, "model",
                          "sphere");
  const BodyFrameShape body = to_body_frame(s, 2.0, MassModel::dilated);
  ASSERT_EQ(body.shape.vertices().size(), 1u);
  EXPECT_LT(body.shape.vertices()[0].norm(), 1e-15);
  EXPECT_LT((body.centroid - Vector3d(1, 2, 3)).norm(), 1e-15);
  EXPECT_EQ(body.rotation.angularDistance(Eigen::Quaterniond::Identity()), 0.0);
  const double mass = 2.0 * 4.0 / 3.0 * kPi * 0.125;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(body.principal_moments[i], 0.4 * mass * 0.25, 1e-15);
  EXPECT_EQ(body.shape.sweep_radius(), 0.5);
}

TEST(ConvexShapeSphere, BadRadiusNamesTheArgument) {
  for (double r : {0.0, -1.0, std::numeric_limits<double>::infinity(),
                   std::numeric_limits<double>::quiet_NaN()})
    expect_invalid_argument([&] { ConvexShape::sphere(r); }, "radius",
                            "radius must be a finite number > 0, got");
  expect_invalid_argument([&] { ConvexShape::sphere(-2.0); }, "radius", "got -2");
  expect_invalid_argument([&] { ConvexShape::from_points({Vector3d(1, 0, 0)}, 0.0); },
                          "sweep_radius", "one point is a sphere and needs sweep_radius > 0");
  expect_invalid_argument(
      [&] { ConvexShape::from_points({Vector3d(std::numeric_limits<double>::quiet_NaN(), 0, 0)}, 1.0); },
      "points", "point 0 has a non-finite coordinate");
  expect_invalid_argument([&] { ConvexShape::from_points({Vector3d(1, 0, 0), Vector3d(0, 1, 0)}, 1.0); },
                          "points", "at least 4 points, got 2");
  expect_invalid_argument([&] { ConvexShape::from_points({}, 1.0); }, "points",
                          "at least 4 points, got 0");
}

// A vertex file with one point and a positive sweep radius is a sphere.
TEST(ConvexShapeSphere, OnePointVertexFile) {
  const std::string path = ::testing::TempDir() + "wiregrain_sphere_" + std::to_string(::getpid()) + ".txt";
  {
    std::ofstream out(path);
    out << "# a sphere\n0.25 -0.5 1\n";
  }
  const ConvexShape s = ConvexShape::from_vertex_file(path, 0.4);
  ASSERT_TRUE(s.is_sphere());
  EXPECT_EQ(s.vertices()[0], Vector3d(0.25, -0.5, 1.0));
  EXPECT_EQ(s.sweep_radius(), 0.4);
  expect_invalid_argument([&] { ConvexShape::from_vertex_file(path, 0.0); }, "sweep_radius",
                          "needs sweep_radius > 0");
  std::remove(path.c_str());
}

// Drawing: a polyhedron's faces (moved out by r along their normals when swept); a
// sphere's ball as a latitude–longitude tessellation: B bands × 2B sectors (2B triangles
// at each pole, 2B (B − 2) quadrilaterals), every vertex at distance r from the centre,
// every polygon planar and counter-clockwise seen from outside, and the polygons closing
// into a surface of genus 0 (each directed edge once, its reverse once, V − E + F = 2).
TEST(ConvexShapeSphere, SurfacePolygons) {
  const ConvexShape cube = ConvexShape::cube(2.0, 0.25);
  for (bool swept : {false, true}) {
    const auto polygons = surface_polygons(cube, swept);
    ASSERT_EQ(polygons.size(), 6u);
    for (std::size_t f = 0; f < 6; ++f) {
      ASSERT_EQ(polygons[f].size(), 4u);
      const Vector3d& n = cube.faces()[f].normal;
      for (const Vector3d& p : polygons[f]) EXPECT_NEAR(p.dot(n), swept ? 1.25 : 1.0, 1e-15);
    }
  }

  const double r = 0.7;
  const Vector3d c(1.0, -2.0, 0.5);
  const ConvexShape ball = ConvexShape::from_points({c}, r);
  const int B = kSphereDisplayBands;
  for (bool swept : {false, true}) {
    const auto polygons = surface_polygons(ball, swept);
    ASSERT_EQ(static_cast<int>(polygons.size()), 2 * B * B);
    int triangles = 0;
    std::set<std::array<double, 3>> corners;
    std::set<std::pair<std::array<double, 3>, std::array<double, 3>>> directed;
    const auto key = [](const Vector3d& p) { return std::array<double, 3>{p.x(), p.y(), p.z()}; };
    for (const auto& polygon : polygons) {
      const std::size_t m = polygon.size();
      ASSERT_TRUE(m == 3 || m == 4);
      triangles += m == 3;
      Vector3d newell = Vector3d::Zero(), mean = Vector3d::Zero();
      for (std::size_t k = 0; k < m; ++k) {
        newell += (polygon[k] - c).cross(polygon[(k + 1) % m] - c);
        mean += (polygon[k] - c) / static_cast<double>(m);
        EXPECT_NEAR((polygon[k] - c).norm(), r, 1e-15);
        corners.insert(key(polygon[k]));
        EXPECT_TRUE(directed.insert({key(polygon[k]), key(polygon[(k + 1) % m])}).second);
      }
      const Vector3d n = newell.normalized();
      EXPECT_GT(n.dot(mean), 0.0);  // outward
      for (const Vector3d& p : polygon) EXPECT_NEAR(n.dot(p - c), n.dot(mean), 1e-15);  // planar
    }
    EXPECT_EQ(triangles, 4 * B);
    for (const auto& [a, b] : directed) EXPECT_EQ(directed.count({b, a}), 1u);
    const long v = static_cast<long>(corners.size()), e = static_cast<long>(directed.size()) / 2;
    EXPECT_EQ(v, 2 + (B - 1) * 2 * B);
    EXPECT_EQ(v - e + static_cast<long>(polygons.size()), 2);
  }
}
