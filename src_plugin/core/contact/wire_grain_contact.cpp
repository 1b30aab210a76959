#include "core/contact/wire_grain_contact.h"

#include <algorithm>
#include <cmath>

#include "core/common/errors.h"
#include "core/common/validation.h"

namespace wiregrain {

double load_point_parameter(const PosedShape& grain, const SegmentContact& g, const WireSegmentState& segment,
                            double angle_tolerance) {
  if (!(g.t_end > g.t_begin)) return g.t;
  const Eigen::Vector3d axis = segment.x1 - segment.x0;
  const auto overlap_at = [&](double t) {
    const Eigen::Vector3d p = segment.x0 + t * axis;
    return -segment_contact(grain, p, p, segment.radius).gap;
  };
  const double begin = overlap_at(g.t_begin), end = overlap_at(g.t_end);
  const double deeper_end = begin >= end ? g.t_begin : g.t_end;
  const double positive = std::max(0.0, begin) + std::max(0.0, end);
  if (!(positive > 0.0)) return deeper_end;
  const double lever = (g.t_begin * std::max(0.0, begin) + g.t_end * std::max(0.0, end)) / positive;
  const double tilt = std::asin(std::min(1.0, std::abs(begin - end) / ((g.t_end - g.t_begin) * axis.norm())));
  const double weight = std::min(1.0, std::max(0.0, 2.0 * (1.0 - tilt / angle_tolerance)));
  return weight * lever + (1.0 - weight) * deeper_end;
}

WireGrainContact wire_grain_contact(const SoftContactLaw& law, const PosedShape& grain,
                                    const GrainMotion& motion, const WireSegmentState& segment,
                                    double dt, TangentialHistory& history, double exact_gap_below,
                                    GjkSimplex* simplex) {
  WireGrainContact out;
  ContactOptions only_touching;  // pairs apart need their gap only, farther ones a bound
  only_touching.feature_gap_limit = 0.0;
  only_touching.exit_gap = exact_gap_below;
  out.geometry = segment_contact(grain, segment.x0, segment.x1, segment.radius, only_touching, simplex);
  const SegmentContact& g = out.geometry;
  out.overlap = -g.gap;
  out.normal = g.normal;
  if (!(out.overlap > 0.0)) return out;
  const double t = load_point_parameter(grain, g, segment, ContactOptions().angle_tolerance);
  load_touching_pair(law, grain.position(), motion, segment, t, dt, history, out);
  return out;
}

void load_touching_pair(const SoftContactLaw& law, const Eigen::Vector3d& centre, const GrainMotion& motion,
                        const WireSegmentState& segment, double t, double dt, TangentialHistory& history,
                        WireGrainContact& out) {
  out.touching = true;
  out.load_parameter = t;
  const Eigen::Vector3d axis_point = segment.x0 + t * (segment.x1 - segment.x0);
  out.point = axis_point - (segment.radius - 0.5 * out.overlap) * out.normal;
  const Eigen::Vector3d arm = out.point - centre;
  const Eigen::Vector3d wire_velocity = (1.0 - t) * segment.v0 + t * segment.v1;
  const Eigen::Vector3d grain_velocity = motion.velocity + motion.angular_velocity.cross(arm);
  const double wire_mass = segment.m0 + segment.m1;
  const double effective_mass = wire_mass * motion.mass / (wire_mass + motion.mass);
  out.spring_dashpot = contact_spring_dashpot(law, effective_mass);
  const SoftContactForce f = soft_contact_force(law, out.overlap, out.normal, wire_velocity - grain_velocity, dt,
                                                effective_mass, history);
  out.normal_force = f.normal_force;
  out.sliding = history.sliding;
  out.force_bead0 = (1.0 - t) * f.force;
  out.force_bead1 = t * f.force;
  out.force_grain = -(out.force_bead0 + out.force_bead1);
  out.torque_grain = arm.cross(out.force_grain);
}

WireGrainContact wire_sphere_contact(const SoftContactLaw& law, const Eigen::Vector3d& centre, double sphere_radius,
                                     const GrainMotion& motion, const WireSegmentState& segment, double dt,
                                     TangentialHistory& history) {
  WireGrainContact out;
  SegmentContact& g = out.geometry;
  const Eigen::Vector3d axis = segment.x1 - segment.x0;
  const double length2 = axis.squaredNorm();
  g.t = length2 > 0.0 ? std::min(1.0, std::max(0.0, (centre - segment.x0).dot(axis) / length2)) : 0.0;
  g.t_begin = g.t_end = g.t;
  g.point_on_segment = segment.x0 + g.t * axis;
  g.point_on_core = centre;
  const Eigen::Vector3d out_of_centre = g.point_on_segment - centre;
  g.distance = out_of_centre.norm();
  g.gap = g.distance - (sphere_radius + segment.radius);
  if (g.distance > 0.0)
    g.normal = out_of_centre / g.distance;
  else  // the axis through the centre: any way out across the segment
    g.normal = length2 > 0.0 ? Eigen::Vector3d(axis.unitOrthogonal()) : Eigen::Vector3d::UnitZ();
  out.overlap = -g.gap;
  out.normal = g.normal;
  if (!(out.overlap > 0.0)) return out;
  load_touching_pair(law, centre, motion, segment, g.t, dt, history, out);
  return out;
}

WireGrainContact wire_superquadric_contact(const SoftContactLaw& law, const PosedSuperquadric& grain,
                                           const GrainMotion& motion, const WireSegmentState& segment, double dt,
                                           TangentialHistory& history, double exact_gap_below,
                                           SmoothContactGuess* guess) {
  WireGrainContact out;
  if (!(exact_gap_below >= 0.0))
    throw InvalidArgument("exact_gap_below", "exact_gap_below must be >= 0, got " + format_number(exact_gap_below));
  out.geometry = segment_contact(grain, segment.x0, segment.x1, segment.radius, segment.radius + exact_gap_below, guess);
  if (guess) {
    const bool closest_points = out.geometry.method == DistanceMethod::gjk;
    guess->normal = closest_points ? out.geometry.normal : Eigen::Vector3d::Zero();
    guess->t = closest_points ? out.geometry.t : 0.0;
  }
  out.overlap = -out.geometry.gap;
  out.normal = out.geometry.normal;
  if (!(out.overlap > 0.0)) return out;
  load_touching_pair(law, grain.position(), motion, segment, out.geometry.t, dt, history, out);
  return out;
}

}  // namespace wiregrain
