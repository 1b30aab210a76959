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
