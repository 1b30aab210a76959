// Soft (penalty) contact of the wire: linear spring–dashpot in the normal direction and a
// tangential spring with static and dynamic Coulomb friction (Cundall & Strack 1979; the
// paper's section 2.2; docs/design.md, "The wire: bead chain with soft contacts"). Used for
// wire–wire, wire–wall and wire–grain contacts; each pairing's stiffnesses are built from
// the materials in contact_laws.h.
#pragma once

#include <Eigen/Core>

namespace wiregrain {

struct SoftContactLaw {
  double normal_stiffness = 0.0;      // k_n
  double tangential_stiffness = 0.0;  // k_t
  double damping_ratio = 0.0;         // ζ: γ_n = 2ζ√(k_n m), γ_t = 2ζ√(k_t m)
  double static_friction = 0.0;       // μ_s
  double dynamic_friction = 0.0;      // μ_d ≤ μ_s
  bool limit_force = false;           // no attractive normal force when true

  // Throws InvalidArgument for negative values or μ_d > μ_s (names: k_n, k_t,
  // damping_ratio, mu_s, mu_d).
  void validate() const;
};

// ζ of a linear spring–dashpot whose coefficient of restitution is e, from
// e = exp(−πζ/√(1−ζ²)): ζ = −ln e / √(π² + ln² e). e = 0 gives ζ = 1 (critical), e = 1 gives 0.
double damping_ratio_from_restitution(double restitution);
// and back
double restitution_from_damping_ratio(double damping_ratio);

// History of one contact: the tangential spring ξ_t and whether it slid last step.
struct TangentialHistory {
  Eigen::Vector3d spring = Eigen::Vector3d::Zero();
  bool sliding = false;
};

struct SoftContactForce {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // on body B; body A gets −force
  double normal_force = 0.0;                        // f_n (k_n ξ + γ_n ξ̇)
  double tangential_force = 0.0;                    // |f_t|
};

// One contact at overlap ξ ≥ 0 with unit normal n from A to B and relative velocity
// u = v_B − v_A of the contact points, for a time step dt and effective mass m.
//   f_n = k_n ξ − γ_n (u·n)                  (ξ̇ = −u·n; clamped at 0 with limit_force)
//   ξ_t: rotated into the current tangent plane (length kept), then ξ_t += u_t dt
//   trial f_t = −k_t ξ_t − γ_t u_t
//   slips when |f_t| > μ f_n with μ = μ_s while sticking, μ_d while already sliding
//   (so sliding continues at μ_d as long as the motion goes on); then
//   f_t = μ_d f_n t̂ and the spring is reset to the slip limit, k_t ξ_t = −f_t.
// The history is updated in place.
SoftContactForce soft_contact_force(const SoftContactLaw& law, double overlap,
                                    const Eigen::Vector3d& normal,
                                    const Eigen::Vector3d& relative_velocity, double dt,
                                    double effective_mass, TangentialHistory& history);

}  // namespace wiregrain
