// The reduced problem (reduced_problem.h): its checks, its operator, its solve and its
// assembly from a time step.
#include "core/nscd/reduced_problem.h"

#include <string>

#include "core/common/errors.h"
#include "core/nscd/body_operator.h"
#include "core/nscd/input_checks.h"

namespace wiregrain {

void ReducedProblem::validate() const {
  const int n = contact_count();
  if (q.size() != 3 * n) {
    throw InvalidArgument("q", "q has " + std::to_string(q.size()) + " entries for " +
                                   std::to_string(n) + " contacts (3 each)");
  }
  if (static_cast<int>(mu.size()) != n) {
    throw InvalidArgument("mu", "mu has " + std::to_string(mu.size()) + " entries for " +
                                    std::to_string(n) + " contacts");
  }
  check_finite(q.allFinite(), "q", [] { return "q"; });
  for (int c = 0; c < n; ++c) {
    check_nonnegative(mu[c], "mu", [&] { return contact_label(c) + "friction"; });
    for (const BlockSparseMatrix3::Entry& e : W.row(c)) {
      check_finite(e.block.allFinite(), "W", [&] { return contact_label(c) + "a block of W"; });
    }
    const Eigen::Matrix3d* diagonal = W.find(c, c);
    if (diagonal == nullptr || !((*diagonal)(0, 0) > 0.0)) {
      throw InvalidArgument("W", contact_label(c) + "diagonal block missing or W_nn <= 0");
    }
  }
}

namespace {

class ReducedOperator final : public ContactOperator {
 public:
  explicit ReducedOperator(const ReducedProblem& problem)
      : problem_(problem),
        impulses_(problem.contact_count(), Eigen::Vector3d::Zero()),
        norm_q_(problem.q.norm()) {
    problem.validate();
    const int n = problem.contact_count();
    diagonal_.reserve(n);
    for (int c = 0; c < n; ++c) diagonal_.emplace_back(*problem.W.find(c, c));
  }
  int contact_count() const override { return problem_.contact_count(); }
  const LocalDelassus& delassus_block(int c) const override { return diagonal_[c]; }
  double friction_coefficient(int c) const override { return problem_.mu[c]; }
  Eigen::Vector3d velocity(int c) const override {
    Eigen::Vector3d u = problem_.q.segment<3>(3 * c);
    for (const BlockSparseMatrix3::Entry& e : problem_.W.row(c)) {
      u.noalias() += e.block * impulses_[e.column];
    }
    return u;
  }
  void add_impulse(int c, const Eigen::Vector3d& delta) override { impulses_[c] += delta; }
  double free_velocity_norm() const override { return norm_q_; }
  const BlockSparseMatrix3& delassus_matrix() override { return problem_.W; }

 private:
  const ReducedProblem& problem_;
  std::vector<LocalDelassus> diagonal_;
  std::vector<Eigen::Vector3d> impulses_;
  double norm_q_;
};

}  // namespace

ContactSolution solve_reduced(const ReducedProblem& problem, const SolverSettings& settings,
                              const std::vector<Eigen::Vector3d>& warm_start) {
  ReducedOperator op(problem);
  return solve_frictional_contact(op, settings, warm_start);
}

double siconos_error(const ReducedProblem& problem, const std::vector<Eigen::Vector3d>& r) {
  ReducedOperator op(problem);
  if (static_cast<int>(r.size()) != op.contact_count()) {
    throw InvalidArgument("r", "impulse count does not match the problem");
  }
  for (int c = 0; c < op.contact_count(); ++c) op.add_impulse(c, r[c]);
  return siconos_error(op, r);
}

ReducedProblem assemble_reduced(const NscdStep& step) {
  BodyContactOperator op(step);  // validates, gives q and W
  const int n = op.contact_count();
  ReducedProblem problem;
  problem.W = op.delassus_matrix();
  problem.q.resize(3 * n);
  problem.mu.resize(n);
  for (int c = 0; c < n; ++c) {
    problem.q.segment<3>(3 * c) = op.velocity(c);
    problem.mu[c] = step.contacts[c].friction;
  }
  return problem;
}

}  // namespace wiregrain
