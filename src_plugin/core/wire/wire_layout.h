// Node positions for laying a wire: straight line, flat or multi-turn loop, helix and
// polyline. Every layout places consecutive nodes at Euclidean distance exactly l_w
// (the segment length) on the curve; the remainder shorter than one segment at the end
// of the curve is dropped. Errors name the argument ("length", "radius", ...).
#pragma once

#include <Eigen/Core>
#include <istream>
#include <string>
#include <vector>

namespace wiregrain {

// The most beads one layout may give (create_grains takes at most as many grains): a layout
// that would give more throws InvalidArgument("segment_length", "segment_length L gives N
// beads, more than the 100000000 one wire may have ...") before any node is allocated.
constexpr long kMaxWireBeads = 100000000L;

// Straight wire from `start` along `direction` (need not be unit), floor(length / l_w)
// segments (a ratio within 1e-9 relative of an integer counts as that integer).
std::vector<Eigen::Vector3d> wire_line(const Eigen::Vector3d& start,
                                       const Eigen::Vector3d& direction, double length,
                                       double segment_length);

// Helix about the vertical axis through (centre_x, centre_y): node at azimuth φ is
//   (cx + R cos φ, cy + R sin φ, z + pitch (φ − φ0) / 2π),  φ from φ0 to φ0 + 2π turns.
// The azimuth step Δφ solves (2 R sin(Δφ/2))² + (pitch Δφ / 2π)² = l_w², so every chord
// is l_w; floor(2π turns / Δφ) segments. pitch = 0 is a flat (multi-turn) circle: then
// Δφ = 2 asin(l_w / 2R). A negative pitch descends. Requires R > 0, turns > 0,
// l_w > 0 and that one chord fits in half a turn: 4 R² + pitch²/4 ≥ l_w².
struct WireHelix {
  double centre_x = 0.0;
  double centre_y = 0.0;
  double z = 0.0;              // height of the first node
  double radius = 1.0;         // R
  double turns = 1.0;          // may be fractional
  double pitch = 0.0;          // rise per turn
  double start_angle = 0.0;    // φ0 (radians)
};
std::vector<Eigen::Vector3d> wire_helix(const WireHelix& helix, double segment_length);

// The paper's wire layer: a loop of radius R with free ends, `turns` times round
// (the "double loop" is turns = 2), consecutive turns offset vertically by `pitch`
// (pitch ≥ 2 r_w keeps them from overlapping; 0 lays them on top of each other).
// The same curve as wire_helix.
std::vector<Eigen::Vector3d> wire_loop(double centre_x, double centre_y, double z,
                                       double radius, double turns, double pitch,
                                       double segment_length);

// Resample a polyline (≥ 2 points, no zero-length piece): the first node is the first
// point, each next node is the first point further along the polyline at Euclidean
// distance l_w from the previous node, until the polyline ends. Across a corner the
// chord cuts the corner, so nodes lie on the polyline but the arc length between them
// can exceed l_w.
std::vector<Eigen::Vector3d> wire_polyline(const std::vector<Eigen::Vector3d>& points,
                                           double segment_length);

// Points "x y z" one per line; '#' starts a comment, blank lines are skipped. Anything
// else on a line is an error naming `source_name` and the line number (argument "file").
std::vector<Eigen::Vector3d> read_polyline(std::istream& in, const std::string& source_name);
std::vector<Eigen::Vector3d> read_polyline_file(const std::string& path);

}  // namespace wiregrain
