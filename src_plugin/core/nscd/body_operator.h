// The contact operator of one time step on bodies (core/nscd/contact_operator.h), behind
// solve_nscd_step and assemble_reduced: the bodies' velocities are the state,
//     u_c = H_a V_a + H_b V_b + offset_c + s_c e_n,
// s_c the shift of the contact law (core/nscd/nscd_step.h); an impulse increment updates
// the velocities of its bodies, V += M⁻¹ Hᵀ Δr, and W = H M⁻¹ Hᵀ is never formed (it is
// assembled on demand for method subspace).
//
// Rolling resistance (NscdContact::rolling_friction μ_r > 0 and rolling_radius R; not in
// the paper, whose contacts have none; bodies only). A contact also carries a couple m (its
// tangential components t1, t2: a pure couple, +m on b and −m on a) against the rolling
// part of the relative angular velocity, w = Tᵀ (ω_b − ω_a), T = (t1 t2), w = W_r m + w_free
// with W_r = Tᵀ (I_a⁻¹ + I_b⁻¹) T; the law is Coulomb's on a disc:
//     |m| ≤ μ_r R r_n,  and w = 0, or w = −λ m with λ ≥ 0 and |m| = μ_r R r_n
// (the couple resists rolling as the tangential impulse resists sliding; the spin about
// n is not resisted). In a sweep, after a contact's 3×3 block, its couple is solved with
// the new r_n: m = −W_r⁻¹ w_free if that is in the disc, else the m on the disc's edge
// with m = −(W_r + σ I)⁻¹ w_free, σ ≥ 0 (a 2×2 secular equation, Newton on
// 1/|m(σ)| − 1/(μ_r R r_n) from σ = 0, monotone as for a trust region); a contact with a
// rolling axis a (NscdContact::rolling_axis) takes m = m_a a, the stick value
// −aᵀ w_free / aᵀ W_r a clamped to ± μ_r R r_n. Couples start from the caller's couple
// warm start (else 0). A solve is converged only once the couples satisfy their law too:
// with a measure that computes the Siconos error, the rolling law's natural-map residual
// written as the Siconos error writes Coulomb's (the couple as the impulse m / R at the
// rolling radius, the rolling velocity as the surface speed w R, ρ = 1),
//     sqrt(Σ_c |m_c/R_c − proj_{D_c}(m_c/R_c − R_c w_c)|²) ≤ tolerance × max(‖q‖, ‖r‖),
// D_c the disc of radius μ_r r_n; with `increment`, the couples' increment in the last
// sweep at most tolerance × the bounds' norm. (Measured against |m| itself the test
// never passes where the couples are ~0: a box at rest hits the sweep cap every step;
// relative to the bounds' norm it asks 1/μ_r times the accuracy of Coulomb's law: the
// 500-grain deposit takes 180–370 sweeps per step while it lands, against 8–15 with the
// form above; 2026-11-27, commit b774b66; docs/design.md, "Rolling resistance".) Stick
// solves hold couples as they are and would leave them one update behind, so method
// subspace makes none when any contact has a rolling resistance. A sphere (a point swept
// by r, R = r) on a plane decelerates at (5/7) μ_r g while it rolls and rests on an
// incline while tan α ≤ μ_r (core test NscdRolling).
//
// The class is visible to the solver (core/nscd/gauss_seidel.cpp), which binds its sweep
// to it statically and solves the couples through it.
#pragma once

#include <Eigen/Dense>

#include <cmath>
#include <utility>
#include <vector>

#include "core/common/worker_exchange.h"
#include "core/nscd/nscd_step.h"

namespace wiregrain {

class BodyContactOperator final : public ContactOperator {
 public:
  // Validates the step (its law first, then the time step, the bodies and the contacts
  // in order; the InvalidArgument of solve_nscd_step) and starts in the state r = 0.
  explicit BodyContactOperator(const NscdStep& step);
  // Hands its links' storage to the next operator built on this thread.
  ~BodyContactOperator() override;
  BodyContactOperator(const BodyContactOperator&) = delete;
  BodyContactOperator& operator=(const BodyContactOperator&) = delete;

  bool has_rolling() const { return !rolling_.empty(); }
  double rolling_bound(int c) const { return links_[c].rolling; }
  // The couple of contact c's rolling law (header) for normal impulse r_n, the other
  // impulses and couples as they are; `couple`: its present couple.
  Eigen::Vector2d solve_couple(int c, double r_n, const Eigen::Vector2d& couple) const;
  // The rolling law's natural-map residual as the Siconos error's numerator has it for
  // Coulomb's law (header): the couple as the impulse m / R at the rolling radius, the
  // rolling velocity as the surface speed w R, and ρ = 1:
  //     sqrt(Σ_c |m_c / R_c − proj_{D_c}(m_c / R_c − w_c R_c)|²),
  // D_c the disc of radius μ_r r_n (a one-axis couple: the segment along its axis).
  double rolling_residual(const std::vector<Eigen::Vector2d>& couples,
                          const std::vector<Eigen::Vector3d>& impulses) const;
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
  const BlockSparseMatrix3& delassus_matrix() override;

