#include "core/wire/wire_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/common/errors.h"
#include "core/common/constants.h"
#include "core/common/validation.h"

namespace wiregrain {

namespace {

// A length ratio this close to an integer counts as that integer, so that e.g.
// length 1 with l_w 0.2 (1/0.2 = 4.999... in floating point) gives 5 segments.
constexpr double kCountTolerance = 1e-9;

// A bead count in words: the integer when it has one, else as a number (1e+300, inf).
std::string bead_count_text(double beads) {
  return beads < 9e18 ? std::to_string(static_cast<long long>(beads)) : format_number(beads);
}

[[noreturn]] void throw_too_many_beads(double segment_length, const std::string& how_many) {
  throw InvalidArgument("segment_length", "segment_length " + format_number(segment_length) + " gives " + how_many +
                                              " (take a longer segment_length or a shorter layout)");
}

// The whole segments in a curve `ratio` segment lengths long, checked against kMaxWireBeads
// before the count is converted (a ratio of 1e30 or inf has no long). Beyond the limit the
// count is floor(ratio): the tolerance, relative, would add ratio × 1e-9 segments there.
long whole_segments(double ratio, double segment_length) {
  const double plain = std::floor(ratio);
  const double segments =
      plain + 1.0 > static_cast<double>(kMaxWireBeads) ? plain : std::floor(ratio * (1.0 + kCountTolerance));
  if (!(segments + 1.0 <= static_cast<double>(kMaxWireBeads)))
    throw_too_many_beads(segment_length, bead_count_text(segments + 1.0) + " beads, more than the " +
                                             std::to_string(kMaxWireBeads) + " one wire may have");
  return static_cast<long>(segments);
}

// Azimuth step Δφ ∈ (0, π] of a helix chord of length l:
// f(Δφ) = (2R sin(Δφ/2))² + (p Δφ/2π)² − l² is increasing on [0, π], f(0) = −l² < 0;
// bisection to the last representable bit.
double helix_azimuth_step(double radius, double pitch, double l) {
  const auto chord2_minus_l2 = [&](double dphi) {
    const double horizontal = 2.0 * radius * std::sin(0.5 * dphi);
    const double vertical = pitch * dphi / (2.0 * kPi);
    return horizontal * horizontal + vertical * vertical - l * l;
  };
  if (pitch == 0.0) return 2.0 * std::asin(l / (2.0 * radius));
  double lo = 0.0, hi = kPi;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (chord2_minus_l2(mid) < 0.0 ? lo : hi) = mid;
  }
  // the end whose chord is closer to l
  return std::abs(chord2_minus_l2(lo)) < std::abs(chord2_minus_l2(hi)) ? lo : hi;
}

}  // namespace

std::vector<Eigen::Vector3d> wire_line(const Eigen::Vector3d& start,
                                       const Eigen::Vector3d& direction, double length,
                                       double segment_length) {
  require_positive("segment_length", segment_length);
  require_positive("length", length);
  if (!start.allFinite())
    throw InvalidArgument("start", "start must be a finite point");
  const double dir_norm = direction.norm();
  if (!(dir_norm > 0.0) || !std::isfinite(dir_norm))
    throw InvalidArgument("direction", "direction must be a finite non-zero vector, got (" +
                                           format_number(direction.x()) + ", " +
                                           format_number(direction.y()) + ", " +
                                           format_number(direction.z()) + ")");
  const long segments = whole_segments(length / segment_length, segment_length);
  if (segments < 1)
    throw InvalidArgument("length", "length must be at least one segment_length (" +
                                        format_number(segment_length) + "), got " +
                                        format_number(length));
  const Eigen::Vector3d step = direction / dir_norm;
  std::vector<Eigen::Vector3d> nodes;
  nodes.reserve(static_cast<std::size_t>(segments) + 1);
  for (long k = 0; k <= segments; ++k)
    nodes.push_back(start + (static_cast<double>(k) * segment_length) * step);
  return nodes;
}

