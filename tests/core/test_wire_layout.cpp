// Wire layouts: every chord is l_w, nodes lie on the curve, the node count follows from
// the curve's length, and bad input names its argument.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/common/errors.h"
#include "core/wire/wire_layout.h"

using namespace wiregrain;
using Eigen::Vector3d;

namespace {

constexpr double kPi = 3.14159265358979323846;

void expect_all_chords(const std::vector<Vector3d>& nodes, double l, double tol = 1e-12) {
  for (std::size_t k = 1; k < nodes.size(); ++k)
    ASSERT_NEAR((nodes[k] - nodes[k - 1]).norm(), l, tol) << "segment " << k;
}

template <typename F>
void expect_invalid(F&& call, const std::string& argument) {
  try {
    call();
    ADD_FAILURE() << "no InvalidArgument for " << argument;
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), argument) << e.what();
  }
}

// distance from p to the segment [a, b]
double distance_to_segment(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d d = b - a;
  const double u = std::min(1.0, std::max(0.0, (p - a).dot(d) / d.squaredNorm()));
  return (a + u * d - p).norm();
}

}  // namespace

TEST(WireLayout, StraightLine) {
  const Vector3d start(1.0, -2.0, 0.5), direction(1.0, 2.0, -2.0);  // |direction| = 3
  // length 1 with l_w 0.2 is 5 segments although 1/0.2 rounds below 5
  const auto five = wire_line(start, direction, 1.0, 0.2);
  ASSERT_EQ(five.size(), 6u);
  expect_all_chords(five, 0.2);
  EXPECT_LT((five.back() - (start + direction / 3.0)).norm(), 1e-14);
  // 1.05 / 0.2 = 5.25: the last partial segment is dropped
  const auto dropped = wire_line(start, direction, 1.05, 0.2);
  EXPECT_EQ(dropped.size(), 6u);
  // 300 segments, all on the line
  const auto long_line = wire_line(start, direction, 60.0, 0.2);
  ASSERT_EQ(long_line.size(), 301u);
  expect_all_chords(long_line, 0.2);
  for (const auto& p : long_line)
    EXPECT_LT((p - start).cross(direction / 3.0).norm(), 1e-12);
}

TEST(WireLayout, StraightLineErrors) {
  const Vector3d o(0, 0, 0), x(1, 0, 0);
  expect_invalid([&] { wire_line(o, x, 0.0, 0.2); }, "length");
  expect_invalid([&] { wire_line(o, x, -1.0, 0.2); }, "length");
  expect_invalid([&] { wire_line(o, x, 0.1, 0.2); }, "length");  // shorter than a segment
  expect_invalid([&] { wire_line(o, x, 1.0, 0.0); }, "segment_length");
  expect_invalid([&] { wire_line(o, Vector3d::Zero(), 1.0, 0.2); }, "direction");
}

// Flat double loop (the paper's wire layer), R = 5: azimuth step 2 asin(l/2R), every node
// at distance R from the axis and at the loop's height.
TEST(WireLayout, FlatDoubleLoop) {
  const double R = 5.0, l = 0.2, cx = 1.5, cy = -0.5, z = 3.0;
  const auto nodes = wire_loop(cx, cy, z, R, 2.0, 0.0, l);
  const double dphi = 2.0 * std::asin(l / (2.0 * R));
  const std::size_t expected = static_cast<std::size_t>(std::floor(4.0 * kPi / dphi)) + 1;
  EXPECT_EQ(nodes.size(), expected);
  EXPECT_EQ(nodes.size(), 315u);  // 4π / 0.0400027 = 314.14
  expect_all_chords(nodes, l);
  for (const auto& p : nodes) {
    EXPECT_NEAR(std::hypot(p.x() - cx, p.y() - cy), R, 1e-12);
    EXPECT_EQ(p.z(), z);
  }
}