  const Vector6d& body_velocity(int b) const { return bodies_[b].velocity; }
  int body_count() const { return static_cast<int>(bodies_.size()); }
  // the bodies of contact c that an impulse moves: their indices, −1 for a wall or a body
  // of infinite mass and inertia (core/nscd/contact_colouring.h)
  std::pair<int, int> moving_bodies(int c) const {
    const auto moving = [this](int b) {
      return b >= 0 && (bodies_[b].inverse_mass != 0.0 || !bodies_[b].inverse_inertia.isZero(0.0)) ? b : -1;
    };
    return {moving(links_[c].body_a), moving(links_[c].body_b)};
  }

  // A distributed step (NscdStep::touching_copies non-empty): the exchange of the copies'
  // velocities after a sweep (mass splitting, core/nscd/nscd_step.h): every body takes
  // V_sync + (1/k) Σ_copies (V_copy − V_sync); a body touched by this worker's contacts
  // alone (k = 1) keeps its velocity as it is, to the bit. Collective.
  bool distributed() const { return distributed_; }
  void synchronize(WorkerExchange& exchange);
  // W x over every worker's contacts with the bodies' true masses (not split): x one
  // impulse per contact of this worker (local frames); the bodies' velocity changes
  // M⁻¹ Hᵀ x summed over every copy, read by each contact. Collective.
  std::vector<Eigen::Vector3d> delassus_product(const std::vector<Eigen::Vector3d>& x, WorkerExchange& exchange) const;
  // W_cc with the true masses (the sweep's delassus_block(c) has the split ones)
  Eigen::Matrix3d true_delassus_block(int c) const;
  // W over this worker's contacts with the true masses: the principal block of every
  // worker's W that belongs to this worker's contacts (its blocks between this worker's
  // contacts and other workers' are not here); delassus_matrix() has the split masses.
  BlockSparseMatrix3 true_delassus_matrix() const;
  // ‖q‖ over every worker's contacts (collective); free_velocity_norm() is this worker's
  double free_velocity_norm_over_workers(WorkerExchange& exchange) const {
    double squared = norm_q_ * norm_q_;
    exchange.sum_over_workers(&squared, 1);
    return std::sqrt(squared);
  }
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
  // a contact's rolling block: T = (t1 t2) in world axes and W_r = Tᵀ (I_a⁻¹ + I_b⁻¹) T
  struct RollingBlock {
    Eigen::Matrix<double, 3, 2> tangents;
    Eigen::Matrix2d delassus;
    bool one_axis = false;  // the couple only along `axis` (t1, t2 components, unit)
    Eigen::Vector2d axis = Eigen::Vector2d::Zero();
  };

  // The constructor's steps: the bodies at their free velocities; contact c's checks;
  // its link (Jacobians, μ, Delassus block, the law's shift); the rolling blocks.
  void set_bodies(const NscdStep& step);
  void check_contact(const NscdStep& step, int c) const;
  void set_link(const NscdStep& step, int c);
  void set_rolling_blocks(const NscdStep& step);
  void set_copies(const NscdStep& step);
  // W = H M⁻¹ Hᵀ over this worker's contacts, with the bodies' split masses or their true ones
  BlockSparseMatrix3 assemble_delassus(bool true_masses) const;

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

  std::vector<Link> links_;
  // The links of the last operator destroyed on this thread, taken over by the next one: a
  // run builds one operator per step, and fresh links (half a kilobyte a contact) took
  // 6.6 % of the Table 1 column's wall phase in their construction and page faults. Every
  // field of a link is written by set_link, so the recycled values are never read.
  static thread_local std::vector<Link> recycled_links_;
  std::vector<RollingBlock> rolling_;  // empty unless a contact has a rolling resistance
  std::vector<Body> bodies_;
  std::vector<double> start_normal_velocity_;
  double norm_q_ = 0.0;
  // distributed: per body k (touching_copies), whether a contact here touches it, and its
  // velocity after the last exchange
  bool distributed_ = false;
  std::vector<double> copies_;
  std::vector<char> touched_here_;
  std::vector<Vector6d> synchronized_;
  BlockSparseMatrix3 delassus_;  // assembled on demand
};

}  // namespace wiregrain