std::vector<Eigen::Vector3d> wire_helix(const WireHelix& h, double segment_length) {
  require_positive("segment_length", segment_length);
  require_positive("radius", h.radius);
  require_positive("turns", h.turns);
  require_finite("pitch", h.pitch);
  require_finite("centre_x", h.centre_x);
  require_finite("centre_y", h.centre_y);
  require_finite("z", h.z);
  require_finite("start_angle", h.start_angle);
  const double l = segment_length;
  if (4.0 * h.radius * h.radius + 0.25 * h.pitch * h.pitch < l * l)
    throw InvalidArgument("radius", "radius " + format_number(h.radius) +
                                        " is too small for segment_length " +
                                        format_number(l) +
                                        ": one segment must fit in half a turn "
                                        "(4 radius^2 + pitch^2/4 >= segment_length^2)");
  const double dphi = helix_azimuth_step(h.radius, h.pitch, l);
  const long segments = whole_segments(2.0 * kPi * h.turns / dphi, l);
  if (segments < 1)
    throw InvalidArgument("turns", "turns " + format_number(h.turns) +
                                       " is shorter than one segment");
  std::vector<Eigen::Vector3d> nodes;
  nodes.reserve(static_cast<std::size_t>(segments) + 1);
  for (long k = 0; k <= segments; ++k) {
    const double swept = static_cast<double>(k) * dphi;
    const double phi = h.start_angle + swept;
    nodes.emplace_back(h.centre_x + h.radius * std::cos(phi),
                       h.centre_y + h.radius * std::sin(phi),
                       h.z + h.pitch * swept / (2.0 * kPi));
  }
  return nodes;
}

std::vector<Eigen::Vector3d> wire_loop(double centre_x, double centre_y, double z,
                                       double radius, double turns, double pitch,
                                       double segment_length) {
  WireHelix h;
  h.centre_x = centre_x;
  h.centre_y = centre_y;
  h.z = z;
  h.radius = radius;
  h.turns = turns;
  h.pitch = pitch;
  return wire_helix(h, segment_length);
}

std::vector<Eigen::Vector3d> wire_circle(double centre_x, double centre_y, double z, double radius,
                                         double segment_length) {
  std::vector<Eigen::Vector3d> nodes = wire_loop(centre_x, centre_y, z, radius, 1.0, 0.0, segment_length);
  // 2π / Δφ a whole number puts the last node on the first: the circle stays open
  if (nodes.size() > 2 && (nodes.back() - nodes.front()).norm() < 1e-6 * segment_length) nodes.pop_back();
  return nodes;
}

