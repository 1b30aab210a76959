// NSCD Gauss–Seidel solver; the formulation is in core/nscd_solver.h.
#include "core/nscd/nscd_solver.h"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <random>
#include <string>
#include <type_traits>

#include "core/common/errors.h"
#include "core/common/validation.h"

namespace wiregrain {

namespace {

std::string contact_label(int c) { return "contact " + std::to_string(c) + ": "; }

// The checks run for every body and contact of every step: `what()` (the subject of the
// message) is built only when a check fails.
template <class What>
void check_finite(bool finite, const char* argument, const What& what) {
  if (!finite) throw InvalidArgument(argument, std::string(what()) + " has a non-finite entry");
}

// "<what> must be a finite number >= 0, got <value>" under the keyword `argument`.
template <class What>
void check_nonnegative(double value, const char* argument, const What& what) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw InvalidArgument(argument, std::string(what()) + " must be a finite number >= 0, got " +
                                        format_number(value));
  }
}

}  // namespace

void NscdOptions::validate() const {
  require_nonnegative("tolerance", tolerance);
  if (max_iterations < 1) {
    throw InvalidArgument("max_iterations", "max_iterations must be >= 1, got " +
                                                std::to_string(max_iterations));
  }
  if (!(relaxation > 0.0 && relaxation < 2.0)) {
    throw InvalidArgument("relaxation", "relaxation must be in (0, 2), got " +
                                            format_number(relaxation));
  }
  if (!(theta >= 0.5 && theta <= 1.0)) {
    throw InvalidArgument("theta", "theta must be in [0.5, 1], got " + format_number(theta));
  }
  if (!(restitution >= 0.0 && restitution <= 1.0)) {
    throw InvalidArgument("restitution", "restitution must be in [0, 1], got " +
                                             format_number(restitution));
  }
  if (!(overlap_speed >= 0.0)) {
    throw InvalidArgument("overlap_speed", "overlap_speed must be >= 0, got " + format_number(overlap_speed));
  }
  if (!(subspace_regularization > 0.0 && subspace_regularization < 1.0)) {
    throw InvalidArgument("subspace_regularization", "subspace_regularization must be in (0, 1), got " +
                                                         format_number(subspace_regularization));
  }
  if (!(subspace_closing >= 0.0 && subspace_closing <= 1.0)) {
    throw InvalidArgument("subspace_closing", "subspace_closing must be in [0, 1], got " + format_number(subspace_closing));
  }
  if (freeze < 0) throw InvalidArgument("freeze", "freeze must be >= 0 sweeps, got " + std::to_string(freeze));
  if (freeze > 0 && measure == ConvergenceMeasure::increment) {
    throw InvalidArgument("freeze", "freeze needs a measure with the Siconos error (natural_map or "
                                    "increment_then_natural_map): the increment does not see frozen contacts");
  }
  if (!(overlap_recovery >= 0.0 && overlap_recovery <= 1.0)) {
    throw InvalidArgument("overlap_recovery", "overlap_recovery must be in [0, 1], got " +
                                                  format_number(overlap_recovery));
  }
}

// ---------------------------------------------------------------------------------------
// The Gauss–Seidel sweep.

double siconos_error(const ContactOperator& op, const std::vector<Eigen::Vector3d>& impulses) {
  double sum = 0.0, norm_r_squared = 0.0, norm_u_squared = 0.0;
  for (int c = 0; c < op.contact_count(); ++c) {
    const Eigen::Vector3d u = op.velocity(c);
    // an open contact (r = 0, u_n ≥ 0) has residual 0 exactly: r − u♯ = −(u_n + μ|u_t|, u_t)
    // lies in the polar cone, whose projection on K_μ is 0 (most points of a pile are open)
    if (!(impulses[c].isZero(0.0) && u[0] >= 0.0))
      sum += natural_map_residual(impulses[c], u, op.friction_coefficient(c)).squaredNorm();
    norm_r_squared += impulses[c].squaredNorm();
    norm_u_squared += u.squaredNorm();
  }
  const double scale = std::max(
      {op.free_velocity_norm(), std::sqrt(norm_r_squared), std::sqrt(norm_u_squared)});
  const double error = std::sqrt(sum);
  return scale > DBL_EPSILON ? error / scale : error;
}

