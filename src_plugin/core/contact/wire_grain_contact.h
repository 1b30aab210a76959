// Soft contact of a wire segment with a grain (paper Sec. 2.3, Fig. 4; docs/design.md,
// "Wire–grain contacts").
//
// The segment [x0, x1] is a spherocylinder of radius r_w, the grain a spheropolyhedron
// (convex core + sweep radius r_p). Geometry from segment_contact (core/geometry/
// segment_contact.h): signed core–axis distance d (exact segment–polytope distance
// when disjoint, minus the penetration depth when the axis crosses the core, so a
// crossing segment still has a defined normal and a finite overlap), unit normal n from
// the grain to the wire and the closest-point parameter t ∈ [0, 1] on the segment.
//   overlap ξ_n = r_p + r_w − d;
//   load point x(t): the closest point; when the segment lies parallel (within the angle
//   tolerance θ_tol of segment_contact) to a face or edge over [t_b, t_e], with the exact
//   overlaps ξ_b, ξ_e of the interval's ends (point–core distances) and the tilt
//   θ = asin(|ξ_b − ξ_e| / ((t_e − t_b) l)) they show,
//       t = w t_lever + (1 − w) t_deeper,  t_lever = (t_b ξ_b⁺ + t_e ξ_e⁺) / (ξ_b⁺ + ξ_e⁺),
//       w = clamp(2 (1 − θ/θ_tol), 0, 1),
//   so a flat-lying segment is loaded at its middle, and as it tilts the load moves
//   continuously to the deeper end, where the geometry puts the single closest point
//   beyond θ_tol. The paper's closest point (Sec. 2.3) is undefined for a flat-lying
//   segment; the middle of the interval, switched to its end at θ_tol, makes a wire lying
//   on faces chatter between the two bead shares and never come to rest. (Loading at
//   the centroid of the overlap profile instead applies the force k_n ξ_n from the
//   closest point elsewhere: the contact is then not conservative and a resting wire
//   keeps vibrating; measured in tests/styles/test_wire_grain.py.)
//   contact point p = x(t) − (r_w − ξ_n/2) n (halfway through the overlap);
//   relative velocity of the wire with respect to the grain at p:
//       u = (1 − t) v_0 + t v_1 − (v_g + ω_g × (p − x_g));
//   force on the wire F = soft_contact_force(law, ξ_n, n, u, dt, m_eff, history) with
//       m_eff = m_w m_g / (m_w + m_g), m_w = m_0 + m_1 (as pair wire/contact does);
//   bead 0 gets (1 − t) F, bead 1 gets t F (the closest-point weights, paper Sec. 2.2);
//   the grain gets −F and the torque (p − x_g) × (−F); no torque on the wire (paper).
// So the forces on wire and grain sum to zero exactly (momentum is conserved); the
// torque on the grain is that of −F applied at p.
#pragma once

#include <limits>

#include <Eigen/Core>

#include "core/contact/contact_time_step.h"
#include "core/contact/soft_contact.h"
#include "core/contact/wire_segment_state.h"
#include "core/geometry/posed_shape.h"
#include "core/geometry/segment_contact.h"
#include "core/geometry/superquadric_contact.h"
#include "core/geometry/superquadric.h"

