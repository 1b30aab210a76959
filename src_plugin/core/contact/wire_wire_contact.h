// Soft contact of two wire segments (the paper's section 2.2 and Sec. 2.4, wire–wire
// bullet; docs/design.md, "The wire: bead chain with soft contacts").
//
// Segment A = [a0, a1] and segment B = [b0, b1] are spherocylinders of radii r_a, r_b.
//   closest points of the two axes (segment_closest_points, core/geometry/
//   segment_distance.h): p = a0 + s (a1 − a0) on A, q = b0 + t (b1 − b0) on B, d = |q − p|;
//   overlap ξ = r_a + r_b − d; unit normal n = (q − p)/d from A to B; where the axes
//   intersect (d = 0), n = (a1 − a0) × (b1 − b0) normalised (perpendicular to both), +z
//   for parallel axes;
//   contact point p + (r_a − ξ/2) n (the middle of the overlap);
//   relative velocity of B with respect to A at the contact, each side's velocity that of
//   its axis point, interpolated between its beads:
//       u = ((1 − t) v_b0 + t v_b1) − ((1 − s) v_a0 + s v_a1);
//   force on B: F = soft_contact_force(law, ξ, n, u, dt, m_eff, history) with
//       m_eff = m_A m_B / (m_A + m_B), m_A = m_a0 + m_a1, m_B = m_b0 + m_b1;
//   shared among the four beads by the lever rule of the closest points:
//       b0 gets (1 − t) F, b1 gets t F, a0 gets −(1 − s) F, a1 gets −s F.
// So the four forces sum to zero, and their torque is (q − p) × F: zero for the normal
// force, that of the couple of the tangential force across d otherwise.
// The stiffnesses of `law` for a wire–wire pair (core/contact/contact_laws.h): E* of the
// two materials, l_w and r_w the means of the two segments' rest lengths and radii.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/contact/contact_time_step.h"
#include "core/contact/soft_contact.h"
#include "core/contact/wire_segment_state.h"
#include "core/geometry/segment_distance.h"

namespace wiregrain {

// The geometry of a pair of segments: what every pair that passes the bounding-sphere test
// costs, so it holds nothing else.
struct WireWireGeometry {
  bool touching = false;  // ξ > 0; when false only `closest` and `overlap` are set
  double overlap = 0.0;   // ξ (negative: the gap)
  SegmentClosestPoints closest;  // s on A, t on B, p, q, d
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // from A to B
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // the middle of the overlap
};

// A touching pair: its geometry and the force.
struct WireWireContact : WireWireGeometry {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // F, on B; A gets −F
  Eigen::Vector3d force_a0 = Eigen::Vector3d::Zero(), force_a1 = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_b0 = Eigen::Vector3d::Zero(), force_b1 = Eigen::Vector3d::Zero();
  double normal_force = 0.0;  // f_n
  bool sliding = false;
  double elastic_energy = 0.0;  // k_n ξ²/2 + k_t |ξ_t|²/2, ξ_t the spring after this call
  double effective_mass = 0.0;  // m_eff: the pair's springs and dashpots for the beads' time-step
                                // check are contact_spring_dashpot(law, m_eff) (contact_time_step.h)
};

// Both inline: the pair loop of pair wire/contact calls them for every candidate pair.
//
// The geometry of the pair (above): closest points and overlap; normal and contact point
// when touching. Only positions and radii of the segments are read.
inline WireWireGeometry wire_wire_geometry(const WireSegmentState& a, const WireSegmentState& b) {
  WireWireGeometry out;
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

// The force of a touching pair of geometry g (from wire_wire_geometry). history is the
// pair's tangential spring, advanced in place; dt = 0 evaluates the force without
// advancing the spring (a setup force call).
inline WireWireContact load_wire_wire_pair(const SoftContactLaw& law, const WireSegmentState& a,
                                           const WireSegmentState& b, double dt, TangentialHistory& history,
                                           const WireWireGeometry& g) {
  WireWireContact out;
  static_cast<WireWireGeometry&>(out) = g;
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
  out.effective_mass = effective_mass;
  return out;
}

// Both: the geometry, then the force when the pair touches (history untouched otherwise;
// a pair apart has only the geometry's fields set).
WireWireContact wire_wire_contact(const SoftContactLaw& law, const WireSegmentState& a, const WireSegmentState& b,
                                  double dt, TangentialHistory& history);

}  // namespace wiregrain