namespace {

// The nodes of the curve c(t), t from 0 to t_end, at chord l: c(0), then each next node the
// first point further along the curve at distance l from the previous node, each given to
// visit(node) in order until none is left or visit returns false. `speed` bounds |c'(t)|: the
// curve is scanned in parameter steps over which it moves at most l/16 (a chord cannot
// reach l and fall back within one step unless the curve bends on a radius below l/32),
// and the crossing is bisected to the last representable bit of t.
template <class Curve, class Visit>
void walk_curve(const Curve& c, double t_end, double speed, double l, Visit visit) {
  const double l2 = l * l;
  const double h = l / (16.0 * speed);
  Eigen::Vector3d node = c(0.0);
  if (!visit(node)) return;
  double t_node = 0.0;
  while (true) {
    double a = t_node;
    bool found = false;
    while (a < t_end) {
      double b = std::min(t_end, a + h);
      if (!(b > a)) b = std::nextafter(a, t_end);
      if ((c(b) - node).squaredNorm() >= l2) {
        double lo = a, hi = b;
        for (int it = 0; it < 200; ++it) {
          const double mid = 0.5 * (lo + hi);
          if (mid <= lo || mid >= hi) break;
          ((c(mid) - node).squaredNorm() < l2 ? lo : hi) = mid;
        }
        const double e_lo = std::abs((c(lo) - node).norm() - l), e_hi = std::abs((c(hi) - node).norm() - l);
        t_node = (e_lo < e_hi && lo > t_node) ? lo : hi;
        found = true;
        break;
      }
      a = b;
    }
    if (!found) return;
    node = c(t_node);
    if (!visit(node)) return;
  }
}

// The last segment of a join and the checks on it (wire_join's rules).
WireJoin finish_join(std::vector<Eigen::Vector3d> nodes, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                     double l, const JoinSettings& s) {
  const auto last_from = [&]() { return nodes.empty() ? from : nodes.back(); };
  const double r = (to - last_from()).norm();
  WireJoin join;
  if (!nodes.empty() && r < kCountTolerance * l) {  // `to` on the last node: that node is `to`
    nodes.pop_back();
    join.last_rest_length = l;
  } else if (r >= l * (1.0 - kCountTolerance)) {
    join.last_rest_length = l;
  } else if (r < s.min_last * l || r < kCountTolerance * l) {
    if (nodes.empty())
      throw InvalidArgument("join_min", "the layout's first node is " + format_number(r) +
                                            " from the end bead, closer than join_min x segment_length = " +
                                            format_number(s.min_last * l) +
                                            " (lay the layout further away, or lower join_min)");
    nodes.pop_back();
    join.last_rest_length = (to - last_from()).norm();
  } else {
    join.last_rest_length = r;
  }
  join.length = static_cast<double>(nodes.size()) * l + join.last_rest_length;
  if (s.max_length > 0.0 && join.length > s.max_length)
    throw InvalidArgument("join_max", "the join from the end bead to the layout's first node is " +
                                          format_number(join.length) + " long (" +
                                          std::to_string(nodes.size() + 1) + " segments), longer than join_max " +
                                          format_number(s.max_length) +
                                          " (raise join_max, or append to another chain end)");
  join.nodes = std::move(nodes);
  return join;
}

// The helix join's curve (wire_join): ρ, φ, z linear in t ∈ [0, 1].
struct HelixJoinCurve {
  double cx, cy, rho0, drho, phi0, dphi, z0, dz;
  Eigen::Vector3d operator()(double t) const {
    const double rho = rho0 + drho * t, phi = phi0 + dphi * t;
    return Eigen::Vector3d(cx + rho * std::cos(phi), cy + rho * std::sin(phi), z0 + dz * t);
  }
};

}  // namespace

std::vector<Eigen::Vector3d> wire_spiral(double centre_x, double centre_y, double z, double r0, double r1,
                                         double turns, double segment_length) {
  require_positive("segment_length", segment_length);
  require_finite("centre_x", centre_x);
  require_finite("centre_y", centre_y);
  require_finite("z", z);
  require_nonnegative("r0", r0);
  require_nonnegative("r1", r1);
  require_positive("turns", turns);
  if (r0 == r1)
    throw InvalidArgument("r1", "r1 must differ from r0 (" + format_number(r0) +
                                    "): a spiral of constant radius is a loop");
  const double l = segment_length;
  const double phi_end = 2.0 * kPi * turns;
  const double b = (r1 - r0) / phi_end;  // dr/dφ
  // the arc ∫ sqrt(r² + b²) dφ ≤ ∫ (r + |b|) dφ bounds the chords
  const double arc_bound = phi_end * 0.5 * (r0 + r1) + std::abs(r1 - r0);
  if (!(arc_bound / l + 1.0 <= static_cast<double>(kMaxWireBeads)))
    throw_too_many_beads(l, bead_count_text(std::floor(arc_bound / l) + 1.0) + " beads or more, more than the " +
                                std::to_string(kMaxWireBeads) + " one wire may have");
  const auto curve = [&](double phi) {
    const double r = r0 + b * phi;
    return Eigen::Vector3d(centre_x + r * std::cos(phi), centre_y + r * std::sin(phi), z);
  };
  std::vector<Eigen::Vector3d> nodes;
  walk_curve(curve, phi_end * (1.0 + kCountTolerance), std::max(r0, r1) + std::abs(b), l,
             [&](const Eigen::Vector3d& node) {
               nodes.push_back(node);
               return true;
             });
  if (nodes.size() < 2)
    throw InvalidArgument("turns", "turns " + format_number(turns) + " is shorter than one segment");
  return nodes;
}

