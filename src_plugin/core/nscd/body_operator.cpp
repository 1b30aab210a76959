// BodyContactOperator (body_operator.h): its construction from a step, the rolling
// couples' local law and residual, and W assembled on demand.
#include "core/nscd/body_operator.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/errors.h"
#include "core/common/validation.h"
#include "core/nscd/input_checks.h"

namespace wiregrain {

thread_local std::vector<BodyContactOperator::Link> BodyContactOperator::recycled_links_;

BodyContactOperator::BodyContactOperator(const NscdStep& step) {
  step.law.validate();
  require_positive("time_step", step.time_step);
  set_bodies(step);
  set_copies(step);
  const int n = static_cast<int>(step.contacts.size());
  links_.swap(recycled_links_);
  links_.resize(n);
  start_normal_velocity_.resize(n);
  double norm_q_squared = 0.0;
  for (int c = 0; c < n; ++c) {
    check_contact(step, c);
    set_link(step, c);
    const Eigen::Vector3d q = velocity(c);
    norm_q_squared += q.squaredNorm();
  }
  norm_q_ = std::sqrt(norm_q_squared);
  set_rolling_blocks(step);
}

BodyContactOperator::~BodyContactOperator() {
  if (links_.capacity() > recycled_links_.capacity()) recycled_links_.swap(links_);
}

// Mass splitting (core/nscd/nscd_step.h): a body touched on k > 1 workers is swept with
// k times its inverse mass and inertia (the Delassus blocks of its contacts with them).
void BodyContactOperator::set_copies(const NscdStep& step) {
  if (!step.distributed) return;
  distributed_ = true;
  const int body_count = static_cast<int>(bodies_.size());
  if (static_cast<int>(step.touching_copies.size()) != body_count)
    throw InvalidArgument("bodies", "touching_copies has " + std::to_string(step.touching_copies.size()) +
                                        " entries for " + std::to_string(body_count) + " bodies");
  copies_ = step.touching_copies;
  touched_here_.assign(body_count, 0);
  for (const NscdContact& contact : step.contacts)  // (indices out of range: check_contact's error)
    for (int body : {contact.body_a, contact.body_b})
      if (body >= 0 && body < body_count) touched_here_[body] = 1;
  for (int b = 0; b < body_count; ++b) {
    if (!(copies_[b] >= (touched_here_[b] ? 1.0 : 0.0)) || !std::isfinite(copies_[b]))
      throw InvalidArgument("bodies", "body " + std::to_string(b) + ": touching_copies " +
                                          std::to_string(copies_[b]) + " below the copies touched here");
    if (copies_[b] > 1.0) {
      bodies_[b].inverse_mass *= copies_[b];
      bodies_[b].inverse_inertia *= copies_[b];
    }
  }
  synchronized_.resize(body_count);
  for (int b = 0; b < body_count; ++b) synchronized_[b] = bodies_[b].velocity;
}

Eigen::Matrix3d BodyContactOperator::true_delassus_block(int c) const {
  const Link& link = links_[c];
  Eigen::Matrix3d W = Eigen::Matrix3d::Zero();
  for (const auto& [body, H] : {std::pair<int, const RowJacobian*>{link.body_a, &link.jacobian_a},
                                std::pair<int, const RowJacobian*>{link.body_b, &link.jacobian_b}}) {
    if (body < 0) continue;
    const double split = copies_.empty() ? 1.0 : std::max(copies_[body], 1.0);
    const Body& b = bodies_[body];
    W += (b.inverse_mass / split) * H->leftCols<3>() * H->leftCols<3>().transpose() +
         H->rightCols<3>() * (b.inverse_inertia / split) * H->rightCols<3>().transpose();
  }
  return W;
}

std::vector<Eigen::Vector3d> BodyContactOperator::delassus_product(const std::vector<Eigen::Vector3d>& x,
                                                                   WorkerExchange& exchange) const {
  const int body_count = static_cast<int>(bodies_.size());
  std::vector<double> change(6 * static_cast<std::size_t>(body_count), 0.0);
  for (int c = 0; c < static_cast<int>(links_.size()); ++c) {
    if (x[c].isZero(0.0)) continue;
    const Link& link = links_[c];
    for (const auto& [body, H] : {std::pair<int, const RowJacobian*>{link.body_a, &link.jacobian_a},
                                  std::pair<int, const RowJacobian*>{link.body_b, &link.jacobian_b}}) {
      if (body < 0) continue;
      const double split = copies_.empty() ? 1.0 : std::max(copies_[body], 1.0);
      const Eigen::Vector3d linear = H->leftCols<3>().transpose() * x[c];
      const Eigen::Vector3d angular = (bodies_[body].inverse_inertia / split) * (H->rightCols<3>().transpose() * x[c]);
      for (int j = 0; j < 3; ++j) {
        change[6 * body + j] += bodies_[body].inverse_mass / split * linear[j];
        change[6 * body + 3 + j] += angular[j];
      }
    }
  }
  exchange.sum_over_copies(change, 6);
  std::vector<Eigen::Vector3d> product(links_.size(), Eigen::Vector3d::Zero());
  for (int c = 0; c < static_cast<int>(links_.size()); ++c) {
    const Link& link = links_[c];
    if (link.body_a >= 0) product[c] += side_velocity(link.jacobian_a, Eigen::Map<const Vector6d>(&change[6 * link.body_a]));
    if (link.body_b >= 0) product[c] += side_velocity(link.jacobian_b, Eigen::Map<const Vector6d>(&change[6 * link.body_b]));
  }
  return product;
}

void BodyContactOperator::synchronize(WorkerExchange& exchange) {
  const int body_count = static_cast<int>(bodies_.size());
  std::vector<double> change(6 * static_cast<std::size_t>(body_count));
  for (int b = 0; b < body_count; ++b)
    for (int j = 0; j < 6; ++j) change[6 * b + j] = bodies_[b].velocity[j] - synchronized_[b][j];
  exchange.sum_over_copies(change, 6);
  for (int b = 0; b < body_count; ++b) {
    if (!(copies_[b] == 1.0 && touched_here_[b]))  // (one copy touched, here: as it is)
      for (int j = 0; j < 6; ++j) bodies_[b].velocity[j] = synchronized_[b][j] + change[6 * b + j] / std::max(copies_[b], 1.0);
    synchronized_[b] = bodies_[b].velocity;
  }
}

void BodyContactOperator::set_bodies(const NscdStep& step) {
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
}

void BodyContactOperator::check_contact(const NscdStep& step, int c) const {
  const int body_count = static_cast<int>(step.bodies.size());
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
}

void BodyContactOperator::set_link(const NscdStep& step, int c) {
  const double h = step.time_step;
  const NscdContact& contact = step.contacts[c];
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
    throw InvalidArgument("contacts", contact_label(c) + "Delassus block has W_nn = " +
                                          format_number(W(0, 0)) +
                                          " (both sides of infinite mass, or a zero normal row)");
  }
  link.delassus = LocalDelassus(W);
  // Contact-law shift of the normal velocity (core/nscd/nscd_step.h).
  const MoreauJeanLaw& law = step.law;
  const double theta = law.theta;
  const double g = contact.gap;
  const double un_begin = u_begin[0];
  start_normal_velocity_[c] = un_begin;
  // an overlap is removed by β of it per step, at most at the speed overlap_speed
  const double g_target = g < 0.0 ? std::max(law.overlap_recovery * g, -law.overlap_speed * h) : g;
  double shift = (g_target / h + (1.0 - theta) * un_begin) / theta;
  if (law.restitution > 0.0 && un_begin < 0.0 && g + h * un_begin <= 0.0) {
    shift = std::min(shift, law.restitution * un_begin);
  }
  link.constant = contact.velocity_offset;
  link.constant[0] += shift;
}

