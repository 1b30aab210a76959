// The stress of one grain from the forces at its contacts (Love–Weber):
//
//   σ_i = (1/V_i) Σ_c (x_c − x_i) ⊗ f_c,   (a ⊗ b)_jk = a_j b_k,
//
// x_i the grain's centre of mass, V_i its volume, f_c the force grain i receives at contact
// point x_c (Love 1927; Weber 1966; Christoffersen, Mehrabadi & Nemat-Nasser, J. Appl. Mech.
// 48:339, 1981). Tension is positive: a grain squeezed between two plates has σ_zz < 0.
// The tensor is symmetric when the grain's contact forces have no net torque (statics,
// no rolling couples); out of equilibrium it is not, and all nine components are kept.
//
// The volume sum of a packing's grain stresses is fixed by its boundary (an identity of the
// sum over contacts: each inner contact's force acts on both grains, with opposite signs):
//   Σ_i V_i σ_i = Σ_{boundary c} x_c ⊗ f_c − Σ_i x_i ⊗ F_i,
// F_i the total contact force on grain i (= −m_i g at rest under gravity).
#pragma once

#include <Eigen/Core>

namespace wiregrain {

// Σ_c (x_c − x_i) ⊗ f_c, built one contact at a time.
struct ContactMomentSum {
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  // arm = x_c − x_i (the minimum image in a periodic box), force = f_c on the grain
  void add(const Eigen::Vector3d& arm, const Eigen::Vector3d& force) { sum += arm * force.transpose(); }
};

// σ = sum / V; InvalidArgument("volume") unless V > 0 and finite.
Eigen::Matrix3d love_weber_stress(const Eigen::Matrix3d& moment_sum, double volume);

// The mean normal stress as a pressure, p = −(σ_xx + σ_yy + σ_zz)/3: positive in compression.
double pressure(const Eigen::Matrix3d& stress);

}  // namespace wiregrain
