#include "core/contact/wire_grain_contact.h"

#include <algorithm>

namespace wiregrain {

double load_point_parameter(const SegmentContact& g, const WireSegmentState& segment, double sweep_radius) {
  if (!(g.t_end > g.t_begin)) return g.t;
  const Eigen::Vector3d axis = segment.x1 - segment.x0;
  const double reach = sweep_radius + segment.radius;
  const auto overlap_at = [&](double t) {
    return std::max(0.0, reach - g.normal.dot(segment.x0 + t * axis - g.point_on_core));
  };
  const double begin = overlap_at(g.t_begin), end = overlap_at(g.t_end);
  if (!(begin + end > 0.0)) return g.t;
  return (g.t_begin * begin + g.t_end * end) / (begin + end);
}

WireGrainContact wire_grain_contact(const SoftContactLaw& law, const PosedShape& grain,
                                    const GrainMotion& motion, const WireSegmentState& segment,
                                    double dt, TangentialHistory& history) {
  WireGrainContact out;
  out.geometry = segment_contact(grain, segment.x0, segment.x1, segment.radius);
  const SegmentContact& g = out.geometry;
  out.overlap = -g.gap;
  out.normal = g.normal;
  if (!(out.overlap > 0.0)) return out;
  out.touching = true;
  const double t = load_point_parameter(g, segment, grain.sweep_radius());
  out.load_parameter = t;
  const Eigen::Vector3d axis_point = segment.x0 + t * (segment.x1 - segment.x0);
  out.point = axis_point - (segment.radius - 0.5 * out.overlap) * g.normal;
  const Eigen::Vector3d arm = out.point - grain.position();
  const Eigen::Vector3d wire_velocity = (1.0 - t) * segment.v0 + t * segment.v1;
  const Eigen::Vector3d grain_velocity = motion.velocity + motion.angular_velocity.cross(arm);
  const double wire_mass = segment.m0 + segment.m1;
  const double effective_mass = wire_mass * motion.mass / (wire_mass + motion.mass);
  const SoftContactForce f = soft_contact_force(law, out.overlap, g.normal, wire_velocity - grain_velocity, dt,
                                                effective_mass, history);
  out.normal_force = f.normal_force;
  out.sliding = history.sliding;
  out.force_bead0 = (1.0 - t) * f.force;
  out.force_bead1 = t * f.force;
  out.force_grain = -(out.force_bead0 + out.force_bead1);
  out.torque_grain = arm.cross(out.force_grain);
  return out;
}

}  // namespace wiregrain
