// What the contact solver sees of a problem (the idea of Chrono's solver interface: a
// Delassus operator and a cone projector, not the engine): per contact its diagonal
// Delassus block W_cc, μ_c, the current local velocity u_c = (W r + q)_c, and a way to add
// an impulse increment. Two operators implement it: BodyContactOperator
// (core/nscd/body_operator.h: bodies and Jacobians, W never formed) behind
// solve_nscd_step, and the reduced problem's (W as 3×3 blocks, q, μ: the FCLib "local"
// problem; core/nscd/reduced_problem.h) behind solve_reduced.
//
// Siconos error (fc3d_compute_error of Siconos numerics 4.4 as fc3d_nsgs calls it, with
// the De Saxcé modified velocity, natural_map_residual in core/nscd/coulomb_local.h):
//     error = sqrt(Σ_c ‖r_c − proj_{K_μc}(r_c − u_c − μ_c ‖u_t,c‖ e_n)‖²)
//             / max(‖q‖, ‖r‖, ‖u‖)
// (no division when the maximum is ≤ DBL_EPSILON). The normalisation was measured on the
// installed library (Debian's 4.4; releases before 4.x divided by 1 + ‖q‖);
// bench/fclib_nscd prints both values for every solve.
#pragma once

#include <Eigen/Dense>

#include <vector>

#include "core/nscd/block_sparse_matrix.h"
#include "core/nscd/coulomb_local.h"

namespace wiregrain {

// What the Gauss–Seidel solver needs from a problem. The operator starts in the state
// r = 0 (velocity(c) = q_c) and follows the increments given to add_impulse.
class ContactOperator {
 public:
  virtual ~ContactOperator() = default;
  virtual int contact_count() const = 0;
  virtual const LocalDelassus& delassus_block(int contact) const = 0;
  virtual double friction_coefficient(int contact) const = 0;
  // u_c = (W r + q)_c for the impulses added so far.
  virtual Eigen::Vector3d velocity(int contact) const = 0;
  // Its normal component alone, equal to velocity(contact)[0] to the bit: the sweep's test
  // of a contact without impulse that stays open (u_n ≥ 0: r = 0 is its local solution).
  virtual double normal_velocity(int contact) const { return velocity(contact)[0]; }
  // r_c += delta; updates what velocity() depends on.
  virtual void add_impulse(int contact, const Eigen::Vector3d& delta) = 0;
  // ‖q‖ (all contacts), the Siconos error's normalisation.
  virtual double free_velocity_norm() const = 0;
  // W itself (method subspace only; may be assembled on the first call).
  virtual const BlockSparseMatrix3& delassus_matrix() = 0;
};

// Siconos error of impulses r on an operator in the state r (see the top of this file).
double siconos_error(const ContactOperator& op, const std::vector<Eigen::Vector3d>& impulses);
// Its sums over the contacts, to be added up over the workers of a distributed step:
// Σ_c ‖r_c − proj(...)‖², ‖r‖², ‖u‖²; and the error from the summed parts and ‖q‖.
struct SiconosErrorSums {
  double residual_squared = 0.0, impulses_squared = 0.0, velocities_squared = 0.0;
};
SiconosErrorSums siconos_error_sums(const ContactOperator& op, const std::vector<Eigen::Vector3d>& impulses);
double siconos_error(const SiconosErrorSums& sums, double free_velocity_norm);

}  // namespace wiregrain