WireJoin wire_join(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double segment_length,
                   const JoinSettings& s) {
  require_positive("segment_length", segment_length);
  if (!from.allFinite()) throw InvalidArgument("append", "the end bead is not at a finite point");
  if (!to.allFinite()) throw InvalidArgument("append", "the layout's first node is not a finite point");
  if (!(s.min_last >= 0.0 && s.min_last <= 1.0))
    throw InvalidArgument("join_min", "join_min must be in [0, 1], got " + format_number(s.min_last));
  require_nonnegative("join_max", s.max_length);
  const double l = segment_length;
  std::vector<Eigen::Vector3d> nodes;
  if (s.path == JoinPath::straight) {
    const Eigen::Vector3d d = to - from;
    const double distance = d.norm();
    if (!(distance / l + 1.0 <= static_cast<double>(kMaxWireBeads)))
      throw_too_many_beads(l, "a join of more than " + std::to_string(kMaxWireBeads) + " beads");
    if (distance > 0.0) {
      const Eigen::Vector3d u = d / distance;
      for (long k = 1; static_cast<double>(k) * l <= distance; ++k) nodes.push_back(from + (static_cast<double>(k) * l) * u);
    }
  } else {
    require_finite("axis_x", s.axis_x);
    require_finite("axis_y", s.axis_y);
    const double ax = from.x() - s.axis_x, ay = from.y() - s.axis_y;
    const double bx = to.x() - s.axis_x, by = to.y() - s.axis_y;
    HelixJoinCurve c;
    c.cx = s.axis_x;
    c.cy = s.axis_y;
    c.rho0 = std::hypot(ax, ay);
    c.drho = std::hypot(bx, by) - c.rho0;
    c.phi0 = std::atan2(ay, ax);
    double dphi = std::atan2(by, bx) - c.phi0;
    while (dphi < 0.0) dphi += 2.0 * kPi;
    while (dphi >= 2.0 * kPi) dphi -= 2.0 * kPi;
    c.dphi = dphi;
    c.z0 = from.z();
    c.dz = to.z() - from.z();
    const double rho_max = std::max(c.rho0, c.rho0 + c.drho);
    const double speed = std::abs(c.drho) + rho_max * dphi + std::abs(c.dz);
    if (!(speed / l + 1.0 <= static_cast<double>(kMaxWireBeads)))
      throw_too_many_beads(l, "a join of more than " + std::to_string(kMaxWireBeads) + " beads");
    if (speed > 0.0)
      walk_curve(c, 1.0, speed, l, [&](const Eigen::Vector3d& node) {
        nodes.push_back(node);
        return true;
      });
    if (!nodes.empty()) nodes.erase(nodes.begin());  // c(0) is `from`, not a join node
  }
  return finish_join(std::move(nodes), from, to, l, s);
}

namespace {

// The nodes of a polyline resampled at chord l_w (wire_polyline), each given to visit(node)
// in order, the first point first, until the polyline ends or visit returns false.
template <class Visit>
void walk_polyline(const std::vector<Eigen::Vector3d>& points, double segment_length, Visit visit) {
  const double l2 = segment_length * segment_length;
  Eigen::Vector3d node = points[0];
  if (!visit(node)) return;
  std::size_t piece = 0;  // the polyline piece [points[piece], points[piece+1]] holding node
  while (true) {
    bool found = false;
    for (std::size_t s = piece; s + 1 < points.size(); ++s) {
      const Eigen::Vector3d& b = points[s + 1];
      if ((b - node).squaredNorm() < l2) continue;
      // The piece from a to b leaves the sphere |q − node| = l_w: q = a + u (b − a) with
      // |a − node + u d|² = l_w², the larger root (the start is inside, so the roots
      // have opposite signs or the smaller one is below the start).
      const Eigen::Vector3d a = (s == piece) ? node : points[s];
      const Eigen::Vector3d d = b - a, w = a - node;
      const double qa = d.squaredNorm(), qb = w.dot(d), qc = w.squaredNorm() - l2;
      const double root = std::sqrt(std::max(0.0, qb * qb - qa * qc));
      // stable form of (−qb + root)/qa
      double u = qb > 0.0 ? -qc / (qb + root) : (root - qb) / qa;
      u = std::min(1.0, std::max(0.0, u));
      node = a + u * d;
      if (!visit(node)) return;
      piece = s;
      found = true;
      break;
    }
    if (!found) break;
  }
}

}  // namespace

