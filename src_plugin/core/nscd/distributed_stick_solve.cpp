// The distributed stick solve (distributed_stick_solve.h).
#include "core/nscd/distributed_stick_solve.h"

#include <algorithm>
#include <cmath>

#include "core/nscd/subspace_correction.h"

namespace wiregrain {

namespace {

// CG stops once its residual has not halved over this many iterations (header)
constexpr int kStallWindow = 50;

double dot(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double sum = 0.0;
  for (std::size_t c = 0; c < a.size(); ++c) sum += a[c].dot(b[c]);
  return sum;
}

// z = M⁻¹ r on this worker's unknowns: the LDLᵀ factors of its own block of
// W_SS + ε D_S (`factor`), or, where that factorisation failed, each contact's 3×3 block
// (`block_inverse`; zero for a worker without unknowns and for its contacts not closed).
class WorkerPreconditioner {
 public:
  WorkerPreconditioner(const BodyContactOperator& op, const ClosedComponents& closed, double epsilon,
                       NscdReport& report)
      : closed_(closed) {
    const int n = op.contact_count();
    const int m = static_cast<int>(closed.components.size());
    block_inverse_.assign(n, Eigen::Matrix3d::Zero());
    if (m == 0) return;
    Eigen::SparseMatrix<double> regularized = closed_block(op.true_delassus_matrix(), closed);
    for (int k = 0; k < m; ++k) regularized.coeffRef(k, k) *= 1.0 + epsilon;
    regularized.makeCompressed();
    factor_ = stick_solve_factors(regularized, report);
    if (factor_ != nullptr) return;
    for (int c = 0; c < n; ++c) {
      if (closed.unknown[3 * c] < 0) continue;
      const Eigen::Matrix3d W = op.true_delassus_block(c);
      if (closed.unknown[3 * c + 1] < 0) {
        block_inverse_[c](0, 0) = 1.0 / ((1.0 + epsilon) * W(0, 0));
      } else {
        Eigen::Matrix3d regularized_block = W;
        regularized_block.diagonal() *= 1.0 + epsilon;
        block_inverse_[c] = regularized_block.inverse();
      }
    }
  }

  void apply(const std::vector<Eigen::Vector3d>& r, std::vector<Eigen::Vector3d>& z) const {
    const std::vector<int>& components = closed_.components;
    const int m = static_cast<int>(components.size());
    if (factor_ == nullptr) {
      for (std::size_t c = 0; c < r.size(); ++c) z[c] = block_inverse_[c] * r[c];
      return;
    }
    Eigen::VectorXd rhs(m);
    for (int i = 0; i < m; ++i) rhs[i] = r[components[i] / 3][components[i] % 3];
    const Eigen::VectorXd solution = factor_->solve(rhs);
    for (Eigen::Vector3d& v : z) v.setZero();
    for (int i = 0; i < m; ++i) z[components[i] / 3][components[i] % 3] = solution[i];
  }

 private:
  const ClosedComponents& closed_;
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>* factor_ = nullptr;
  std::vector<Eigen::Matrix3d> block_inverse_;
};

}  // namespace

DistributedStickSolve distributed_stick_solve(const BodyContactOperator& op, const std::vector<Eigen::Vector3d>& impulses,
                                              const std::vector<ContactState>& states, const SolverSettings& settings,
                                              double free_velocity_norm, WorkerExchange& exchange) {
  const int n = op.contact_count();
  const double epsilon = settings.subspace_regularization;
  const ClosedComponents closed = closed_components(op, impulses, states, free_velocity_norm);
  DistributedStickSolve out;
  out.candidate = impulses;
  double unknowns = static_cast<double>(closed.components.size());
  exchange.sum_over_workers(&unknowns, 1);
  if (unknowns == 0.0) return out;
  out.any_closed = true;
  std::vector<Eigen::Vector3d> mask(n, Eigen::Vector3d::Zero()), diagonal(n, Eigen::Vector3d::Zero());
  for (const int k : closed.components) mask[k / 3][k % 3] = 1.0;
  for (int c = 0; c < n; ++c)
    if (!mask[c].isZero(0.0)) diagonal[c] = op.true_delassus_block(c).diagonal().cwiseProduct(mask[c]);
  NscdReport factorizations;  // (the caller counts the CG iterations instead)
  const WorkerPreconditioner preconditioner(op, closed, epsilon, factorizations);
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
  preconditioner.apply(residual, z);
  p = z;
  double rz = sum(dot(residual, z));
  const double rhs_norm = std::sqrt(sum(dot(residual, residual)));
  const int cap = std::max(100, static_cast<int>(unknowns));
  double residual_norm = rhs_norm;
  double residual_before = rhs_norm;  // kStallWindow iterations ago
  while (out.iterations < cap && residual_norm > 1e-12 * rhs_norm) {
    if (out.iterations > 0 && out.iterations % kStallWindow == 0) {
      if (residual_norm > 0.5 * residual_before) break;  // stalled (header)
      residual_before = residual_norm;
    }
    const std::vector<Eigen::Vector3d> Ap = apply(p);
    const double pAp = sum(dot(p, Ap));
    if (!(pAp > 0.0)) break;  // (a direction W_SS + ε D does not see: round-off)
    const double alpha = rz / pAp;
    for (int c = 0; c < n; ++c) {
      x[c] += alpha * p[c];
      residual[c] -= alpha * Ap[c];
    }
    preconditioner.apply(residual, z);
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