// A double loop turned by θ about its axis is the helix that starts at azimuth θ
// (wire_helix's φ0, computed from its own formula), node by node.
TEST(WireLayout, TurnedLoopStartsAtTheAngle) {
  const double R = 3.0, l = 0.2, cx = 1.5, cy = -0.5, z = 2.0, theta = 2.0;
  auto nodes = wire_loop(cx, cy, z, R, 2.0, 0.25, l);
  turn_about_vertical_axis(nodes, cx, cy, theta);
  WireHelix helix;
  helix.centre_x = cx;
  helix.centre_y = cy;
  helix.z = z;
  helix.radius = R;
  helix.turns = 2.0;
  helix.pitch = 0.25;
  helix.start_angle = theta;
  const auto expected = wire_helix(helix, l);
  ASSERT_EQ(nodes.size(), expected.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) EXPECT_LT((nodes[i] - expected[i]).norm(), 1e-13) << i;
  EXPECT_NEAR(nodes.front().x(), cx + R * std::cos(theta), 1e-15);
  EXPECT_NEAR(nodes.front().y(), cy + R * std::sin(theta), 1e-15);
  expect_all_chords(nodes, l);
}

// Two turns offset by a pitch 2 r_w = 0.2: the chord includes the rise, every node at
// distance R from the axis and at height z + pitch · (azimuth swept) / 2π.
TEST(WireLayout, LoopWithPitchAndHelix) {
  const double R = 7.0, l = 0.2, pitch = 0.2;
  const auto loop = wire_loop(0.0, 0.0, 1.0, R, 2.0, pitch, l);
  expect_all_chords(loop, l);
  for (const auto& p : loop) EXPECT_NEAR(std::hypot(p.x(), p.y()), R, 1e-12);
  // azimuth step from the rise: z advances by pitch Δφ/2π per node, so the horizontal
  // chord is sqrt(l² − rise²) = 2R sin(Δφ/2)
  const double rise = loop[1].z() - loop[0].z();
  const double dphi = 2.0 * kPi * rise / pitch;
  EXPECT_NEAR(2.0 * R * std::sin(dphi / 2.0), std::sqrt(l * l - rise * rise), 1e-12);
  EXPECT_EQ(loop.size(), static_cast<std::size_t>(std::floor(4.0 * kPi / dphi)) + 1);
  // the first turn ends one pitch below where the second begins: after one turn the
  // node nearest azimuth 2π is pitch above the first node (to within one step's rise)
  EXPECT_NEAR(loop.back().z() - loop.front().z(), 2.0 * pitch, rise);
  // steep helix, descending, 3.5 turns, started at azimuth 1 rad
  WireHelix h;
  h.centre_x = -2.0;
  h.centre_y = 4.0;
  h.z = 10.0;
  h.radius = 0.5;
  h.pitch = -1.5;
  h.turns = 3.5;
  h.start_angle = 1.0;
  const auto helix = wire_helix(h, l);
  expect_all_chords(helix, l);
  double swept = 0.0;
  for (std::size_t k = 0; k < helix.size(); ++k) {
    const Vector3d& p = helix[k];
    EXPECT_NEAR(std::hypot(p.x() + 2.0, p.y() - 4.0), 0.5, 1e-12);
    if (k > 0) {  // unwrap the azimuth and check the height against it
      const double a0 = std::atan2(helix[k - 1].y() - 4.0, helix[k - 1].x() + 2.0);
      const double a1 = std::atan2(p.y() - 4.0, p.x() + 2.0);
      swept += std::remainder(a1 - a0, 2.0 * kPi);
    }
    EXPECT_NEAR(p.z(), 10.0 - 1.5 * swept / (2.0 * kPi), 1e-11);
  }
  EXPECT_GT(swept, 2.0 * kPi * 3.5 - 2.0 * std::asin(l / 1.0));
  EXPECT_LE(swept, 2.0 * kPi * 3.5 + 1e-12);
}

TEST(WireLayout, LoopErrors) {
  expect_invalid([] { wire_loop(0, 0, 0, 0.0, 2.0, 0.0, 0.2); }, "radius");
  expect_invalid([] { wire_loop(0, 0, 0, -1.0, 2.0, 0.0, 0.2); }, "radius");
  expect_invalid([] { wire_loop(0, 0, 0, 0.05, 2.0, 0.0, 0.2); }, "radius");  // 2R < l_w
  expect_invalid([] { wire_loop(0, 0, 0, 5.0, 0.0, 0.0, 0.2); }, "turns");
  expect_invalid([] { wire_loop(0, 0, 0, 5.0, 2.0, 0.0, 0.0); }, "segment_length");
  expect_invalid([] { wire_loop(0, 0, 0, 5.0, 1e-6, 0.0, 0.2); }, "turns");
}

