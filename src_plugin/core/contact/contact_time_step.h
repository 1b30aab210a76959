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

}  // namespace wiregrain