namespace {

// What one subspace correction did: kept (halved the Siconos error), dropped as
// harmless (the error neither halved nor doubled: a stack already exact to round-off),
// or dropped as harmful (the error more than doubled: a pile where contacts slide).
enum class StickSolveOutcome { kept, harmless, harmful };

// One subspace correction (header): solve the closed contacts together, keep the result
// if it halves the Siconos error `error_before`; error_after: the Siconos error of the
// impulses it leaves when kept.
StickSolveOutcome subspace_correction(ContactOperator& op, std::vector<Eigen::Vector3d>& impulses,
                                      const std::vector<ContactState>& states, const NscdOptions& options,
                                      double error_before, double& error_after, NscdReport& report) {
  const double regularization = options.subspace_regularization;
  const int n = op.contact_count();
  // Unknowns: the three components of each closed contact, only the normal one of a
  // frictionless contact (its tangential impulse is 0 and stays so).
  std::vector<int> unknown(3 * n, -1), components;
  // closing or touching (u_n ≤ 0 up to rounding): e.g. the interfaces of a stack falling
  // as one body in the first sweeps, which Gauss–Seidel loads one interface per sweep
  const double closing = 1e-12 * op.free_velocity_norm();
  for (int c = 0; c < n; ++c) {
    const bool loaded = states[c] != ContactState::open && impulses[c][0] > 0.0;
    if (!loaded && op.velocity(c)[0] > closing) continue;
    const int count = op.friction_coefficient(c) == 0.0 ? 1 : 3;
    for (int a = 0; a < count; ++a) {
      unknown[3 * c + a] = static_cast<int>(components.size());
      components.push_back(3 * c + a);
    }
  }
  if (components.empty()) return StickSolveOutcome::harmless;
  const BlockSparseMatrix3& W = op.delassus_matrix();
  const int m = static_cast<int>(components.size());
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < m; ++i) {
    const int c = components[i] / 3, a = components[i] % 3;
    for (const BlockSparseMatrix3::Entry& e : W.row(c)) {
      for (int b = 0; b < 3; ++b) {
        const int j = unknown[3 * e.column + b];
        if (j >= 0) entries.emplace_back(i, j, e.block(a, b));
      }
    }
  }
  Eigen::SparseMatrix<double> A(m, m);
  A.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseMatrix<double> regularized = A;
  for (int k = 0; k < m; ++k) regularized.coeffRef(k, k) *= 1.0 + regularization;
  regularized.makeCompressed();
  // The fill-reducing ordering (AMD) costs ~20 times the numerical factorisation; it is
  // kept from the last solve of this thread while the pattern of W_SS is unchanged (a
  // resting stack or pile: the same contacts step after step), and the factorisation too
  // while its values are the same to the bit (a pile at rest: the same poses; the same
  // factors as a new factorisation would give, so the results do not change). Kept
  // factors of a W_SS that changed are not kept, even refined on the current one: a
  // coupled column at rest changes W_SS by 5e-8 of its largest entry per step, and
  // factors 1e-6 or 1e-4 old make some stick solves harmful (the near-null directions
  // that ε holds move).
  struct FactorCache {
    std::vector<int> outer, inner;
    std::vector<double> values;  // of the matrix last factorised (empty: none usable)
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor;
  };
  thread_local FactorCache cache;
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
    if (factor.info() != Eigen::Success) return StickSolveOutcome::harmful;
    cache.values.assign(values, values + regularized.nonZeros());
  }
  Eigen::VectorXd rhs(m);
  Eigen::VectorXd current(m);
  for (int i = 0; i < m; ++i) {
    current[i] = impulses[components[i] / 3][components[i] % 3];
    rhs[i] = -op.velocity(components[i] / 3)[components[i] % 3];
  }
  // the increment closest to the current impulses: (W_SS + ε D) Δr_S = −u_S (header)
  Eigen::VectorXd increment = factor.solve(rhs);
  for (int refinement = 0; refinement < 2; ++refinement) increment += factor.solve(rhs - A * increment);
  if (!increment.allFinite()) return StickSolveOutcome::harmful;
  const Eigen::VectorXd x = current + increment;

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

}  // namespace

// ---------------------------------------------------------------------------------------
// Bodies.