// An L-shaped polyline: nodes every 0.2 along the first leg (length 1.1) up to x = 1.0;
// the next node is 0.2 from (1, 0) on the second leg x = 1.1: y = sqrt(0.2² − 0.1²).
TEST(WireLayout, PolylineAcrossACorner) {
  const std::vector<Vector3d> points{{0, 0, 0}, {1.1, 0, 0}, {1.1, 1.0, 0}};
  const auto nodes = wire_polyline(points, 0.2);
  expect_all_chords(nodes, 0.2);
  ASSERT_GE(nodes.size(), 7u);
  EXPECT_LT((nodes[5] - Vector3d(1.0, 0, 0)).norm(), 1e-14);
  EXPECT_LT((nodes[6] - Vector3d(1.1, std::sqrt(0.03), 0)).norm(), 1e-14);
  // then straight up in steps of 0.2 while y ≤ 1: y = sqrt(0.03) + 0.2 k, k ≤ 4
  EXPECT_EQ(nodes.size(), 11u);
  EXPECT_NEAR(nodes.back().y(), std::sqrt(0.03) + 0.8, 1e-14);
  for (const auto& p : nodes)
    EXPECT_LT(std::min(distance_to_segment(p, points[0], points[1]),
                       distance_to_segment(p, points[1], points[2])),
              1e-14);
}

// A fine polyline on a circle (many short pieces, shorter than l_w): the resampled nodes
// keep the chord l_w and lie on the polyline.
TEST(WireLayout, PolylineOfManyShortPieces) {
  std::vector<Vector3d> points;
  const double R = 3.0;
  for (int k = 0; k <= 1000; ++k) {
    const double phi = 2.0 * kPi * k / 1000.0;
    points.emplace_back(R * std::cos(phi), R * std::sin(phi), 0.01 * k);
  }
  const auto nodes = wire_polyline(points, 0.2);
  expect_all_chords(nodes, 0.2);
  EXPECT_GT(nodes.size(), 90u);  // the curve is ≈ 2π·3 + ... ≈ 21.3 long
  for (const auto& p : nodes) {
    double d = 1e300;
    for (std::size_t s = 0; s + 1 < points.size(); ++s)
      d = std::min(d, distance_to_segment(p, points[s], points[s + 1]));
    EXPECT_LT(d, 1e-12);
  }
}

TEST(WireLayout, PolylineErrors) {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(1, 1, 0);
  expect_invalid([&] { wire_polyline({a, b, b, c}, 0.2); }, "points");  // repeated point
  expect_invalid([&] { wire_polyline({a, a}, 0.2); }, "points");        // zero length
  expect_invalid([&] { wire_polyline({a}, 0.2); }, "points");
  expect_invalid([&] { wire_polyline({a, Vector3d(0.1, 0, 0)}, 0.2); }, "points");  // too short
  expect_invalid([&] { wire_polyline({a, b}, -0.2); }, "segment_length");
  try {
    wire_polyline({a, b, b, c}, 0.2);
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "polyline points 2 and 3 coincide (zero-length piece)");
  }
}

// More beads than kMaxWireBeads (1e8) are refused by their count, before any node is
// stored (a std::bad_alloc otherwise). The counts here from the curves' lengths: a line of 1
// in chords of 1e-8 has 1e8 segments, 1e8 + 1 beads; a flat loop of R = 1e7 in chords of 0.2
// has floor(2π / (2 asin(0.01 / 1e6))) = floor(π · 1e8) = 314159265 segments.
TEST(WireLayout, TooManyBeads) {
  const auto message = [](auto&& call) {
    try {
      call();
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.argument(), "segment_length");
      return std::string(e.what());
    }
    return std::string("no InvalidArgument");
  };
  const Vector3d o(0, 0, 0), x(1, 0, 0);
  EXPECT_EQ(message([&] { wire_line(o, x, 1.0, 1e-8); }),
            "segment_length 1e-08 gives 100000001 beads, more than the 100000000 one wire may have "
            "(take a longer segment_length or a shorter layout)");
  const double segments = std::floor(2.0 * kPi / (2.0 * std::asin(0.2 / 2e7)));
  EXPECT_EQ(segments, 314159265.0);
  EXPECT_EQ(message([] { wire_loop(0, 0, 0, 1e7, 1.0, 0.0, 0.2); }),
            "segment_length 0.2 gives 314159266 beads, more than the 100000000 one wire may have "
            "(take a longer segment_length or a shorter layout)");
  // a ratio beyond any integer type: 1e300 / 1e-300 = inf
  EXPECT_EQ(message([&] { wire_line(o, x, 1e300, 1e-300); }),
            "segment_length 1e-300 gives inf beads, more than the 100000000 one wire may have "
            "(take a longer segment_length or a shorter layout)");
  // a polyline is counted by walking it (its length only bounds the count): 1 / 0.99e-8
  // = 101010101 chords
  EXPECT_EQ(message([&] { wire_polyline({o, x}, 0.99e-8); }),
            "segment_length 9.9e-09 gives more than 100000000 beads, the most one wire may have "
            "(take a longer segment_length or a shorter layout)");
}