std::vector<Eigen::Vector3d> wire_polyline(const std::vector<Eigen::Vector3d>& points,
                                           double segment_length) {
  require_positive("segment_length", segment_length);
  if (points.size() < 2)
    throw InvalidArgument("points", "a polyline needs at least 2 points, got " +
                                        std::to_string(points.size()));
  double length = 0.0;  // along the pieces: at least the chords between the nodes
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite())
      throw InvalidArgument("points", "polyline point " + std::to_string(i + 1) +
                                          " is not a finite point");
    if (i > 0 && (points[i] - points[i - 1]).squaredNorm() == 0.0)
      throw InvalidArgument("points", "polyline points " + std::to_string(i) + " and " +
                                          std::to_string(i + 1) +
                                          " coincide (zero-length piece)");
    if (i > 0) length += (points[i] - points[i - 1]).norm();
  }
  // Each chord spans at least its own length of the polyline, so length / l_w + 1 bounds the
  // beads; beyond the limit, count them without storing (up to one past the limit).
  if (!(length / segment_length + 1.0 <= static_cast<double>(kMaxWireBeads))) {
    long count = 0;
    walk_polyline(points, segment_length, [&](const Eigen::Vector3d&) { return ++count <= kMaxWireBeads; });
    if (count > kMaxWireBeads)
      throw_too_many_beads(segment_length, "more than " + std::to_string(kMaxWireBeads) +
                                               " beads, the most one wire may have");
  }
  std::vector<Eigen::Vector3d> nodes;
  walk_polyline(points, segment_length, [&](const Eigen::Vector3d& node) {
    nodes.push_back(node);
    return true;
  });
  if (nodes.size() < 2)
    throw InvalidArgument("points", "the polyline never gets segment_length (" +
                                        format_number(segment_length) +
                                        ") away from its first point");
  return nodes;
}

std::vector<Eigen::Vector3d> read_polyline(std::istream& in, const std::string& source_name) {
  std::vector<Eigen::Vector3d> points;
  std::string line;
  long line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string content = line.substr(0, line.find('#'));
    std::istringstream words(content);
    std::vector<std::string> tokens;
    for (std::string t; words >> t;) tokens.push_back(t);
    if (tokens.empty()) continue;
    const auto fail = [&]() {
      throw InvalidArgument("file", "line " + std::to_string(line_number) + " of '" +
                                        source_name +
                                        "': expected three finite numbers x y z, got '" +
                                        line + "'");
    };
    if (tokens.size() != 3) fail();
    Eigen::Vector3d p;
    for (int c = 0; c < 3; ++c) {
      const char* begin = tokens[c].c_str();
      char* end = nullptr;
      p[c] = std::strtod(begin, &end);
      if (end == begin || *end != '\0' || !std::isfinite(p[c])) fail();
    }
    points.push_back(p);
  }
  if (in.bad())
    throw InvalidArgument("file", "reading '" + source_name + "' failed");
  return points;
}

std::vector<Eigen::Vector3d> read_polyline_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InvalidArgument("file", "cannot open polyline file '" + path + "'");
  return read_polyline(in, path);
}

void turn_about_vertical_axis(std::vector<Eigen::Vector3d>& nodes, double centre_x, double centre_y,
                              double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  for (Eigen::Vector3d& x : nodes) {
    const double dx = x.x() - centre_x, dy = x.y() - centre_y;
    x.x() = centre_x + c * dx - s * dy;
    x.y() = centre_y + s * dx + c * dy;
  }
}

}  // namespace wiregrain
