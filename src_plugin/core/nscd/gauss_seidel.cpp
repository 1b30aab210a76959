// The Gauss–Seidel contact solver (gauss_seidel.h).
#include "core/nscd/gauss_seidel.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <random>
#include <string>
#include <type_traits>

#include "core/common/errors.h"
#include "core/nscd/body_operator.h"
#include "core/nscd/contact_colouring.h"
#include "core/nscd/distributed_stick_solve.h"
#include "core/nscd/input_checks.h"
#include "core/nscd/subspace_correction.h"

namespace wiregrain {

namespace {

// One Gauss–Seidel sweep over the contacts in `order` (reversed when `backward`): each
// contact's local problem solved exactly with the others' impulses fixed, its increment
// applied at once (relaxed by settings.relaxation). Returns Σ|Δr|²; counts the contacts'
// states; `changed` is set when an impulse changed. A template so that the calls on the
// body operator are inlined (GaussSeidelSolve instantiates it for BodyContactOperator and
// for ContactOperator).
template <class Operator>
double sweep_contacts(Operator& op, const std::vector<int>& order, bool backward, int iteration,
                      const SolverSettings& settings, std::vector<int>& frozen_until,
                      ContactSolution& result, int counts[3], bool& changed, double& couple_increment_squared) {
  const int n = static_cast<int>(order.size());
  const double omega = settings.relaxation;
  NscdReport& report = result.report;
  double increment_squared = 0.0;
  // a contact's rolling couple for its normal impulse r_n (core/nscd/body_operator.h,
  // "Rolling resistance"; bodies only)
  const auto update_couple = [&](int c, double r_n) {
    if constexpr (std::is_same_v<Operator, BodyContactOperator>) {
      if (result.couples.empty() || op.rolling_bound(c) == 0.0) return;
      Eigen::Vector2d& m = result.couples[c];
      const Eigen::Vector2d delta = op.solve_couple(c, r_n, m) - m;
      if (delta.isZero(0.0)) return;
      op.add_couple(c, delta);
      m += delta;
      couple_increment_squared += delta.squaredNorm();
      changed = true;
    } else {
      (void)c;
      (void)r_n;
    }
  };
  for (int k = 0; k < n; ++k) {
    const int c = backward ? order[n - 1 - k] : order[k];
    if (!frozen_until.empty() && frozen_until[c] > iteration) {
      ++report.frozen_updates;
      ++counts[static_cast<int>(result.states[c])];
      continue;
    }
    Eigen::Vector3d& r = result.impulses[c];
    // A contact without impulse whose u_n ≥ 0 stays open: its local solution is r = 0
    // (solve_coulomb_local's first case, q_n = u_n − (W 0)_n = u_n), nothing changes; u_n
    // alone costs a third of u (on a settled pile most detected contacts are open).
    if (r.isZero(0.0) && op.normal_velocity(c) >= 0.0) {
      update_couple(c, 0.0);  // an open contact carries no couple
      if (!frozen_until.empty()) frozen_until[c] = iteration + 1 + settings.freeze;
      result.states[c] = ContactState::open;
      ++counts[static_cast<int>(ContactState::open)];
      continue;
    }
    const LocalDelassus& W = op.delassus_block(c);
    const Eigen::Vector3d q_local = op.velocity(c) - W.matrix() * r;
    const LocalSolution local = solve_coulomb_local(W, q_local, op.friction_coefficient(c), r);
    report.newton_iterations += local.newton_iterations;
    if (local.slide_method == SlideMethod::scan) {
      ++report.slide_fallbacks;
    }
    const Eigen::Vector3d updated =
        omega == 1.0 ? local.impulse : Eigen::Vector3d(omega * local.impulse + (1.0 - omega) * r);
    const Eigen::Vector3d delta = updated - r;
    if (!delta.isZero(0.0)) {
      op.add_impulse(c, delta);
      r = updated;
      increment_squared += delta.squaredNorm();
      changed = true;
    }
    update_couple(c, r[0]);
    if (!frozen_until.empty() && delta.squaredNorm() <= settings.tolerance * settings.tolerance * r.squaredNorm())
      frozen_until[c] = iteration + 1 + settings.freeze;
    result.states[c] = local.state;
    ++counts[static_cast<int>(local.state)];
  }
  return increment_squared;
}

// One call of solve_frictional_contact: the operator, the impulses and couples found so
// far, and the bookkeeping of the stopping test and of the stick solves.
class GaussSeidelSolve {
 public:
  GaussSeidelSolve(ContactOperator& op, const SolverSettings& settings, StickSolveBackoff* backoff,
                   WorkerExchange* exchange);
  ContactSolution run(const std::vector<Eigen::Vector3d>& warm_start,
                      const std::vector<Eigen::Vector2d>& couple_warm_start);