// rolling blocks (header, "Rolling resistance"), for every contact once any has one
void BodyContactOperator::set_rolling_blocks(const NscdStep& step) {
  bool rolling = false;
  for (const NscdContact& contact : step.contacts) rolling |= contact.rolling_friction > 0.0;
  if (!rolling) return;
  const int n = static_cast<int>(step.contacts.size());
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

Eigen::Vector2d BodyContactOperator::solve_couple(int c, double r_n, const Eigen::Vector2d& couple) const {
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

double BodyContactOperator::rolling_residual(const std::vector<Eigen::Vector2d>& couples,
                                             const std::vector<Eigen::Vector3d>& impulses) const {
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

const BlockSparseMatrix3& BodyContactOperator::delassus_matrix() {
  if (delassus_.block_count() != contact_count()) delassus_ = assemble_delassus(false);
  return delassus_;
}

BlockSparseMatrix3 BodyContactOperator::true_delassus_matrix() const { return assemble_delassus(true); }

BlockSparseMatrix3 BodyContactOperator::assemble_delassus(bool true_masses) const {
  const int n = contact_count();
  BlockSparseMatrix3 W(n);
  // per body, the contacts touching it with that side's H and M⁻¹ Hᵀ
  struct Touch {
    int contact;
    ContactJacobian H;
    Eigen::Matrix<double, 6, 3> response;
  };
  std::vector<std::vector<Touch>> touches(bodies_.size());
  const auto touch = [&](int c, int body, const RowJacobian& H) {
    const double split = true_masses && !copies_.empty() ? std::max(copies_[body], 1.0) : 1.0;
    touches[body].push_back({c, H, response(body, H) / split});
  };
  for (int c = 0; c < n; ++c) {
    const Link& link = links_[c];
    if (link.body_a >= 0) touch(c, link.body_a, link.jacobian_a);
    if (link.body_b >= 0) touch(c, link.body_b, link.jacobian_b);
  }
  for (const std::vector<Touch>& body : touches) {
    for (const Touch& row : body) {
      for (const Touch& column : body) W.add(row.contact, column.contact, row.H * column.response);
    }
  }
  return W;
}

}  // namespace wiregrain