namespace wiregrain {

struct GrainMotion {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // v_g (of the centre of mass)
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // ω_g (world frame)
  double mass = 0.0;
};

struct WireGrainContact {
  bool touching = false;  // ξ_n > 0; when false only `geometry` and `overlap` are set
  double overlap = 0.0;   // ξ_n (negative: the gap)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  // from the grain to the wire
  Eigen::Vector3d force_bead0 = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_bead1 = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_grain = Eigen::Vector3d::Zero();   // = −(force_bead0 + force_bead1)
  Eigen::Vector3d torque_grain = Eigen::Vector3d::Zero();  // about the grain's centre of mass
  double normal_force = 0.0;
  double load_parameter = 0.0;  // t of the load point: bead 0 gets (1 − t) F, bead 1 t F
  bool sliding = false;
  SpringDashpot spring_dashpot;  // the pair's k and γ, for the beads' time-step check (contact_time_step.h)
  SegmentContact geometry;
};

// t of the load point (above) for the geometry g of a touching pair.
// (two extra exact point–core distances when the segment is parallel to a feature)
double load_point_parameter(const PosedShape& grain, const SegmentContact& g, const WireSegmentState& segment,
                            double angle_tolerance);

// Geometry and force of one (segment, grain) pair. `grain` is posed at its centre of mass
// (PosedShape::position()). history is the pair's tangential spring; it is advanced only
// when the pair touches (the caller drops it when the pair separates). dt = 0 evaluates
// the force without advancing the spring (a setup force call). exact_gap_below ≥ 0 (+inf:
// always exact): the geometry's gap is exact while below it; a pair farther apart may get
// a lower bound of its gap (GJK's early exit, ContactOptions::exit_gap). The force is the
// same whatever the value: it needs only gap ≤ 0. simplex: the geometry's GJK warm start,
// in and out (GjkSimplex), or null.
WireGrainContact wire_grain_contact(const SoftContactLaw& law, const PosedShape& grain,
                                    const GrainMotion& motion, const WireSegmentState& segment,
                                    double dt, TangentialHistory& history,
                                    double exact_gap_below = std::numeric_limits<double>::infinity(),
                                    GjkSimplex* simplex = nullptr);

// The force of a touching pair whose overlap and normal are in `out`, loaded at t on the
// axis (the part after the geometry above, for grains of any kind): the body's centre of
// mass `centre`. Sets touching and everything after `normal`.
void load_touching_pair(const SoftContactLaw& law, const Eigen::Vector3d& centre, const GrainMotion& motion,
                        const WireSegmentState& segment, double t, double dt, TangentialHistory& history,
                        WireGrainContact& out);

// The same contact against a sphere of radius R centred at c (a stock LIGGGHTS granular
// sphere; fix wire/sphere), in closed form: t = clamp((c − x0)·a / |a|², 0, 1) with
// a = x1 − x0, x(t) the foot of c on the segment, d = |x(t) − c|, overlap R + r_w − d,
// n = (x(t) − c)/d; an axis through the centre (d = 0) takes a unit normal ⟂ a. The
// load point is the foot, unique for a sphere. Same force as against a polyhedron
// whose core is the point c (ConvexShape::sphere), without the GJK of the general path.
WireGrainContact wire_sphere_contact(const SoftContactLaw& law, const Eigen::Vector3d& centre, double sphere_radius,
                                     const GrainMotion& motion, const WireSegmentState& segment, double dt,
                                     TangentialHistory& history);

// The same contact against a superquadric (a stock LIGGGHTS superquadric grain): the
// geometry of segment_contact(PosedSuperquadric, ...) (GJK with the closed-form support
// point; core/geometry/superquadric_contact.h), overlap r_w − d (the body has no sweep), the
// load point the closest point, the force as against a polyhedron. (The rule that shares
// the load of a segment lying on a polyhedron's face, load_point_parameter, in its smooth
// form changes nothing measurable on blocky superquadrics: the residual motion of a wire
// lying on their tops goes away with a smaller time step: docs/commands/fix_wire_grain.md,
// Restrictions.)
// exact_gap_below ≥ 0: the geometry's gap is exact while below it; a pair farther apart
// gets a lower bound of its gap (GJK's early exit, far cheaper than the closest points of
// a smooth body). The force is the same whatever the value: it needs only gap ≤ 0.
// guess (optional, in and out): the pair's closest-point solution of the last call, to
// start from (segment_contact's SmoothContactGuess); replaced by this call's when its
// closest points were computed (method gjk), else cleared (normal zero).
WireGrainContact wire_superquadric_contact(const SoftContactLaw& law, const PosedSuperquadric& grain,
                                           const GrainMotion& motion, const WireSegmentState& segment, double dt,
                                           TangentialHistory& history,
                                           double exact_gap_below = std::numeric_limits<double>::infinity(),
                                           SmoothContactGuess* guess = nullptr);


}  // namespace wiregrain