 private:
  void apply_warm_start(const std::vector<Eigen::Vector3d>& warm_start);
  void apply_couple_warm_start(const std::vector<Eigen::Vector2d>& couple_warm_start);
  // order coloured: order_ colour by colour (contact_colouring.h)
  void colour_order();
  // a sweep in this iteration's order; its Σ|Δr|² and the couples' Σ|Δm|²
  double sweep(int iteration, double& couple_increment_squared);
  // the stopping measure after a sweep (gauss_seidel.h, "Stopping")
  bool converged(int iteration);
  // the couples' law too (core/nscd/body_operator.h, "Rolling resistance")
  bool couples_converged(double couple_increment_squared, double norm_r);
  // method subspace: the closing stick solve of a converged solve, and the scheduled one
  // after a sweep (true: it ended the solve)
  void closing_stick_solve();
  bool scheduled_stick_solve(int iteration);
  // The Siconos error of the current impulses, computed once: a sweep that changes an
  // impulse and a stick solve that is not kept forget it (a dropped solve subtracts its
  // increments again, which need not restore the impulses to the last bit).
  double error_now();
  // one stick solve, counted in the report; returns the error before it
  double try_stick_solve(StickSolveOutcome& outcome);
  StickSolveOutcome distributed_stick_solve_step(double error_before);