namespace {

// The operator of one time step on bodies: velocities of the bodies are the state,
// u_c = H_a V_a + H_b V_b + offset_c + s_c e_n.
class BodyContactOperator final : public ContactOperator {
 public:
  BodyContactOperator(const NscdStep& step, const NscdOptions& options) {
    const double h = step.time_step;
    require_positive("time_step", h);
    const int body_count = static_cast<int>(step.bodies.size());
    bodies_.resize(body_count);
    for (int b = 0; b < body_count; ++b) {
      const NscdBody& body = step.bodies[b];
      const auto label = [b](const char* what) { return "body " + std::to_string(b) + ": " + what; };
      check_nonnegative(body.inverse_mass, "bodies", [&] { return label("inverse mass"); });
      check_finite(body.inverse_inertia.allFinite(), "bodies", [&] { return label("inverse inertia"); });
      check_finite(body.velocity_begin.allFinite() && body.angular_velocity_begin.allFinite(),
                   "bodies", [&] { return label("start velocity"); });
      check_finite(body.velocity_free.allFinite() && body.angular_velocity_free.allFinite(),
                   "bodies", [&] { return label("free velocity"); });
      bodies_[b].velocity << body.velocity_free, body.angular_velocity_free;
      bodies_[b].inverse_mass = body.inverse_mass;
      bodies_[b].inverse_inertia = body.inverse_inertia;
    }

    const int n = static_cast<int>(step.contacts.size());
    links_.resize(n);
    start_normal_velocity_.resize(n);
    double norm_q_squared = 0.0;
    for (int c = 0; c < n; ++c) {
      const NscdContact& contact = step.contacts[c];
      const auto label = [c](const char* what) { return contact_label(c) + what; };
      for (int body : {contact.body_a, contact.body_b}) {
        if (body < -1 || body >= body_count) {
          throw InvalidArgument("contacts", label("body index ") + std::to_string(body) +
                                                " out of range [-1, " +
                                                std::to_string(body_count) + ")");
        }
      }
      if (contact.body_a == contact.body_b && contact.body_a >= 0) {
        throw InvalidArgument("contacts", label("both sides are body ") +
                                              std::to_string(contact.body_a));
      }
      check_nonnegative(contact.friction, "contacts", [&] { return label("friction"); });
      check_nonnegative(contact.rolling_friction, "contacts", [&] { return label("rolling friction"); });
      check_nonnegative(contact.rolling_radius, "contacts", [&] { return label("rolling radius"); });
      if (contact.rolling_friction > 0.0 && !(contact.rolling_radius > 0.0)) {
        throw InvalidArgument("contacts", label("rolling friction ") + format_number(contact.rolling_friction) +
                                              " needs a rolling radius > 0");
      }
      check_finite(contact.rolling_axis.allFinite(), "contacts", [&] { return label("rolling axis"); });
      check_finite(std::isfinite(contact.gap), "contacts", [&] { return label("gap"); });
      check_finite(contact.jacobian_a.allFinite() && contact.jacobian_b.allFinite(), "contacts",
                   [&] { return label("Jacobian"); });
      check_finite(contact.velocity_offset.allFinite(), "contacts", [&] { return label("velocity offset"); });

      Link& link = links_[c];
      link.body_a = contact.body_a;
      link.body_b = contact.body_b;
      link.jacobian_a = contact.jacobian_a;
      link.jacobian_b = contact.jacobian_b;
      link.mu = contact.friction;
      link.rolling = contact.rolling_friction * contact.rolling_radius;
      link.rolling_radius = contact.rolling_radius;
      Eigen::Matrix3d W = Eigen::Matrix3d::Zero();
      Eigen::Vector3d u_begin = contact.velocity_offset;
      if (link.body_a >= 0) {
        W += contact.jacobian_a * response(link.body_a, contact.jacobian_a);
        const NscdBody& body = step.bodies[link.body_a];
        u_begin += contact.jacobian_a.leftCols<3>() * body.velocity_begin +
                   contact.jacobian_a.rightCols<3>() * body.angular_velocity_begin;
      }
      if (link.body_b >= 0) {
        W += contact.jacobian_b * response(link.body_b, contact.jacobian_b);
        const NscdBody& body = step.bodies[link.body_b];
        u_begin += contact.jacobian_b.leftCols<3>() * body.velocity_begin +
                   contact.jacobian_b.rightCols<3>() * body.angular_velocity_begin;
      }
      if (!(W(0, 0) > 0.0)) {
        throw InvalidArgument("contacts", label("Delassus block has W_nn = ") +
                                              format_number(W(0, 0)) +
                                              " (both sides of infinite mass, or a zero normal row)");
      }
      link.delassus = LocalDelassus(W);
      // Contact-law shift of the normal velocity (header).
      const double theta = options.theta;
      const double g = contact.gap;
      const double un_begin = u_begin[0];
      start_normal_velocity_[c] = un_begin;
      // an overlap is removed by β of it per step, at most at the speed overlap_speed
      const double g_target =
          g < 0.0 ? std::max(options.overlap_recovery * g, -options.overlap_speed * h) : g;
      double shift = (g_target / h + (1.0 - theta) * un_begin) / theta;
      if (options.restitution > 0.0 && un_begin < 0.0 && g + h * un_begin <= 0.0) {
        shift = std::min(shift, options.restitution * un_begin);
      }
      link.constant = contact.velocity_offset;
      link.constant[0] += shift;
      const Eigen::Vector3d q = velocity(c);
      norm_q_squared += q.squaredNorm();
    }
    norm_q_ = std::sqrt(norm_q_squared);

    // rolling blocks (header, "Rolling resistance"), for every contact once any has one
    bool rolling = false;
    for (const NscdContact& contact : step.contacts) rolling |= contact.rolling_friction > 0.0;
    if (rolling) {
      rolling_.resize(n);
      for (int c = 0; c < n; ++c) {
        const Link& link = links_[c];
        RollingBlock& block = rolling_[c];
        // the frame's rows (n, t1, t2) from the Jacobian's linear part (± frameᵀ)
        const Eigen::Matrix3d frame_t =
            link.body_b >= 0 ? Eigen::Matrix3d(link.jacobian_b.leftCols<3>()) : Eigen::Matrix3d(-link.jacobian_a.leftCols<3>());
        block.tangents = frame_t.bottomRows<2>().transpose();
        Eigen::Matrix3d inverse_inertia = Eigen::Matrix3d::Zero();
        if (link.body_a >= 0) inverse_inertia += bodies_[link.body_a].inverse_inertia;
        if (link.body_b >= 0) inverse_inertia += bodies_[link.body_b].inverse_inertia;
        block.delassus = block.tangents.transpose() * inverse_inertia * block.tangents;
        const NscdContact& contact = step.contacts[c];
        if (!contact.rolling_axis.isZero(0.0)) {
          const Eigen::Vector2d axis = block.tangents.transpose() * contact.rolling_axis;
          if (!(axis.norm() > 0.5)) {
            throw InvalidArgument("contacts", contact_label(c) + "rolling axis is not a unit vector of the tangent plane");
          }
          block.axis = axis.normalized();
          block.one_axis = true;
        }
      }
    }
  }

