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

// One flat circle of radius R about the vertical axis through (centre_x, centre_y) at
// height z: wire_loop with turns = 1 and pitch = 0 (the first node at (cx + R, cy, z)); the
// circle stays open: when 2π / Δφ is a whole number the node that would fall on the first
// is left out (R = l_w: a hexagon of 6 nodes, not 7).
std::vector<Eigen::Vector3d> wire_circle(double centre_x, double centre_y, double z, double radius,
                                         double segment_length);

// Archimedean spiral in the plane at height z about (centre_x, centre_y):
//   r(φ) = r0 + (r1 − r0) φ / (2π turns),  node at (cx + r cos φ, cy + r sin φ, z),
// φ from 0 to 2π turns (counter-clockwise); r0 < r1 winds out from the centre, r0 > r1 in.
// The first node is at φ = 0; each next node is the first point further along the spiral
// at Euclidean distance l_w from the previous node (the chord, found by bisection to the
// last bit of φ); the part of the spiral shorter than one chord left at its end is dropped,
// an end within 1e-9 (relative, of φ) of a node counting as reached. Requires r0, r1 ≥ 0,
// r0 ≠ r1, turns > 0, l_w > 0; |r1 − r0| / turns ≥ 2 r_w keeps the turns from touching.
std::vector<Eigen::Vector3d> wire_spiral(double centre_x, double centre_y, double z, double r0, double r1,
                                         double turns, double segment_length);

// Turns the nodes of a layout about the vertical axis through (centre_x, centre_y) by
// `angle` (radians, counter-clockwise seen from +z): x' = c + Rz(angle) (x − c), z kept.
// A loop, circle or spiral laid from azimuth 0 then starts at azimuth `angle`; chords and
// distances from the axis are kept to round-off.
void turn_about_vertical_axis(std::vector<Eigen::Vector3d>& nodes, double centre_x, double centre_y,
                              double angle);

// The stretch that joins the free end of a chain (`from`, its end bead) to the first node
// of a layout (`to`):
//   straight: the line from `from` to `to`;
//   helix: about the vertical axis through (axis_x, axis_y), radius ρ, azimuth φ and height
//     z all linear in t ∈ [0, 1], from those of `from` to those of `to`, the azimuth turning
//     counter-clockwise (the way loop, helix, circle and spiral turn) by
//     Δφ = (φ_to − φ_from) mod 2π ∈ [0, 2π) (a point on the axis has azimuth 0).
// Join nodes lie on the path from `from` at chord l_w from one another (the first l_w from
// `from`), while the path's end `to` is more than l_w away from the last node; the
// segment from the last join node (or from `from` when there is none) to `to` is the last
// segment, of length r ≤ l_w: its rest length is r (the join is laid without stress).
// Rules for r: within 1e-9 l_w of l_w it is l_w (a `to` exactly l_w further along makes a
// join of no node whose one segment is a whole segment); below min_last l_w the last join
// node is dropped and the last segment runs from the node before (a chord of up to about
// (1 + min_last) l_w: no segment much stiffer than a whole one); with no join node to drop,
// or r below 1e-9 l_w, `to` is too close to `from`: InvalidArgument("join_min"). The join's
// length (the sum of its segments) may be at most max_length: InvalidArgument("join_max").
enum class JoinPath { straight, helix };
struct WireJoin {
  std::vector<Eigen::Vector3d> nodes;  // strictly between `from` and `to`, in order
  double last_rest_length = 0.0;       // rest length of the segment into `to`
  double length = 0.0;                 // the sum of the join's segments (l_w each, then the last)
};
struct JoinSettings {
  JoinPath path = JoinPath::straight;
  double axis_x = 0.0, axis_y = 0.0;  // helix: the vertical axis
  double min_last = 0.5;              // the shortest last segment, in l_w
  double max_length = 0.0;            // > 0: the longest join
};
WireJoin wire_join(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double segment_length,
                   const JoinSettings& settings);

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