TEST(WireLayout, ReadPolyline) {
  std::istringstream in(
      "# a wire\n"
      "0 0 0\n"
      "\n"
      "  1.5 0 0   # corner\n"
      "1.5 2e-1 -3\n");
  const auto points = read_polyline(in, "inline");
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[1], Vector3d(1.5, 0, 0));
  EXPECT_EQ(points[2], Vector3d(1.5, 0.2, -3));

  std::istringstream two_numbers("0 0 0\n1 2\n");
  try {
    read_polyline(two_numbers, "w.txt");
    ADD_FAILURE() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "file");
    EXPECT_STREQ(e.what(), "line 2 of 'w.txt': expected three finite numbers x y z, got '1 2'");
  }
  std::istringstream junk("0 0 0x\n");
  expect_invalid([&] { read_polyline(junk, "j"); }, "file");

  const std::string path = ::testing::TempDir() + "wire_polyline_test.txt";
  {
    std::ofstream out(path);
    out << "0 0 0\n1 0 0 # end\n";
  }
  const auto from_file = read_polyline_file(path);
  ASSERT_EQ(from_file.size(), 2u);
  EXPECT_EQ(from_file[1], Vector3d(1, 0, 0));
  std::remove(path.c_str());
  expect_invalid([&] { read_polyline_file(path); }, "file");
}

// One flat circle: R = l_w is a hexagon (Δφ = 2 asin(1/2) = π/3), open: 6 nodes at 60°
// steps, the seventh (on the first) left out; R = 1, l_w = 0.3: floor(2π / 2 asin(0.15))
// = 20 segments (2π / 0.301128 = 20.87), 21 nodes.
TEST(WireLayout, Circle) {
  const auto hexagon = wire_circle(1.0, -1.0, 2.0, 0.5, 0.5);
  ASSERT_EQ(hexagon.size(), 6u);
  for (int k = 0; k < 6; ++k) {
    const Vector3d expected(1.0 + 0.5 * std::cos(k * kPi / 3.0), -1.0 + 0.5 * std::sin(k * kPi / 3.0), 2.0);
    EXPECT_LT((hexagon[k] - expected).norm(), 1e-15) << "node " << k;
  }
  expect_all_chords(hexagon, 0.5);
  const auto circle = wire_circle(0.0, 0.0, 0.0, 1.0, 0.3);
  ASSERT_EQ(circle.size(), 21u);
  expect_all_chords(circle, 0.3);
  for (const Vector3d& p : circle) EXPECT_NEAR(p.head<2>().norm(), 1.0, 1e-15);
  expect_invalid([] { wire_circle(0, 0, 0, 0.1, 0.3); }, "radius");
}

