// The wire–wire contact; the equations are in wire_wire_contact.h.
#include "core/contact/wire_wire_contact.h"

#include <Eigen/Geometry>

namespace wiregrain {

WireWireContact wire_wire_geometry(const WireSegmentState& a, const WireSegmentState& b) {
  WireWireContact out;
  out.closest = segment_closest_points(a.x0, a.x1, b.x0, b.x1);
  const SegmentClosestPoints& cp = out.closest;
  out.overlap = a.radius + b.radius - cp.distance;
  if (out.overlap <= 0.0) return out;
  out.touching = true;
  Eigen::Vector3d normal = cp.q - cp.p;
  if (cp.distance > 0.0) {
    normal /= cp.distance;
  } else {  // the axes intersect: push apart perpendicular to both
    normal = (a.x1 - a.x0).cross(b.x1 - b.x0);
    if (normal.norm() == 0.0) normal = Eigen::Vector3d::UnitZ();
    normal.normalize();
  }
  out.normal = normal;
  out.point = cp.p + (a.radius - 0.5 * out.overlap) * normal;
  return out;
}

void load_wire_wire_pair(const SoftContactLaw& law, const WireSegmentState& a, const WireSegmentState& b, double dt,
                         TangentialHistory& history, WireWireContact& out) {
  const double s = out.closest.s, t = out.closest.t;
  const Eigen::Vector3d va = (1.0 - s) * a.v0 + s * a.v1;
  const Eigen::Vector3d vb = (1.0 - t) * b.v0 + t * b.v1;
  const double m_a = a.m0 + a.m1, m_b = b.m0 + b.m1;
  const double effective_mass = m_a * m_b / (m_a + m_b);
  const SoftContactForce f = soft_contact_force(law, out.overlap, out.normal, vb - va, dt, effective_mass, history);
  out.force = f.force;
  out.force_b0 = (1.0 - t) * f.force;
  out.force_b1 = t * f.force;
  out.force_a0 = -(1.0 - s) * f.force;
  out.force_a1 = -s * f.force;
  out.normal_force = f.normal_force;
  out.sliding = history.sliding;
  out.elastic_energy = 0.5 * law.normal_stiffness * out.overlap * out.overlap +
                       0.5 * law.tangential_stiffness * history.spring.squaredNorm();
  out.spring_dashpot = contact_spring_dashpot(law, effective_mass);
}

WireWireContact wire_wire_contact(const SoftContactLaw& law, const WireSegmentState& a, const WireSegmentState& b,
                                  double dt, TangentialHistory& history) {
  WireWireContact out = wire_wire_geometry(a, b);
  if (out.touching) load_wire_wire_pair(law, a, b, dt, history, out);
  return out;
}

}  // namespace wiregrain