  bool has_rolling() const { return !rolling_.empty(); }
  double rolling_bound(int c) const { return links_[c].rolling; }
  // The couple of contact c's rolling law (header) for normal impulse r_n, the other
  // impulses and couples as they are; `couple`: its present couple.
  Eigen::Vector2d solve_couple(int c, double r_n, const Eigen::Vector2d& couple) const {
    const double bound = links_[c].rolling * r_n;
    if (!(bound > 0.0)) return Eigen::Vector2d::Zero();
    const RollingBlock& block = rolling_[c];
    const Eigen::Vector2d w_free = rolling_velocity(c) - block.delassus * couple;
    if (block.one_axis) {  // m = m_e a: m_e = −aᵀ w_free / aᵀ W_r a, clamped to ± the bound
      const double stick = -block.axis.dot(w_free) / block.axis.dot(block.delassus * block.axis);
      return std::clamp(stick, -bound, bound) * block.axis;
    }
    const Eigen::Vector2d stick = -block.delassus.ldlt().solve(w_free);
    if (stick.norm() <= bound) return stick;
    // on the disc's edge: m(σ) = −(W_r + σ I)⁻¹ w_free with |m(σ)| = bound; Newton on
    // φ(σ) = 1/|m(σ)| − 1/bound, φ' = mᵀ (W_r + σ I)⁻¹ m / |m|³ (> 0), from σ = 0 where
    // φ < 0: the iterates increase to the root (φ is concave in σ)
    double sigma = 0.0;
    Eigen::Vector2d m = stick;
    for (int iteration = 0; iteration < 100; ++iteration) {
      const Eigen::Matrix2d shifted = block.delassus + sigma * Eigen::Matrix2d::Identity();
      m = -shifted.ldlt().solve(w_free);
      const double norm = m.norm();
      if (std::abs(norm - bound) <= 1e-14 * bound) break;
      const double slope = m.dot(shifted.ldlt().solve(m)) / (norm * norm * norm);
      sigma = std::max(0.0, sigma - (1.0 / norm - 1.0 / bound) / slope);
    }
    return bound / m.norm() * m;
  }
  // The rolling law's natural-map residual as the Siconos error's numerator has it for
  // Coulomb's law (header): the couple as the impulse m / R at the rolling radius, the
  // rolling velocity as the surface speed w R, and ρ = 1:
  //     sqrt(Σ_c |m_c / R_c − proj_{D_c}(m_c / R_c − w_c R_c)|²),
  // D_c the disc of radius μ_r r_n (a one-axis couple: the segment along its axis).
  double rolling_residual(const std::vector<Eigen::Vector2d>& couples, const std::vector<Eigen::Vector3d>& impulses) const {
    double residual_squared = 0.0;
    for (int c = 0; c < contact_count(); ++c) {
      const Link& link = links_[c];
      if (link.rolling == 0.0) continue;
      const RollingBlock& block = rolling_[c];
      const double bound = link.rolling / link.rolling_radius * impulses[c][0];
      const Eigen::Vector2d m = couples[c] / link.rolling_radius;
      const Eigen::Vector2d trial = m - link.rolling_radius * rolling_velocity(c);
      Eigen::Vector2d projected;
      if (block.one_axis) {
        projected = std::clamp(block.axis.dot(trial), -bound, bound) * block.axis;
      } else {
        projected = trial.norm() <= bound ? trial : Eigen::Vector2d(bound / trial.norm() * trial);
      }
      residual_squared += (m - projected).squaredNorm();
    }
    return std::sqrt(residual_squared);
  }
  // couple += delta: ω_b += I_b⁻¹ T delta, ω_a −= I_a⁻¹ T delta
  void add_couple(int c, const Eigen::Vector2d& delta) {
    const Link& link = links_[c];
    const Eigen::Vector3d world = rolling_[c].tangents * delta;
    if (link.body_a >= 0) bodies_[link.body_a].velocity.tail<3>() -= bodies_[link.body_a].inverse_inertia * world;
    if (link.body_b >= 0) bodies_[link.body_b].velocity.tail<3>() += bodies_[link.body_b].inverse_inertia * world;
  }

  int contact_count() const override { return static_cast<int>(links_.size()); }
  const LocalDelassus& delassus_block(int c) const override { return links_[c].delassus; }
  double friction_coefficient(int c) const override { return links_[c].mu; }
  // The sums in a tree, not one chain: the sweep waits for u of each contact (its bodies'
  // velocities were changed by the contact before).
  Eigen::Vector3d velocity(int c) const override {
    const Link& link = links_[c];
    Eigen::Vector3d side_a = Eigen::Vector3d::Zero(), side_b = Eigen::Vector3d::Zero();
    if (link.body_a >= 0) side_a = side_velocity(link.jacobian_a, bodies_[link.body_a].velocity);
    if (link.body_b >= 0) side_b = side_velocity(link.jacobian_b, bodies_[link.body_b].velocity);
    return link.constant + (side_a + side_b);
  }
  // The first row of velocity(c), summed in the same order (the same bits: checked against
  // velocity(c)[0] by the core test
  // NscdOperators.OpenContactTestReadsTheNormalVelocityToTheBit).
  double normal_velocity(int c) const override {
    const Link& link = links_[c];
    double side_a = 0.0, side_b = 0.0;
    if (link.body_a >= 0) side_a = side_normal_velocity(link.jacobian_a, bodies_[link.body_a].velocity);
    if (link.body_b >= 0) side_b = side_normal_velocity(link.jacobian_b, bodies_[link.body_b].velocity);
    return link.constant[0] + (side_a + side_b);
  }
  void add_impulse(int c, const Eigen::Vector3d& delta) override {
    const Link& link = links_[c];
    if (link.body_a >= 0) apply_impulse(bodies_[link.body_a], link.jacobian_a, delta);
    if (link.body_b >= 0) apply_impulse(bodies_[link.body_b], link.jacobian_b, delta);
  }
  double free_velocity_norm() const override { return norm_q_; }
  // W = H M⁻¹ Hᵀ: a block between every two contacts that share a body.
  const BlockSparseMatrix3& delassus_matrix() override {
    if (delassus_.block_count() == contact_count()) return delassus_;
    const int n = contact_count();
    delassus_ = BlockSparseMatrix3(n);
    // per body, the contacts touching it with that side's H and M⁻¹ Hᵀ
    struct Touch {
      int contact;
      ContactJacobian H;
      Eigen::Matrix<double, 6, 3> response;
    };
    std::vector<std::vector<Touch>> touches(bodies_.size());
    for (int c = 0; c < n; ++c) {
      const Link& link = links_[c];
      if (link.body_a >= 0) touches[link.body_a].push_back({c, link.jacobian_a, response(link.body_a, link.jacobian_a)});
      if (link.body_b >= 0) touches[link.body_b].push_back({c, link.jacobian_b, response(link.body_b, link.jacobian_b)});
    }
    for (const std::vector<Touch>& body : touches) {
      for (const Touch& row : body) {
        for (const Touch& column : body) delassus_.add(row.contact, column.contact, row.H * column.response);
      }
    }
    return delassus_;
  }

