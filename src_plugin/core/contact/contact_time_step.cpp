// Stability limits of a soft contact's spring–dashpot; the formulas are in contact_time_step.h.
#include "core/contact/contact_time_step.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "core/common/validation.h"
#include "core/wire/gear_integrator.h"

namespace wiregrain {

ContactTimeStep spring_dashpot_time_step(double k, double m, double zeta) {
  require_nonnegative("k", k);
  require_positive("m", m);
  require_nonnegative("damping_ratio", zeta);
  ContactTimeStep out;
  if (k == 0.0) {
    out.critical = out.gear5 = std::numeric_limits<double>::infinity();
    return out;
  }
  const double omega = std::sqrt(k / m);
  // √(1 + ζ²) − ζ written as 1/(√(1 + ζ²) + ζ): no cancellation for large ζ
  const double damped = 1.0 / (std::sqrt(1.0 + zeta * zeta) + zeta);
  out.critical = 2.0 / omega * damped;
  out.gear5 = kGear5StableOmegaDt / omega * damped;
  if (zeta > 0.0) out.gear5 = std::min(out.gear5, kGear5StableDampedOmegaDt / (zeta * omega));
  return out;
}

ContactTimeStep contact_time_step(const SoftContactLaw& law, double effective_mass) {
  return spring_dashpot_time_step(std::max(law.normal_stiffness, law.tangential_stiffness), effective_mass,
                                  law.damping_ratio);
}

SpringDashpot contact_spring_dashpot(const SoftContactLaw& law, double m) {
  SpringDashpot out;
  out.normal_stiffness = law.normal_stiffness;
  out.tangential_stiffness = law.tangential_stiffness;
  out.normal_damping = 2.0 * law.damping_ratio * std::sqrt(law.normal_stiffness * m);
  out.tangential_damping = 2.0 * law.damping_ratio * std::sqrt(law.tangential_stiffness * m);
  return out;
}

ContactLoadEntries contact_load_entries(const SpringDashpot& c, const Eigen::Vector3d& n) {
  ContactLoadEntries out;
  const double outer[6] = {n.x() * n.x(), n.y() * n.y(), n.z() * n.z(), n.x() * n.y(), n.x() * n.z(), n.y() * n.z()};
  const double stiffness_along = c.normal_stiffness - c.tangential_stiffness;
  const double damping_along = c.normal_damping - c.tangential_damping;
  for (int e = 0; e < 6; e++) {
    const double identity = e < 3 ? 1.0 : 0.0;
    out.stiffness[e] = c.tangential_stiffness * identity + stiffness_along * outer[e];
    out.damping[e] = c.tangential_damping * identity + damping_along * outer[e];
  }
  return out;
}

void BeadContactLoad::add(double weight, const SpringDashpot& c, const Eigen::Vector3d& n) {
  add(weight, contact_load_entries(c, n));
}

void BeadContactLoad::add(double weight, const ContactLoadEntries& c) {
  // entries xx, yy, zz, xy, xz, yz at (row, column) of the symmetric 3×3
  static constexpr int row[6] = {0, 1, 2, 0, 0, 1}, column[6] = {0, 1, 2, 1, 2, 2};
  for (int e = 0; e < 6; e++) {
    stiffness(row[e], column[e]) += weight * c.stiffness[e];
    damping(row[e], column[e]) += weight * c.damping[e];
    if (e >= 3) {
      stiffness(column[e], row[e]) += weight * c.stiffness[e];
      damping(column[e], row[e]) += weight * c.damping[e];
    }
  }
  contacts++;
}

ContactTimeStep bead_contact_time_step(const BeadContactLoad& load, double mass) {
  if (load.contacts == 0) return spring_dashpot_time_step(0.0, mass, 0.0);
  const auto largest = [](const Eigen::Matrix3d& symmetric) {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(symmetric, Eigen::EigenvaluesOnly);
    return std::max(0.0, solver.eigenvalues()[2]);  // ascending; round-off below 0 is 0
  };
  return bead_contact_time_step(largest(load.stiffness), largest(load.damping), mass);
}

ContactTimeStep bead_contact_time_step_bound(const BeadContactLoad& load, double mass) {
  // K and Γ are positive semi-definite: λ_max ≤ trace, and each limit falls as the
  // stiffness or the damping grows (1/(√(ω² + c²) + c) in ω and c = Γ/(2m))
  return bead_contact_time_step(load.stiffness.trace(), load.damping.trace(), mass);
}

ContactTimeStep bead_contact_time_step(double stiffness, double damping, double mass) {
  require_nonnegative("damping", damping);
  require_nonnegative("k", stiffness);
  require_positive("m", mass);
  if (stiffness == 0.0 && damping == 0.0) return spring_dashpot_time_step(0.0, mass, 0.0);
  ContactTimeStep out;
  if (stiffness == 0.0) {  // a dashpot alone: the Verlet bound 1/(ζω) → 2m/Γ, Gear's 0.075 · 2m/Γ
    out.critical = 2.0 * mass / damping;
    out.gear5 = kGear5StableDampedOmegaDt * 2.0 * mass / damping;
    return out;
  }
  return spring_dashpot_time_step(stiffness, mass, damping / (2.0 * std::sqrt(stiffness * mass)));
}

double reduced_mass(double a, double b) {
  if (std::isinf(b)) return a;
  if (std::isinf(a)) return b;
  return a * b / (a + b);
}

}  // namespace wiregrain