// Archimedean spiral r = b φ from the centre (r0 = 0) with b = l_w / (π/2): the second node
// is the point of the spiral at distance l_w from the centre, r = b φ = l_w at φ = π/2,
// i.e. (cx, cy + l_w, z). Every chord is l_w, every node lies on the spiral (its radius is
// b times its azimuth unwrapped), the azimuths increase, and the node count is that of an
// independent walk along the spiral sampled at 1e-5 rad (linear interpolation of the
// chord's crossing), with the nodes within 1e-9 of its nodes.
TEST(WireLayout, SpiralFromTheCentre) {
  const double l = 0.2, b = l / (kPi / 2.0), turns = 3.0, r1 = b * 2.0 * kPi * turns;  // r1 = 2.4
  const auto nodes = wire_spiral(0.5, 0.25, 1.0, 0.0, r1, turns, l);
  ASSERT_GE(nodes.size(), 3u);
  EXPECT_LT((nodes[0] - Vector3d(0.5, 0.25, 1.0)).norm(), 1e-15);
  EXPECT_LT((nodes[1] - Vector3d(0.5, 0.25 + l, 1.0)).norm(), 1e-14);
  expect_all_chords(nodes, l, 1e-13);
  double unwrapped = 0.0, previous = 0.0;
  for (std::size_t k = 1; k < nodes.size(); ++k) {
    const Vector3d p = nodes[k] - Vector3d(0.5, 0.25, 1.0);
    EXPECT_EQ(p.z(), 0.0);
    double phi = std::atan2(p.y(), p.x());
    while (phi < previous - 1e-12) phi += 2.0 * kPi;  // unwrap (the azimuth only grows)
    unwrapped = phi;
    previous = phi;
    EXPECT_NEAR(p.head<2>().norm(), b * unwrapped, 1e-12) << "node " << k;
  }
  EXPECT_LE(unwrapped, 2.0 * kPi * turns);
  // the independent walk
  std::vector<Vector3d> walk{Vector3d(0.5, 0.25, 1.0)};
  const auto at = [&](double phi) { return Vector3d(0.5 + b * phi * std::cos(phi), 0.25 + b * phi * std::sin(phi), 1.0); };
  double prev_d = 0.0;
  for (double phi = 1e-5; phi <= 2.0 * kPi * turns; phi += 1e-5) {
    const double d = (at(phi) - walk.back()).norm();
    if (d >= l) {
      const double u = (l - prev_d) / (d - prev_d);
      walk.push_back(at(phi - 1e-5 + u * 1e-5));
      prev_d = (at(phi) - walk.back()).norm();
    } else {
      prev_d = d;
    }
  }
  ASSERT_EQ(nodes.size(), walk.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) EXPECT_LT((nodes[k] - walk[k]).norm(), 1e-9) << "node " << k;
}

// Winding in (r0 > r1) gives the same curve walked the other way from the outside: its
// first node at (cx + r0, cy, z); chords l_w, radius r0 + (r1 - r0) φ / (2π turns).
TEST(WireLayout, SpiralInwardAndErrors) {
  const auto nodes = wire_spiral(0.0, 0.0, 0.0, 3.0, 1.0, 2.0, 0.25);
  EXPECT_LT((nodes[0] - Vector3d(3.0, 0.0, 0.0)).norm(), 1e-15);
  expect_all_chords(nodes, 0.25, 1e-13);
  for (const Vector3d& p : nodes) {
    EXPECT_LE(p.head<2>().norm(), 3.0 + 1e-12);
    EXPECT_GE(p.head<2>().norm(), 1.0 - 1e-12);
  }
  expect_invalid([] { wire_spiral(0, 0, 0, 1.0, 1.0, 2.0, 0.2); }, "r1");
  expect_invalid([] { wire_spiral(0, 0, 0, -1.0, 1.0, 2.0, 0.2); }, "r0");
  expect_invalid([] { wire_spiral(0, 0, 0, 0.0, 1.0, 0.0, 0.2); }, "turns");
  expect_invalid([] { wire_spiral(0, 0, 0, 0.0, 1.0, 1.0, 0.0); }, "segment_length");
  expect_invalid([] { wire_spiral(0, 0, 0, 0.0, 1e-3, 1e-3, 0.2); }, "turns");
  expect_invalid([] { wire_spiral(0, 0, 0, 0.0, 1e7, 1e3, 0.2); }, "segment_length");
}

namespace {
JoinSettings straight_join(double min_last = 0.5, double max_length = 0.0) {
  JoinSettings s;
  s.min_last = min_last;
  s.max_length = max_length;
  return s;
}
}  // namespace