  const Vector6d& body_velocity(int b) const { return bodies_[b].velocity; }
  double start_normal_velocity(int c) const { return start_normal_velocity_[c]; }
  // Normal velocity without the shift s_c.
  double unshifted_normal_velocity(int c, const NscdStep& step) const {
    return velocity(c)[0] - links_[c].constant[0] + step.contacts[c].velocity_offset[0];
  }

 private:
  // 16 doubles: velocity and inverse mass of one body
  struct Body {
    Vector6d velocity;  // (v, ω), updated by every impulse
    double inverse_mass = 0.0;
    Eigen::Matrix3d inverse_inertia = Eigen::Matrix3d::Zero();
  };
  // H row by row: u_n reads one contiguous row (most contacts of a pile are open).
  using RowJacobian = Eigen::Matrix<double, 3, 6, Eigen::RowMajor>;
  // The sweep reads every link once per sweep: M⁻¹ Hᵀ is not stored but applied from the
  // bodies' M⁻¹ (the links of a 10 080-contact pile are 4.8 MB instead of 7.7 MB).
  struct Link {
    int body_a = -1, body_b = -1;
    double mu = 0.0;
    double rolling = 0.0;  // μ_r R
    double rolling_radius = 0.0;  // R
    Eigen::Vector3d constant;  // velocity offset + s e_n
    RowJacobian jacobian_a, jacobian_b;
    LocalDelassus delassus;
  };
  // M⁻¹ Hᵀ of one side
  Eigen::Matrix<double, 6, 3> response(int b, const ContactJacobian& H) const {
    Eigen::Matrix<double, 6, 3> M_inv_Ht;
    M_inv_Ht.topRows<3>() = bodies_[b].inverse_mass * H.leftCols<3>().transpose();
    M_inv_Ht.bottomRows<3>() = bodies_[b].inverse_inertia * H.rightCols<3>().transpose();
    return M_inv_Ht;
  }
  // V += M⁻¹ Hᵀ δ as (m⁻¹ H_vᵀ δ, I⁻¹ (H_ωᵀ δ))
  static void apply_impulse(Body& body, const RowJacobian& H, const Eigen::Vector3d& delta) {
    double linear[3], angular[3];
    for (int j = 0; j < 3; ++j) {
      linear[j] = H(0, j) * delta[0] + H(1, j) * delta[1] + H(2, j) * delta[2];
      angular[j] = H(0, 3 + j) * delta[0] + H(1, 3 + j) * delta[1] + H(2, 3 + j) * delta[2];
    }
    for (int j = 0; j < 3; ++j) {
      body.velocity[j] += body.inverse_mass * linear[j];
      body.velocity[3 + j] += body.inverse_inertia(j, 0) * angular[0] +
                              body.inverse_inertia(j, 1) * angular[1] +
                              body.inverse_inertia(j, 2) * angular[2];
    }
  }
  // H V = H_v v + H_ω ω, each row summed left to right (as side_normal_velocity)
  static Eigen::Vector3d side_velocity(const RowJacobian& H, const Vector6d& V) {
    Eigen::Vector3d u;
    for (int i = 0; i < 3; ++i) {
      const double linear = H(i, 0) * V[0] + H(i, 1) * V[1] + H(i, 2) * V[2];
      const double angular = H(i, 3) * V[3] + H(i, 4) * V[4] + H(i, 5) * V[5];
      u[i] = linear + angular;
    }
    return u;
  }
  static double side_normal_velocity(const RowJacobian& H, const Vector6d& V) {
    const double linear = H(0, 0) * V[0] + H(0, 1) * V[1] + H(0, 2) * V[2];
    const double angular = H(0, 3) * V[3] + H(0, 4) * V[4] + H(0, 5) * V[5];
    return linear + angular;
  }

  // w = Tᵀ (ω_b − ω_a)
  Eigen::Vector2d rolling_velocity(int c) const {
    const Link& link = links_[c];
    Eigen::Vector3d relative = Eigen::Vector3d::Zero();
    if (link.body_b >= 0) relative += bodies_[link.body_b].velocity.tail<3>();
    if (link.body_a >= 0) relative -= bodies_[link.body_a].velocity.tail<3>();
    return rolling_[c].tangents.transpose() * relative;
  }
  // a contact's rolling block: T = (t1 t2) in world axes and W_r = Tᵀ (I_a⁻¹ + I_b⁻¹) T
  struct RollingBlock {
    Eigen::Matrix<double, 3, 2> tangents;
    Eigen::Matrix2d delassus;
    bool one_axis = false;  // the couple only along `axis` (t1, t2 components, unit)
    Eigen::Vector2d axis = Eigen::Vector2d::Zero();
  };

