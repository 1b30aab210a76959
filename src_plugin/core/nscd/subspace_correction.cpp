// The stick solve of method subspace (subspace_correction.h).
#include "core/nscd/subspace_correction.h"

#include <Eigen/SparseCholesky>

#include <algorithm>

namespace wiregrain {

ClosedComponents closed_components(const ContactOperator& op, const std::vector<Eigen::Vector3d>& impulses,
                                   const std::vector<ContactState>& states, double free_velocity_norm) {
  const int n = op.contact_count();
  ClosedComponents closed;
  closed.unknown.assign(3 * n, -1);
  // closing or touching (u_n ≤ 0 up to rounding): e.g. the interfaces of a stack falling
  // as one body in the first sweeps, which Gauss–Seidel loads one interface per sweep
  const double closing = 1e-12 * free_velocity_norm;
  for (int c = 0; c < n; ++c) {
    const bool loaded = states[c] != ContactState::open && impulses[c][0] > 0.0;
    if (!loaded && op.velocity(c)[0] > closing) continue;
    const int count = op.friction_coefficient(c) == 0.0 ? 1 : 3;
    for (int a = 0; a < count; ++a) {
      closed.unknown[3 * c + a] = static_cast<int>(closed.components.size());
      closed.components.push_back(3 * c + a);
    }
  }
  return closed;
}

Eigen::SparseMatrix<double> closed_block(const BlockSparseMatrix3& W, const ClosedComponents& closed) {
  const int m = static_cast<int>(closed.components.size());
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < m; ++i) {
    const int c = closed.components[i] / 3, a = closed.components[i] % 3;
    for (const BlockSparseMatrix3::Entry& e : W.row(c)) {
      for (int b = 0; b < 3; ++b) {
        const int j = closed.unknown[3 * e.column + b];
        if (j >= 0) entries.emplace_back(i, j, e.block(a, b));
      }
    }
  }
  Eigen::SparseMatrix<double> A(m, m);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>* stick_solve_factors(
    const Eigen::SparseMatrix<double>& regularized, NscdReport& report) {
  struct FactorCache {
    std::vector<int> outer, inner;
    std::vector<double> values;  // of the matrix last factorised (empty: none usable)
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor;
  };
  thread_local FactorCache cache;
  const int m = static_cast<int>(regularized.rows());
  const auto same_pattern = [&]() {
    const int* outer = regularized.outerIndexPtr();
    const int* inner = regularized.innerIndexPtr();
    return cache.outer.size() == static_cast<std::size_t>(m + 1) &&
           std::equal(cache.outer.begin(), cache.outer.end(), outer) &&
           cache.inner.size() == static_cast<std::size_t>(regularized.nonZeros()) &&
           std::equal(cache.inner.begin(), cache.inner.end(), inner);
  };
  if (!same_pattern()) {
    cache.outer.assign(regularized.outerIndexPtr(), regularized.outerIndexPtr() + m + 1);
    cache.inner.assign(regularized.innerIndexPtr(), regularized.innerIndexPtr() + regularized.nonZeros());
    cache.values.clear();
    cache.factor.analyzePattern(regularized);
  }
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>& factor = cache.factor;
  const double* values = regularized.valuePtr();
  const bool same_values = cache.values.size() == static_cast<std::size_t>(regularized.nonZeros()) &&
                           std::equal(cache.values.begin(), cache.values.end(), values);
  if (!same_values) {
    cache.values.clear();
    factor.factorize(regularized);
    ++report.subspace_factorizations;
    if (factor.info() != Eigen::Success) return nullptr;
    cache.values.assign(values, values + regularized.nonZeros());
  }
  return &factor;
}


StickSolveOutcome subspace_correction(ContactOperator& op, std::vector<Eigen::Vector3d>& impulses,
                                      const std::vector<ContactState>& states, const SolverSettings& settings,
                                      double error_before, double& error_after, NscdReport& report) {
  const double regularization = settings.subspace_regularization;
  const ClosedComponents closed = closed_components(op, impulses, states, op.free_velocity_norm());
  const std::vector<int>& components = closed.components;
  if (components.empty()) return StickSolveOutcome::harmless;
  const BlockSparseMatrix3& W = op.delassus_matrix();
  const int m = static_cast<int>(components.size());
  const Eigen::SparseMatrix<double> A = closed_block(W, closed);
  Eigen::SparseMatrix<double> regularized = A;
  for (int k = 0; k < m; ++k) regularized.coeffRef(k, k) *= 1.0 + regularization;
  regularized.makeCompressed();
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>* const factor = stick_solve_factors(regularized, report);
  if (factor == nullptr) return StickSolveOutcome::harmful;
  Eigen::VectorXd rhs(m);
  Eigen::VectorXd current(m);
  for (int i = 0; i < m; ++i) {
    current[i] = impulses[components[i] / 3][components[i] % 3];
    rhs[i] = -op.velocity(components[i] / 3)[components[i] % 3];
  }
  // the increment closest to the current impulses: (W_SS + ε D) Δr_S = −u_S (header)
  Eigen::VectorXd increment = factor->solve(rhs);
  for (int refinement = 0; refinement < 2; ++refinement) increment += factor->solve(rhs - A * increment);
  if (!increment.allFinite()) return StickSolveOutcome::harmful;
  const Eigen::VectorXd x = current + increment;

  // the candidate on the Coulomb cones, kept if it halves the Siconos error
  std::vector<int> solved;
  std::vector<Eigen::Vector3d> delta;
  for (int i = 0; i < m;) {
    const int c = components[i] / 3;
    Eigen::Vector3d candidate = impulses[c];
    for (; i < m && components[i] / 3 == c; ++i) candidate[components[i] % 3] = x[i];
    const Eigen::Vector3d updated = project_on_coulomb_cone(candidate, op.friction_coefficient(c));
    solved.push_back(c);
    delta.push_back(updated - impulses[c]);
    op.add_impulse(c, delta.back());
    impulses[c] = updated;
  }
  error_after = siconos_error(op, impulses);
  if (error_after < 0.5 * error_before) return StickSolveOutcome::kept;
  for (int i = 0; i < static_cast<int>(solved.size()); ++i) {
    op.add_impulse(solved[i], -delta[i]);
    impulses[solved[i]] -= delta[i];
  }
  return error_after > 2.0 * error_before ? StickSolveOutcome::harmful : StickSolveOutcome::harmless;
}

void update_backoff(StickSolveBackoff& backoff, bool any_kept, bool harmed) {
  if (any_kept) {
    backoff.wait = 0;
  } else if (harmed) {
    backoff.wait = std::min(std::max(1, 2 * backoff.wait), 1024);
    backoff.skip = backoff.wait;
  }
}

}  // namespace wiregrain
