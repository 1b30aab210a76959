// The time step a soft contact of the wire allows: the stability limits of explicit
// integration of one linear spring–dashpot (the contact law of soft_contact.h) acting on
// a point mass. The contact styles (pair wire/contact, fix wire/wall, fix wire/grain)
// evaluate it at each run start for their stiffest contact on their lightest mass and
// warn when the time step exceeds it; fix wire/elastic does the same for its springs
// (wire_elasticity.h: dt_crit = 2/ω_max, gear5 limit 0.313/ω_max).
//
// For a spring k on a mass m with damping ratio ζ (γ = 2ζ√(k m)), ω = √(k/m):
//   velocity Verlet, the damping force evaluated with the half-step velocity (what
//   LIGGGHTS' nve and nve/gear's verlet scheme do):
//       dt_crit = (2/ω) (√(1 + ζ²) − ζ)
//     the critical step of the central-difference method with damping (Belytschko, Liu &
//     Moran, Nonlinear Finite Elements for Continua and Structures, Wiley 2000, ch. 6,
//     stability of explicit integration); ζ = 0 gives 2/ω, the convention of fix
//     wire/elastic;
//   6-value Gear (nve/gear's gear5): ω dt < 0.313 (√(1 + ζ²) − ζ) and ζ ω dt < 0.075. The
//     first is fix wire/elastic's fraction 0.313/2 of dt_crit (kGear5StableOmegaDt,
//     exact for ζ = 0); the second is where the damping term makes the corrector unstable
//     first (ζ ≳ 0.33, restitution ≲ 0.33): measured on the core's gear5 kernels, the first
//     unstable ζ ω dt is 0.0743 at ζ = 0.3, 0.079 at 0.5, 0.0825 at 1 and 0.085 at 2
//     (tests/core/test_contact_time_step.cpp checks both bounds).
// The stiffer of the normal and the tangential spring (k_n = E* l π/4, k_t = E* r) sets
// ω: the tangential one is the stiffer for segments shorter than 4r/π.
#pragma once

#include <Eigen/Core>

#include "core/contact/soft_contact.h"

namespace wiregrain {

// ζ ω dt below which the 6-value Gear corrector is stable on a damped mode (see above).
constexpr double kGear5StableDampedOmegaDt = 0.075;

struct ContactTimeStep {
  double critical = 0.0;  // dt_crit of velocity Verlet (the "Verlet limit")
  double gear5 = 0.0;     // the limit of the 6-value Gear corrector
  // the limit of the integrator in use
  double limit(bool gear5_integrator) const { return gear5_integrator ? gear5 : critical; }
};

// The limits of a spring k ≥ 0 with damping ratio ζ ≥ 0 on a mass m > 0; infinite for
// k = 0. Throws InvalidArgument (names "k", "m", "damping_ratio") otherwise.
ContactTimeStep spring_dashpot_time_step(double stiffness, double mass, double damping_ratio);

// The limits of a soft contact law on the effective mass m_eff of its two sides: the
// stiffer of k_n and k_t, the law's ζ.
ContactTimeStep contact_time_step(const SoftContactLaw& law, double effective_mass);

// m_a m_b / (m_a + m_b); m_b = ∞ (a wall, a held grain) gives m_a.
double reduced_mass(double mass_a, double mass_b);

// The springs and dashpots all the contacts of a step put on ONE bead (a bead wedged
// between grains, loaded by the contacts of both its segments, can rattle at the contact
// frequency although each contact alone is within its limit: the Table 1 column's beads at
// Δt_SP = 1e-3 under Gear-5).
// A contact with normal n, springs k_n, k_t and dashpots γ_n = 2ζ√(k_n m_eff), γ_t =
// 2ζ√(k_t m_eff) (its law's), whose force reaches the bead with the weight w (1 − t or t of
// the load point on the segment, 1 for a wall), adds
//     w S (k_n n nᵀ + k_t (I − n nᵀ))   to the bead's stiffness K (3×3),
//     w S (γ_n n nᵀ + γ_t (I − n nᵀ))   to its damping Γ,
// S the sum of the weights of all the bodies it moves (1 against a wall or a grain held
// during the sub-steps, 2 between two segments or against a moving grain): the bead's
// block row of K summed in absolute values over the beads (Gershgorin's bound on the
// stiffest mode the bead takes part in; exact for a contact at a bead and for the beads
// of a segment moving together). The bead's limit is that of one spring on its mass m
// with the largest eigenvalues of K and Γ: ω² = λ_max(K)/m, ζω = λ_max(Γ)/(2m).
struct SpringDashpot {
  double normal_stiffness = 0.0, tangential_stiffness = 0.0;  // k_n, k_t
  double normal_damping = 0.0, tangential_damping = 0.0;      // γ_n, γ_t
};
SpringDashpot contact_spring_dashpot(const SoftContactLaw& law, double effective_mass);

// One contact's k_t I + (k_n − k_t) n nᵀ and γ_t I + (γ_n − γ_t) n nᵀ as their six
// entries xx, yy, zz, xy, xz, yz: formed once per contact, added to each bead it loads.
struct ContactLoadEntries {
  double stiffness[6];
  double damping[6];
};
ContactLoadEntries contact_load_entries(const SpringDashpot& contact, const Eigen::Vector3d& normal);

struct BeadContactLoad {
  Eigen::Matrix3d stiffness = Eigen::Matrix3d::Zero();  // K
  Eigen::Matrix3d damping = Eigen::Matrix3d::Zero();    // Γ
  int contacts = 0;
  // one contact with the weight w S (above) and unit normal n
  void add(double weight, const SpringDashpot& contact, const Eigen::Vector3d& normal);
  void add(double weight, const ContactLoadEntries& contact);
};
// The bead's limits (m > 0); infinite without contacts.
ContactTimeStep bead_contact_time_step(const BeadContactLoad& load, double mass);
// Lower bounds of those limits from the traces of K and Γ (no eigenvalues: for the beads
// that cannot be the one furthest beyond its limit).
ContactTimeStep bead_contact_time_step_bound(const BeadContactLoad& load, double mass);
// The same from the largest eigenvalues λ_max(K) ≥ 0, λ_max(Γ) ≥ 0.
ContactTimeStep bead_contact_time_step(double stiffness, double damping, double mass);

}  // namespace wiregrain