  std::vector<Link> links_;
  std::vector<RollingBlock> rolling_;  // empty unless a contact has a rolling resistance
  std::vector<Body> bodies_;
  std::vector<double> start_normal_velocity_;
  double norm_q_ = 0.0;
  BlockSparseMatrix3 delassus_;  // assembled on demand
};

}  // namespace

namespace {

// One Gauss–Seidel sweep over the contacts in `order` (reversed when `backward`): each
// contact's local problem solved exactly with the others' impulses fixed, its increment
// applied at once (relaxed by options.relaxation). Returns Σ|Δr|²; counts the contacts'
// states; `changed` is set when an impulse changed. A template so that the calls on the
// body operator are inlined (solve_frictional_contact instantiates it for
// BodyContactOperator and for ContactOperator).
template <class Operator>
double sweep_contacts(Operator& op, const std::vector<int>& order, bool backward, int iteration,
                      const NscdOptions& options, std::vector<int>& frozen_until,
                      ContactSolution& result, int counts[3], bool& changed, double& couple_increment_squared) {
  const int n = static_cast<int>(order.size());
  const double omega = options.relaxation;
  NscdReport& report = result.report;
  double increment_squared = 0.0;
  // a contact's rolling couple for its normal impulse r_n (header, "Rolling resistance";
  // bodies only)
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
      if (!frozen_until.empty()) frozen_until[c] = iteration + 1 + options.freeze;
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
    if (!frozen_until.empty() && delta.squaredNorm() <= options.tolerance * options.tolerance * r.squaredNorm())
      frozen_until[c] = iteration + 1 + options.freeze;
    result.states[c] = local.state;
    ++counts[static_cast<int>(local.state)];
  }
  return increment_squared;
}

}  // namespace

