// The distributed stick solve (distributed_stick_solve.h).
#include "core/nscd/distributed_stick_solve.h"

#include <algorithm>
#include <cmath>

namespace wiregrain {

namespace {

// Per contact: which of its components are unknowns of the stick solve (all three of a
// closed frictional contact, the normal one of a closed frictionless one, none of an open
// one), as subspace_correction's closed_components selects them.
std::vector<Eigen::Vector3d> closed_mask(const BodyContactOperator& op, const std::vector<Eigen::Vector3d>& impulses,
                                         const std::vector<ContactState>& states, double free_velocity_norm) {
  const int n = op.contact_count();
  const double closing = 1e-12 * free_velocity_norm;
  std::vector<Eigen::Vector3d> mask(n, Eigen::Vector3d::Zero());
  for (int c = 0; c < n; ++c) {
    const bool loaded = states[c] != ContactState::open && impulses[c][0] > 0.0;
    if (!loaded && op.velocity(c)[0] > closing) continue;
    mask[c] = op.friction_coefficient(c) == 0.0 ? Eigen::Vector3d(1.0, 0.0, 0.0) : Eigen::Vector3d::Ones();
  }
  return mask;
}

double dot(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double sum = 0.0;
  for (std::size_t c = 0; c < a.size(); ++c) sum += a[c].dot(b[c]);
  return sum;
}

}  // namespace

DistributedStickSolve distributed_stick_solve(const BodyContactOperator& op, const std::vector<Eigen::Vector3d>& impulses,
                                              const std::vector<ContactState>& states, const SolverSettings& settings,
                                              double free_velocity_norm, WorkerExchange& exchange) {
  const int n = op.contact_count();
  const double epsilon = settings.subspace_regularization;
  const std::vector<Eigen::Vector3d> mask = closed_mask(op, impulses, states, free_velocity_norm);
  DistributedStickSolve out;
  out.candidate = impulses;
  double unknowns = 0.0;
  for (const Eigen::Vector3d& m : mask) unknowns += m.sum();
  exchange.sum_over_workers(&unknowns, 1);
  if (unknowns == 0.0) return out;
  out.any_closed = true;
  // the preconditioner: per contact the inverse of (W_cc + ε diag W_cc) on its unknowns
  std::vector<Eigen::Matrix3d> block_inverse(n, Eigen::Matrix3d::Zero());
  std::vector<Eigen::Vector3d> diagonal(n, Eigen::Vector3d::Zero());
  for (int c = 0; c < n; ++c) {
    if (mask[c].isZero(0.0)) continue;
    const Eigen::Matrix3d W = op.true_delassus_block(c);
    diagonal[c] = W.diagonal().cwiseProduct(mask[c]);
    if (mask[c][1] == 0.0) {
      block_inverse[c](0, 0) = 1.0 / ((1.0 + epsilon) * W(0, 0));
    } else {
      Eigen::Matrix3d regularized = W;
      regularized.diagonal() *= 1.0 + epsilon;
      block_inverse[c] = regularized.inverse();
    }
  }
  // A p = W_SS p + ε D_S p on the unknowns
  const auto apply = [&](const std::vector<Eigen::Vector3d>& p) {
    std::vector<Eigen::Vector3d> product = op.delassus_product(p, exchange);
    for (int c = 0; c < n; ++c) product[c] = (product[c] + epsilon * diagonal[c].cwiseProduct(p[c])).cwiseProduct(mask[c]);
    return product;
  };
  const auto sum = [&](double value) {
    exchange.sum_over_workers(&value, 1);
    return value;
  };
  std::vector<Eigen::Vector3d> x(n, Eigen::Vector3d::Zero()), residual(n), z(n), p(n);
  for (int c = 0; c < n; ++c) residual[c] = (-op.velocity(c)).cwiseProduct(mask[c]);
  for (int c = 0; c < n; ++c) z[c] = block_inverse[c] * residual[c];
  p = z;
  double rz = sum(dot(residual, z));
  const double rhs_norm = std::sqrt(sum(dot(residual, residual)));
  const int cap = std::max(100, static_cast<int>(unknowns));
  double residual_norm = rhs_norm;
  while (out.iterations < cap && residual_norm > 1e-12 * rhs_norm) {
    const std::vector<Eigen::Vector3d> Ap = apply(p);
    const double pAp = sum(dot(p, Ap));
    if (!(pAp > 0.0)) break;  // (a direction W_SS + ε D does not see: round-off)
    const double alpha = rz / pAp;
    for (int c = 0; c < n; ++c) {
      x[c] += alpha * p[c];
      residual[c] -= alpha * Ap[c];
      z[c] = block_inverse[c] * residual[c];
    }
    double sums[2] = {dot(residual, z), dot(residual, residual)};
    exchange.sum_over_workers(sums, 2);
    residual_norm = std::sqrt(sums[1]);
    const double beta = sums[0] / rz;
    rz = sums[0];
    for (int c = 0; c < n; ++c) p[c] = z[c] + beta * p[c];
    ++out.iterations;
  }
  out.residual = rhs_norm > 0.0 ? residual_norm / rhs_norm : 0.0;
  for (int c = 0; c < n; ++c)
    if (!mask[c].isZero(0.0))
      out.candidate[c] = project_on_coulomb_cone(impulses[c] + x[c], op.friction_coefficient(c));
  return out;
}

}  // namespace wiregrain