  ContactOperator& op_;
  const SolverSettings& settings_;
  StickSolveBackoff* backoff_;
  const int n_;
  ContactSolution result_;
  std::vector<int> order_;
  std::vector<int> frozen_until_;  // skipped in sweeps before this (freeze)
  std::mt19937_64 generator_;
  BodyContactOperator* const body_op_;
  const bool rolling_;
  // a distributed step (nscd_step.h, NscdStep::touching_copies): the workers' exchange
  // and ‖q‖ over all of them
  WorkerExchange* const exchange_;
  double free_velocity_norm_ = 0.0;
  int check_interval_ = 1, next_error_check_ = 0;  // the Siconos error's checks
  // method subspace: whether the backoff allows any in this solve, and their schedule
  bool stick_solves_ = false;
  StickSolveSchedule schedule_;
  bool stick_solve_harmed_ = false;
  double known_error_ = 0.0;
  bool error_known_ = false;
};

GaussSeidelSolve::GaussSeidelSolve(ContactOperator& op, const SolverSettings& settings, StickSolveBackoff* backoff,
                                   WorkerExchange* exchange)
    : op_(op),
      settings_(settings),
      backoff_(backoff),
      n_(op.contact_count()),
      order_(n_),
      frozen_until_(settings.freeze > 0 ? n_ : 0, 0),
      generator_(settings.seed),
      body_op_(dynamic_cast<BodyContactOperator*>(&op)),
      rolling_(body_op_ != nullptr && body_op_->has_rolling()),
      exchange_(exchange),
      schedule_(settings.max_iterations) {
  if (exchange_ != nullptr && (body_op_ == nullptr || !body_op_->distributed()))
    throw InvalidArgument("exchange", "a distributed solve needs the body operator of a distributed step");
  if (exchange_ != nullptr && rolling_)
    throw InvalidArgument("exchange", "rolling resistance is not solved distributed");
  free_velocity_norm_ = exchange_ != nullptr ? body_op_->free_velocity_norm_over_workers(*exchange_) : op.free_velocity_norm();
  result_.impulses.assign(n_, Eigen::Vector3d::Zero());
  result_.states.assign(n_, ContactState::open);
  for (int c = 0; c < n_; ++c) order_[c] = c;
  if (settings.order == SweepOrder::coloured) colour_order();
  if (rolling_) result_.couples.assign(n_, Eigen::Vector2d::Zero());
  // (no stick solves with rolling resistance: they would leave the couples one update
  // behind, core/nscd/subspace_correction.h)
  stick_solves_ = settings.method == SolverMethod::subspace && !rolling_;
}

void GaussSeidelSolve::apply_warm_start(const std::vector<Eigen::Vector3d>& warm_start) {
  if (warm_start.empty()) return;
  if (static_cast<int>(warm_start.size()) != n_) {
    throw InvalidArgument("warm_start", "warm start has " + std::to_string(warm_start.size()) +
                                            " impulses for " + std::to_string(n_) +
                                            " contacts");
  }
  for (int c = 0; c < n_; ++c) {
    check_finite(warm_start[c].allFinite(), "warm_start", [&] { return contact_label(c) + "impulse"; });
    if (!warm_start[c].isZero(0.0)) {
      result_.impulses[c] = warm_start[c];
      op_.add_impulse(c, warm_start[c]);
    }
  }
}

void GaussSeidelSolve::apply_couple_warm_start(const std::vector<Eigen::Vector2d>& couple_warm_start) {
  if (couple_warm_start.empty()) return;
  if (static_cast<int>(couple_warm_start.size()) != n_) {
    throw InvalidArgument("warm_start", "couple warm start has " + std::to_string(couple_warm_start.size()) +
                                            " couples for " + std::to_string(n_) + " contacts");
  }
  for (int c = 0; c < n_ && rolling_; ++c) {
    check_finite(couple_warm_start[c].allFinite(), "warm_start", [&] { return contact_label(c) + "couple"; });
    if (couple_warm_start[c].isZero(0.0) || body_op_->rolling_bound(c) == 0.0) continue;
    result_.couples[c] = couple_warm_start[c];
    body_op_->add_couple(c, couple_warm_start[c]);
  }
}

void GaussSeidelSolve::colour_order() {
  if (body_op_ == nullptr)
    throw InvalidArgument("order", "order coloured needs the step's bodies (solve_nscd_step), not an assembled problem");
  std::vector<std::pair<int, int>> bodies(n_);
  for (int c = 0; c < n_; ++c) bodies[c] = body_op_->moving_bodies(c);
  const ContactColouring colouring = colour_contacts(bodies, body_op_->body_count());
  order_ = colouring.order;
  result_.report.colours = colouring.colours;
}

double GaussSeidelSolve::sweep(int iteration, double& couple_increment_squared) {
  if (settings_.order == SweepOrder::random) {
    // Fisher–Yates with our own index draw, so the sequence does not depend on the
    // standard library's distributions.
    for (int i = n_ - 1; i > 0; --i) {
      std::swap(order_[i], order_[static_cast<int>(generator_() % static_cast<std::uint64_t>(i + 1))]);
    }
  }
  const bool backward = settings_.order == SweepOrder::alternating && iteration % 2 == 0;

  int counts[3] = {0, 0, 0};
  bool changed = false;
  couple_increment_squared = 0.0;
  const double increment_squared =
      body_op_ != nullptr
          ? sweep_contacts(*body_op_, order_, backward, iteration, settings_, frozen_until_, result_, counts, changed,
                           couple_increment_squared)
          : sweep_contacts(op_, order_, backward, iteration, settings_, frozen_until_, result_, counts, changed,
                           couple_increment_squared);
  if (exchange_ != nullptr) body_op_->synchronize(*exchange_);
  // distributed: another worker's impulses may have changed (every worker computes the
  // error at the same sweeps)
  if (changed || exchange_ != nullptr) error_known_ = false;
  NscdReport& report = result_.report;
  report.open = counts[0];
  report.stick = counts[1];
  report.slide = counts[2];
  report.iterations = iteration;
  return increment_squared;
}

bool GaussSeidelSolve::converged(int iteration) {
  NscdReport& report = result_.report;
  bool converged = false;
  switch (settings_.measure) {
    case ConvergenceMeasure::increment:
      report.residual = report.increment;
      converged = report.residual <= settings_.tolerance;
      break;
    case ConvergenceMeasure::natural_map:
      // The error pass costs half a sweep; it is made after sweeps 1, 2, …, 20 and then
      // at intervals of at most a twentieth of the sweeps done (header).
      if (iteration >= next_error_check_) {
        report.residual = error_now();
        converged = report.residual <= settings_.tolerance;
        if (!converged) {
          check_interval_ = std::min(2 * check_interval_, 1 + iteration / 20);
          next_error_check_ = iteration + check_interval_;
        }
      }
      break;
    case ConvergenceMeasure::increment_then_natural_map:
      // The Siconos error is computed once the increment is below the tolerance, then
      // (while it stays above) at intervals that double after each failed check, capped
      // at a twentieth of the sweeps done: at most ~5 % extra sweeps and a logarithmic
      // number of error evaluations. (Siconos instead tightens the increment tolerance
      // by increment/error; on 15 warm-started steps of a 20-cube column both took the
      // same number of sweeps within 4 %; this rule does not depend on how the
      // increment relates to the error.)
      report.residual = report.increment;
      if (report.increment <= settings_.tolerance && iteration >= next_error_check_) {
        const double error = error_now();
        report.residual = error;
        if (error <= settings_.tolerance) {
          converged = true;
        } else {
          check_interval_ = std::min(2 * check_interval_, 1 + iteration / 20);
          next_error_check_ = iteration + check_interval_;
        }
      }
      break;
  }
  return converged;
}

bool GaussSeidelSolve::couples_converged(double couple_increment_squared, double norm_r) {
  if (settings_.measure == ConvergenceMeasure::increment) {
    double bounds_squared = 0.0;
    for (int c = 0; c < n_; ++c) bounds_squared += std::pow(body_op_->rolling_bound(c) * result_.impulses[c][0], 2);
    return couple_increment_squared <= settings_.tolerance * settings_.tolerance * bounds_squared;
  }
  // normalised as the Siconos error, less ‖u‖ (not at hand here): max(‖q‖, ‖r‖)
  return body_op_->rolling_residual(result_.couples, result_.impulses) <=
         settings_.tolerance * std::max(free_velocity_norm_, norm_r);
}

double GaussSeidelSolve::error_now() {
  if (!error_known_ && exchange_ != nullptr) {
    SiconosErrorSums sums = siconos_error_sums(op_, result_.impulses);
    double parts[3] = {sums.residual_squared, sums.impulses_squared, sums.velocities_squared};
    exchange_->sum_over_workers(parts, 3);
    known_error_ = siconos_error(SiconosErrorSums{parts[0], parts[1], parts[2]}, free_velocity_norm_);
  } else if (!error_known_) {
    known_error_ = siconos_error(op_, result_.impulses);
  }
  error_known_ = true;
  return known_error_;
}

double GaussSeidelSolve::try_stick_solve(StickSolveOutcome& outcome) {
  NscdReport& report = result_.report;
  const double error_before = error_now();
  ++report.subspace_solves;
  if (exchange_ != nullptr) {
    outcome = distributed_stick_solve_step(error_before);
    stick_solve_harmed_ |= outcome == StickSolveOutcome::harmful;
    if (outcome == StickSolveOutcome::kept) ++report.subspace_accepted;
    return error_before;
  }
  double error_after = 0.0;
  outcome = subspace_correction(op_, result_.impulses, result_.states, settings_, error_before, error_after, report);
  error_known_ = outcome == StickSolveOutcome::kept;
  known_error_ = error_after;
  stick_solve_harmed_ |= outcome == StickSolveOutcome::harmful;
  if (outcome == StickSolveOutcome::kept) ++report.subspace_accepted;
  return error_before;
}

// The distributed stick solve (core/nscd/distributed_stick_solve.h): its candidate applied
// on every worker, kept when it halves the Siconos error over all of them, else taken
// back (as subspace_correction does on one worker).
StickSolveOutcome GaussSeidelSolve::distributed_stick_solve_step(double error_before) {
  const DistributedStickSolve solve =
      distributed_stick_solve(*body_op_, result_.impulses, result_.states, settings_, free_velocity_norm_, *exchange_);
  result_.report.subspace_factorizations += solve.iterations;  // (CG iterations stand for the factorisations)
  if (!solve.any_closed) return StickSolveOutcome::harmless;
  std::vector<Eigen::Vector3d> delta(n_);
  for (int c = 0; c < n_; ++c) {
    delta[c] = solve.candidate[c] - result_.impulses[c];
    if (delta[c].isZero(0.0)) continue;
    op_.add_impulse(c, delta[c]);
    result_.impulses[c] = solve.candidate[c];
  }
  body_op_->synchronize(*exchange_);
  error_known_ = false;
  const double error_after = error_now();
  if (error_after < 0.5 * error_before) return StickSolveOutcome::kept;
  for (int c = 0; c < n_; ++c) {
    if (delta[c].isZero(0.0)) continue;
    op_.add_impulse(c, -delta[c]);
    result_.impulses[c] -= delta[c];
  }
  body_op_->synchronize(*exchange_);
  error_known_ = false;
  return error_after > 2.0 * error_before ? StickSolveOutcome::harmful : StickSolveOutcome::harmless;
}

// converged without a kept stick solve: one more (core/nscd/subspace_correction.h), which
// makes a resting stack exact every step instead of merely within the tolerance
void GaussSeidelSolve::closing_stick_solve() {
  NscdReport& report = result_.report;
  if (!(stick_solves_ && report.subspace_accepted == 0 &&
        (settings_.subspace_closing == 0.0 || error_now() > settings_.subspace_closing * settings_.tolerance)))
    return;
  StickSolveOutcome outcome;
  try_stick_solve(outcome);
  if (outcome == StickSolveOutcome::kept) report.residual = error_now();
}

bool GaussSeidelSolve::scheduled_stick_solve(int iteration) {
  if (!(stick_solves_ && schedule_.due(iteration))) return false;
  StickSolveOutcome outcome;
  const double error_before = try_stick_solve(outcome);
  if (outcome == StickSolveOutcome::kept) {
    const double error = error_now();
    if (settings_.measure != ConvergenceMeasure::increment && error <= settings_.tolerance) {
      result_.report.residual = error;
      return true;
    }
    schedule_.kept(iteration, error_before, error);
  } else {
    schedule_.dropped(iteration);
  }
  return false;
}

ContactSolution GaussSeidelSolve::run(const std::vector<Eigen::Vector3d>& warm_start,
                                      const std::vector<Eigen::Vector2d>& couple_warm_start) {
  apply_warm_start(warm_start);
  apply_couple_warm_start(couple_warm_start);
  if (exchange_ != nullptr) body_op_->synchronize(*exchange_);  // the warm starts of every worker
  if (stick_solves_ && backoff_ != nullptr && backoff_->skip > 0) {
    --backoff_->skip;
    stick_solves_ = false;
  }
  NscdReport& report = result_.report;
  for (int iteration = 1; iteration <= settings_.max_iterations; ++iteration) {
    double couple_increment_squared = 0.0;
    double increment_squared = sweep(iteration, couple_increment_squared);
    double norm_r_squared = 0.0;
    for (const Eigen::Vector3d& r : result_.impulses) norm_r_squared += r.squaredNorm();
    if (exchange_ != nullptr) {
      double sums[2] = {increment_squared, norm_r_squared};
      exchange_->sum_over_workers(sums, 2);
      increment_squared = sums[0];
      norm_r_squared = sums[1];
    }
    const double norm_r = std::sqrt(norm_r_squared);
    report.increment = std::sqrt(increment_squared);
    if (norm_r > DBL_EPSILON) report.increment /= norm_r;

    bool done = converged(iteration);
    if (done && rolling_) done = couples_converged(couple_increment_squared, norm_r);
    if (done) closing_stick_solve();
    if (done) break;
    if (scheduled_stick_solve(iteration)) break;
    if (iteration == settings_.max_iterations) report.hit_iteration_cap = true;
  }
  if (stick_solves_ && backoff_ != nullptr) update_backoff(*backoff_, report.subspace_accepted > 0, stick_solve_harmed_);
  report.siconos_error = error_now();
  return result_;
}

}  // namespace

ContactSolution solve_frictional_contact(ContactOperator& op, const SolverSettings& settings,
                                         const std::vector<Eigen::Vector3d>& warm_start,
                                         StickSolveBackoff* backoff,
                                         const std::vector<Eigen::Vector2d>& couple_warm_start,
                                         WorkerExchange* exchange) {
  settings.validate();
  return GaussSeidelSolve(op, settings, backoff, exchange).run(warm_start, couple_warm_start);
}

}  // namespace wiregrain