ContactSolution solve_frictional_contact(ContactOperator& op, const NscdOptions& options,
                                         const std::vector<Eigen::Vector3d>& warm_start,
                                         StickSolveBackoff* backoff,
                                         const std::vector<Eigen::Vector2d>& couple_warm_start) {
  options.validate();
  const int n = op.contact_count();
  ContactSolution result;
  result.impulses.assign(n, Eigen::Vector3d::Zero());
  result.states.assign(n, ContactState::open);
  NscdReport& report = result.report;

  if (!warm_start.empty()) {
    if (static_cast<int>(warm_start.size()) != n) {
      throw InvalidArgument("warm_start", "warm start has " + std::to_string(warm_start.size()) +
                                              " impulses for " + std::to_string(n) +
                                              " contacts");
    }
    for (int c = 0; c < n; ++c) {
      check_finite(warm_start[c].allFinite(), "warm_start", [&] { return contact_label(c) + "impulse"; });
      if (!warm_start[c].isZero(0.0)) {
        result.impulses[c] = warm_start[c];
        op.add_impulse(c, warm_start[c]);
      }
    }
  }

  std::vector<int> order(n);
  for (int c = 0; c < n; ++c) order[c] = c;
  std::vector<int> frozen_until(options.freeze > 0 ? n : 0, 0);  // skipped in sweeps before this
  std::mt19937_64 generator(options.seed);
  BodyContactOperator* const body_op = dynamic_cast<BodyContactOperator*>(&op);
  const bool rolling = body_op != nullptr && body_op->has_rolling();
  if (rolling) result.couples.assign(n, Eigen::Vector2d::Zero());
  if (!couple_warm_start.empty()) {
    if (static_cast<int>(couple_warm_start.size()) != n) {
      throw InvalidArgument("warm_start", "couple warm start has " + std::to_string(couple_warm_start.size()) +
                                              " couples for " + std::to_string(n) + " contacts");
    }
    for (int c = 0; c < n && rolling; ++c) {
      check_finite(couple_warm_start[c].allFinite(), "warm_start", [&] { return contact_label(c) + "couple"; });
      if (couple_warm_start[c].isZero(0.0) || body_op->rolling_bound(c) == 0.0) continue;
      result.couples[c] = couple_warm_start[c];
      body_op->add_couple(c, couple_warm_start[c]);
    }
  }
  int check_interval = 1, next_error_check = 0;  // increment_then_natural_map
  // method subspace: schedule within this solve, and whether the backoff allows any
  int subspace_wait = 2, next_subspace = 2, subspace_dropped = 0;
  // (none with rolling resistance: they would leave the couples one update behind, header)
  bool stick_solves = options.method == SolverMethod::subspace && !rolling;
  if (stick_solves && backoff != nullptr && backoff->skip > 0) {
    --backoff->skip;
    stick_solves = false;
  }
  bool stick_solve_harmed = false;
  // The Siconos error of the current impulses, computed once: a sweep that changes an
  // impulse and a stick solve that is not kept forget it (a dropped solve subtracts its
  // increments again, which need not restore the impulses to the last bit).
  double known_error = 0.0;
  bool error_known = false;
  const auto error_now = [&]() {
    if (!error_known) known_error = siconos_error(op, result.impulses);
    error_known = true;
    return known_error;
  };
  // one stick solve (header), counted in the report; returns the error before it
  const auto try_stick_solve = [&](StickSolveOutcome& outcome) {
    const double error_before = error_now();
    ++report.subspace_solves;
    double error_after = 0.0;
    outcome = subspace_correction(op, result.impulses, result.states, options, error_before, error_after, report);
    error_known = outcome == StickSolveOutcome::kept;
    known_error = error_after;
    stick_solve_harmed |= outcome == StickSolveOutcome::harmful;
    if (outcome == StickSolveOutcome::kept) ++report.subspace_accepted;
    return error_before;
  };

  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    if (options.order == SweepOrder::random) {
      // Fisher–Yates with our own index draw, so the sequence does not depend on the
      // standard library's distributions.
      for (int i = n - 1; i > 0; --i) {
        std::swap(order[i], order[static_cast<int>(generator() % static_cast<std::uint64_t>(i + 1))]);
      }
    }
    const bool backward = options.order == SweepOrder::alternating && iteration % 2 == 0;

    int counts[3] = {0, 0, 0};
    bool changed = false;
    double couple_increment_squared = 0.0;
    const double increment_squared =
        body_op != nullptr
            ? sweep_contacts(*body_op, order, backward, iteration, options, frozen_until, result, counts, changed,
                             couple_increment_squared)
            : sweep_contacts(op, order, backward, iteration, options, frozen_until, result, counts, changed,
                             couple_increment_squared);
    if (changed) error_known = false;
    report.open = counts[0];
    report.stick = counts[1];
    report.slide = counts[2];
    report.iterations = iteration;

    double norm_r_squared = 0.0;
    for (const Eigen::Vector3d& r : result.impulses) norm_r_squared += r.squaredNorm();
    const double norm_r = std::sqrt(norm_r_squared);
    report.increment = std::sqrt(increment_squared);
    if (norm_r > DBL_EPSILON) report.increment /= norm_r;

    bool converged = false;
    switch (options.measure) {
      case ConvergenceMeasure::increment:
        report.residual = report.increment;
        converged = report.residual <= options.tolerance;
        break;
      case ConvergenceMeasure::natural_map:
        // The error pass costs half a sweep; it is made after sweeps 1, 2, …, 20 and then
        // at intervals of at most a twentieth of the sweeps done (header).
        if (iteration >= next_error_check) {
          report.residual = error_now();
          converged = report.residual <= options.tolerance;
          if (!converged) {
            check_interval = std::min(2 * check_interval, 1 + iteration / 20);
            next_error_check = iteration + check_interval;
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
        if (report.increment <= options.tolerance && iteration >= next_error_check) {
          const double error = error_now();
          report.residual = error;
          if (error <= options.tolerance) {
            converged = true;
          } else {
            check_interval = std::min(2 * check_interval, 1 + iteration / 20);
            next_error_check = iteration + check_interval;
          }
        }
        break;
    }
    // rolling resistance: the couples must satisfy their law too (header)
    if (converged && rolling) {
      if (options.measure == ConvergenceMeasure::increment) {
        double bounds_squared = 0.0;
        for (int c = 0; c < n; ++c) bounds_squared += std::pow(body_op->rolling_bound(c) * result.impulses[c][0], 2);
        converged = couple_increment_squared <= options.tolerance * options.tolerance * bounds_squared;
      } else {
        // normalised as the Siconos error, less ‖u‖ (not at hand here): max(‖q‖, ‖r‖)
        converged = body_op->rolling_residual(result.couples, result.impulses) <=
                    options.tolerance * std::max(op.free_velocity_norm(), norm_r);
      }
    }
    // method subspace, converged without a kept stick solve: one more (header), which
    // makes a resting stack exact every step instead of merely within the tolerance
    if (converged && stick_solves && report.subspace_accepted == 0 &&
        (options.subspace_closing == 0.0 || error_now() > options.subspace_closing * options.tolerance)) {
      StickSolveOutcome outcome;
      try_stick_solve(outcome);
      if (outcome == StickSolveOutcome::kept) report.residual = error_now();
    }
    if (converged) break;
    if (stick_solves && iteration >= next_subspace && iteration < options.max_iterations) {
      StickSolveOutcome outcome;
      const double error_before = try_stick_solve(outcome);
      if (outcome == StickSolveOutcome::kept) {
        const double error = error_now();
        if (options.measure != ConvergenceMeasure::increment && error <= options.tolerance) {
          report.residual = error;
          break;
        }
        // soon again only after a solve that cut the error tenfold (header)
        subspace_wait = error <= 0.1 * error_before ? 2 : 2 * subspace_wait;
        subspace_dropped = 0;
      } else {
        subspace_wait *= 2;
        ++subspace_dropped;
      }
      // after three dropped solves in a row, none for the rest of this solve
      next_subspace = subspace_dropped >= 3 ? options.max_iterations : iteration + subspace_wait;
    }
    if (iteration == options.max_iterations) report.hit_iteration_cap = true;
  }
  if (stick_solves && backoff != nullptr) {
    if (report.subspace_accepted > 0) {
      backoff->wait = 0;
    } else if (stick_solve_harmed) {
      backoff->wait = std::min(std::max(1, 2 * backoff->wait), 1024);
      backoff->skip = backoff->wait;
    }
  }
  report.siconos_error = error_now();
  return result;
}

std::unique_ptr<ContactOperator> body_contact_operator(const NscdStep& step, const NscdOptions& options) {
  options.validate();
  return std::make_unique<BodyContactOperator>(step, options);
}

NscdStepResult solve_nscd_step(const NscdStep& step, const NscdOptions& options,
                               const std::vector<Eigen::Vector3d>& warm_start,
                               StickSolveBackoff* backoff,
                               const std::vector<Eigen::Vector2d>& couple_warm_start) {
  options.validate();
  BodyContactOperator op(step, options);
  NscdStepResult result;
  result.contacts = solve_frictional_contact(op, options, warm_start, backoff, couple_warm_start);
  const int body_count = static_cast<int>(step.bodies.size());
  result.velocities.resize(body_count);
  result.angular_velocities.resize(body_count);
  for (int b = 0; b < body_count; ++b) {
    result.velocities[b] = op.body_velocity(b).head<3>();
    result.angular_velocities[b] = op.body_velocity(b).tail<3>();
  }
  const double h = step.time_step, theta = options.theta;
  for (int c = 0; c < op.contact_count(); ++c) {
    const double g = step.contacts[c].gap;
    result.max_overlap = std::max(result.max_overlap, -g);
    const double predicted =
        g + h * ((1.0 - theta) * op.start_normal_velocity(c) + theta * op.unshifted_normal_velocity(c, step));
    result.max_predicted_penetration = std::max(result.max_predicted_penetration, -predicted);
  }
  return result;
}

Eigen::Matrix3d contact_frame(const Eigen::Vector3d& normal) {
  const double length = normal.norm();
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw InvalidArgument("normal", "contact normal must be finite and non-zero");
  }
  const Eigen::Vector3d n = normal / length;
  int axis = 0;
  n.cwiseAbs().minCoeff(&axis);
  const Eigen::Vector3d t1 = n.cross(Eigen::Vector3d::Unit(axis)).normalized();
  const Eigen::Vector3d t2 = n.cross(t1);
  Eigen::Matrix3d frame;
  frame << n, t1, t2;
  return frame;
}