// Straight joins from (0,0,0) up the z axis with l_w = 0.2: to 0.55 two nodes at 0.2 and
// 0.4 and a last segment 0.15 (≥ join_min 0.5 l_w = 0.1); to 0.45 the remainder 0.05 is
// below 0.1: the node at 0.4 is dropped and the last segment is 0.25; with join_min 0 it is
// kept and the last segment is 0.05; to 0.2, or to (0.12, 0.16, 0) (a 3-4-5 triangle), no
// node and one whole segment of rest length exactly l_w; to 0.6 = 3 l_w: nodes at 0.2 and
// 0.4 and a whole last segment.
TEST(WireLayout, StraightJoin) {
  const Vector3d o(0.0, 0.0, 0.0);
  const auto j1 = wire_join(o, Vector3d(0, 0, 0.55), 0.2, straight_join());
  ASSERT_EQ(j1.nodes.size(), 2u);
  EXPECT_EQ(j1.nodes[0], Vector3d(0, 0, 0.2));
  EXPECT_EQ(j1.nodes[1], Vector3d(0, 0, 0.4));
  EXPECT_NEAR(j1.last_rest_length, 0.15, 1e-15);
  EXPECT_NEAR(j1.length, 0.55, 1e-15);
  const auto j2 = wire_join(o, Vector3d(0, 0, 0.45), 0.2, straight_join());
  ASSERT_EQ(j2.nodes.size(), 1u);
  EXPECT_EQ(j2.nodes[0], Vector3d(0, 0, 0.2));
  EXPECT_NEAR(j2.last_rest_length, 0.25, 1e-15);
  const auto j3 = wire_join(o, Vector3d(0, 0, 0.45), 0.2, straight_join(0.0));
  ASSERT_EQ(j3.nodes.size(), 2u);
  EXPECT_NEAR(j3.last_rest_length, 0.05, 1e-15);
  for (const Vector3d& to : {Vector3d(0, 0, 0.2), Vector3d(0.12, 0.16, 0.0)}) {
    const auto j = wire_join(o, to, 0.2, straight_join());
    EXPECT_TRUE(j.nodes.empty());
    EXPECT_EQ(j.last_rest_length, 0.2);
  }
  const auto j4 = wire_join(o, Vector3d(0, 0, 0.6), 0.2, straight_join());
  ASSERT_EQ(j4.nodes.size(), 2u);
  EXPECT_EQ(j4.last_rest_length, 0.2);
  // from a point off the origin along (2, -1, 2)/3: nodes at k l_w along it
  const Vector3d a(1.0, 2.0, 3.0), u = Vector3d(2.0, -1.0, 2.0) / 3.0;
  // length 1 with l_w 0.3: nodes at 0.3, 0.6, 0.9; the remainder 0.1 < 0.15 drops 0.9, last 0.4
  const auto j5 = wire_join(a, a + 1.0 * u, 0.3, straight_join());
  ASSERT_EQ(j5.nodes.size(), 2u);
  for (int k = 0; k < 2; ++k) EXPECT_LT((j5.nodes[k] - (a + 0.3 * (k + 1) * u)).norm(), 1e-15);
  EXPECT_NEAR(j5.last_rest_length, 0.4, 1e-15);
  EXPECT_NEAR(j5.length, 1.0, 1e-15);
}

TEST(WireLayout, JoinErrors) {
  const Vector3d o(0.0, 0.0, 0.0);
  expect_invalid([&] { wire_join(o, Vector3d(0, 0, 0.05), 0.2, straight_join()); }, "join_min");
  expect_invalid([&] { wire_join(o, o, 0.2, straight_join(0.0)); }, "join_min");
  expect_invalid([&] { wire_join(o, Vector3d(0, 0, 0.55), 0.2, straight_join(0.5, 0.5)); }, "join_max");
  EXPECT_NO_THROW(wire_join(o, Vector3d(0, 0, 0.55), 0.2, straight_join(0.5, 0.55)));
  expect_invalid([&] { wire_join(o, Vector3d(0, 0, 1), 0.2, straight_join(1.5)); }, "join_min");
  try {
    wire_join(o, Vector3d(0, 0, 0.05), 0.2, straight_join());
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(std::string(e.what()),
              "the layout's first node is 0.05 from the end bead, closer than join_min x segment_length = 0.1 "
              "(lay the layout further away, or lower join_min)");
  }
  try {
    wire_join(o, Vector3d(0, 0, 0.55), 0.2, straight_join(0.5, 0.5));
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(std::string(e.what()),
              "the join from the end bead to the layout's first node is 0.55 long (3 segments), longer than "
              "join_max 0.5 (raise join_max, or append to another chain end)");
  }
}