ContactJacobian contact_jacobian(const Eigen::Matrix3d& frame, const Eigen::Vector3d& arm,
                                 double sign) {
  // v + ω × arm = v − [arm]× ω.
  Eigen::Matrix3d arm_cross;
  arm_cross << 0.0, -arm[2], arm[1], arm[2], 0.0, -arm[0], -arm[1], arm[0], 0.0;
  ContactJacobian H;
  H.leftCols<3>() = sign * frame.transpose();
  H.rightCols<3>() = -sign * frame.transpose() * arm_cross;
  return H;
}

// ---------------------------------------------------------------------------------------
// Reduced problem.

BlockSparseMatrix3::BlockSparseMatrix3(int block_count) {
  if (block_count < 0) throw InvalidArgument("W", "negative block count");
  rows_.resize(block_count);
}

long BlockSparseMatrix3::stored_blocks() const {
  long count = 0;
  for (const auto& row : rows_) count += static_cast<long>(row.size());
  return count;
}

void BlockSparseMatrix3::add(int row, int column, const Eigen::Matrix3d& block) {
  if (row < 0 || row >= block_count() || column < 0 || column >= block_count()) {
    throw InvalidArgument("W", "block (" + std::to_string(row) + ", " + std::to_string(column) +
                                   ") outside a " + std::to_string(block_count()) +
                                   "-block matrix");
  }
  std::vector<Entry>& entries = rows_[row];
  auto it = std::lower_bound(entries.begin(), entries.end(), column,
                             [](const Entry& e, int col) { return e.column < col; });
  if (it != entries.end() && it->column == column) {
    it->block += block;
  } else {
    entries.insert(it, Entry{column, block});
  }
}

const Eigen::Matrix3d* BlockSparseMatrix3::find(int row, int column) const {
  const std::vector<Entry>& entries = rows_[row];
  auto it = std::lower_bound(entries.begin(), entries.end(), column,
                             [](const Entry& e, int col) { return e.column < col; });
  return (it != entries.end() && it->column == column) ? &it->block : nullptr;
}

BlockSparseMatrix3 BlockSparseMatrix3::from_dense(const Eigen::MatrixXd& dense) {
  if (dense.rows() != dense.cols() || dense.rows() % 3 != 0) {
    throw InvalidArgument("W", "dense W must be square with a size divisible by 3");
  }
  const int n = static_cast<int>(dense.rows() / 3);
  BlockSparseMatrix3 matrix(n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Eigen::Matrix3d block = dense.block<3, 3>(3 * i, 3 * j);
      if (!block.isZero(0.0)) matrix.rows_[i].push_back(Entry{j, block});
    }
  }
  return matrix;
}

Eigen::MatrixXd BlockSparseMatrix3::to_dense() const {
  const int n = block_count();
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int i = 0; i < n; ++i) {
    for (const Entry& e : rows_[i]) dense.block<3, 3>(3 * i, 3 * e.column) = e.block;
  }
  return dense;
}

Eigen::VectorXd BlockSparseMatrix3::multiply(const Eigen::VectorXd& x) const {
  const int n = block_count();
  if (x.size() != 3 * n) throw InvalidArgument("x", "vector size does not match W");
  Eigen::VectorXd y = Eigen::VectorXd::Zero(3 * n);
  for (int i = 0; i < n; ++i) {
    for (const Entry& e : rows_[i]) y.segment<3>(3 * i) += e.block * x.segment<3>(3 * e.column);
  }
  return y;
}

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

ContactSolution solve_reduced(const ReducedProblem& problem, const NscdOptions& options,
                              const std::vector<Eigen::Vector3d>& warm_start) {
  ReducedOperator op(problem);
  return solve_frictional_contact(op, options, warm_start);
}

double siconos_error(const ReducedProblem& problem, const std::vector<Eigen::Vector3d>& r) {
  ReducedOperator op(problem);
  if (static_cast<int>(r.size()) != op.contact_count()) {
    throw InvalidArgument("r", "impulse count does not match the problem");
  }
  for (int c = 0; c < op.contact_count(); ++c) op.add_impulse(c, r[c]);
  return siconos_error(op, r);
}

ReducedProblem assemble_reduced(const NscdStep& step, const NscdOptions& options) {
  options.validate();
  BodyContactOperator op(step, options);  // validates, gives q and W
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