// Helix joins about the z axis. A quarter turn at radius 1 from (1,0,0) to (0,1,h) with
// l_w² = (2 sin(π/12))² + (h/3)² (the chord of a twelfth of a turn rising h/3): nodes at
// azimuths π/6 and π/3, heights h/3 and 2h/3, the last segment a whole one. Flat (h = 0)
// likewise. From radius 1 to radius 2 at one azimuth the path is radial: l_w = 0.3 gives
// nodes at 1.3, 1.6 (1.9 dropped: 0.1 < 0.15), last 0.4. The azimuth turns counter-
// clockwise: from −0.1 rad to 0 a short arc, from 0 to −0.1 rad all the way round.
TEST(WireLayout, HelixJoin) {
  JoinSettings s;
  s.path = JoinPath::helix;
  for (double h : {0.0, 0.7}) {
    const double l = std::hypot(2.0 * std::sin(kPi / 12.0), h / 3.0);
    const auto j = wire_join(Vector3d(1, 0, 0), Vector3d(0, 1, h), l, s);
    ASSERT_EQ(j.nodes.size(), 2u) << "h " << h;
    EXPECT_LT((j.nodes[0] - Vector3d(std::cos(kPi / 6), std::sin(kPi / 6), h / 3)).norm(), 1e-13);
    EXPECT_LT((j.nodes[1] - Vector3d(std::cos(kPi / 3), std::sin(kPi / 3), 2 * h / 3)).norm(), 1e-13);
    EXPECT_EQ(j.last_rest_length, l);
  }
  const auto radial = wire_join(Vector3d(1, 0, 0), Vector3d(2, 0, 0), 0.3, s);
  ASSERT_EQ(radial.nodes.size(), 2u);
  EXPECT_LT((radial.nodes[0] - Vector3d(1.3, 0, 0)).norm(), 1e-14);
  EXPECT_LT((radial.nodes[1] - Vector3d(1.6, 0, 0)).norm(), 1e-14);
  EXPECT_NEAR(radial.last_rest_length, 0.4, 1e-14);
  // about another axis: the same quarter turn shifted by (3, -2)
  s.axis_x = 3.0;
  s.axis_y = -2.0;
  const double l = 2.0 * std::sin(kPi / 12.0);
  const auto shifted = wire_join(Vector3d(4, -2, 0), Vector3d(3, -1, 0), l, s);
  ASSERT_EQ(shifted.nodes.size(), 2u);
  EXPECT_LT((shifted.nodes[0] - Vector3d(3 + std::cos(kPi / 6), -2 + std::sin(kPi / 6), 0)).norm(), 1e-13);
  s.axis_x = s.axis_y = 0.0;
  // counter-clockwise: from −0.1 rad to 0 one segment, the chord 2 sin(0.05) = 0.09996 ≥ 0.5 l_w
  const Vector3d before(std::cos(-0.1), std::sin(-0.1), 0.0), zero(1, 0, 0);
  const auto short_arc = wire_join(before, zero, 0.15, s);
  EXPECT_TRUE(short_arc.nodes.empty());
  EXPECT_NEAR(short_arc.last_rest_length, 2.0 * std::sin(0.05), 1e-15);
  const auto round = wire_join(zero, before, 0.2, s);
  // chord 0.2 on the unit circle: Δφ = 2 asin(0.1) = 0.200335; the path turns 2π − 0.1 =
  // 30.86 Δφ: 30 nodes at k Δφ, the remainder 0.173 rad (chord 0.1729 ≥ 0.1) the last segment
  const double dphi = 2.0 * std::asin(0.1), rest_angle = 2.0 * kPi - 0.1 - 30.0 * dphi;
  ASSERT_EQ(round.nodes.size(), 30u);
  for (std::size_t k = 0; k < round.nodes.size(); ++k) {
    const double phi = (k + 1) * dphi;
    EXPECT_LT((round.nodes[k] - Vector3d(std::cos(phi), std::sin(phi), 0.0)).norm(), 1e-12) << "node " << k;
  }
  EXPECT_NEAR(round.last_rest_length, 2.0 * std::sin(0.5 * rest_angle), 1e-12);
}
