// Rigid-body rotation by splitting of the free rigid body; see rigid_body.h.
#include "core/nscd/rigid_body.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include "core/common/errors.h"
#include "core/common/validation.h"

namespace wiregrain {

namespace {

using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;


void check_moments(const Vector3d& moments) {
  for (int k = 0; k < 3; ++k)
    if (!(moments[k] > 0.0) || !std::isfinite(moments[k]))
      throw InvalidArgument("principal_moments",
                            "principal_moments must be > 0 and finite, got (" +
                                format_number(moments[0]) + ", " + format_number(moments[1]) + ", " +
                                format_number(moments[2]) + ")");
}

Quaterniond checked_unit(const Quaterniond& q) {
  const double norm = q.norm();
  if (!(norm > 0.0) || !std::isfinite(norm))
    throw InvalidArgument("orientation",
                          "orientation must be a non-zero finite quaternion, got norm " +
                              format_number(norm));
  return Quaterniond(q.coeffs() / norm);
}

void check_dt(double dt) {
  if (!std::isfinite(dt)) throw InvalidArgument("dt", "dt must be finite, got " + format_number(dt));
}

}  // namespace

RigidRotation::RigidRotation(const Vector3d& principal_moments, const Quaterniond& orientation,
                             const Vector3d& angular_momentum)
    : principal_moments_(principal_moments),
      orientation_(checked_unit(orientation)),
      angular_momentum_(angular_momentum) {
  check_moments(principal_moments);
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(),
                   [&](int i, int j) { return principal_moments[i] < principal_moments[j]; });
  median_axis_ = order[1];
}

RigidRotation RigidRotation::from_angular_velocity(const Vector3d& principal_moments,
                                                   const Quaterniond& orientation,
                                                   const Vector3d& angular_velocity) {
  RigidRotation body(principal_moments, orientation, Vector3d::Zero());
  body.set_angular_velocity(angular_velocity);
  return body;
}

Vector3d RigidRotation::angular_momentum_body() const {
  return orientation_.conjugate() * angular_momentum_;
}

Vector3d RigidRotation::angular_velocity_body() const {
  return angular_momentum_body().cwiseQuotient(principal_moments_);
}

Vector3d RigidRotation::angular_velocity() const { return orientation_ * angular_velocity_body(); }

Matrix3d RigidRotation::inertia_space() const {
  const Matrix3d r = orientation_.toRotationMatrix();
  return r * principal_moments_.asDiagonal() * r.transpose();
}

Matrix3d RigidRotation::inverse_inertia_space() const {
  const Matrix3d r = orientation_.toRotationMatrix();
  return r * principal_moments_.cwiseInverse().asDiagonal() * r.transpose();
}

double RigidRotation::kinetic_energy() const {
  const Vector3d pi = angular_momentum_body();
  return 0.5 * pi.cwiseProduct(pi).cwiseQuotient(principal_moments_).sum();
}

void RigidRotation::set_orientation(const Quaterniond& orientation) {
  orientation_ = checked_unit(orientation);
}

void RigidRotation::set_angular_velocity(const Vector3d& angular_velocity) {
  const Vector3d omega_body = orientation_.conjugate() * angular_velocity;
  angular_momentum_ = orientation_ * principal_moments_.cwiseProduct(omega_body);
}

void RigidRotation::kick(const Vector3d& torque, double dt) {
  check_dt(dt);
  angular_momentum_ += torque * dt;
}

// Exact flow of c_k π_k²/2: π_k is constant, the body turns about its own axis k at the
// rate c_k π_k (π = qᵀ L changes, L does not).
void RigidRotation::rotate_about_body_axis(int axis, double rate_per_momentum, double dt) {
  const double pi_k = (orientation_.conjugate() * angular_momentum_)[axis];
  const double half_angle = 0.5 * rate_per_momentum * pi_k * dt;
  Quaterniond turn(std::cos(half_angle), 0.0, 0.0, 0.0);
  turn.vec()[axis] = std::sin(half_angle);
  orientation_ = orientation_ * turn;
}

// Exact flow of |π|²/(2 I_s): the body turns about the fixed space vector L at the rate
// |L| / I_s.
void RigidRotation::rotate_about_momentum(double moment, double dt) {
  const double l = angular_momentum_.norm();
  if (l == 0.0) return;
  orientation_ = Quaterniond(Eigen::AngleAxisd(l * dt / moment, angular_momentum_ / l)) * orientation_;
}

// H = |π|²/(2 I_s) + Σ_{k≠s} (π_k²/2)(1/I_k − 1/I_s), I_s the median moment. The first
// term commutes with the others (|π|² is a Casimir), so only the two correction terms
// are split: R_a(dt/2) R_c(dt) R_a(dt/2), then the spherical rotation over dt.
void RigidRotation::strang(double dt) {
  const int s = median_axis_, a = s == 0 ? 1 : 0, c = 3 - s - a;  // a < c
  const double inv_s = 1.0 / principal_moments_[s];
  const double rate_a = 1.0 / principal_moments_[a] - inv_s;
  const double rate_c = 1.0 / principal_moments_[c] - inv_s;
  rotate_about_body_axis(a, rate_a, 0.5 * dt);
  rotate_about_body_axis(c, rate_c, dt);
  rotate_about_body_axis(a, rate_a, 0.5 * dt);
  rotate_about_momentum(principal_moments_[s], dt);
}

void RigidRotation::rotate_free(double dt, FreeRotationScheme scheme) {
  check_dt(dt);
  if (scheme == FreeRotationScheme::splitting4) {
    // Yoshida (Phys. Lett. A 150, 262 (1990)): S(w1 dt) S(w0 dt) S(w1 dt)
    const double w1 = 1.0 / (2.0 - std::cbrt(2.0));
    const double w0 = 1.0 - 2.0 * w1;
    strang(w1 * dt);
    strang(w0 * dt);
    strang(w1 * dt);
  } else {
    strang(dt);
  }
  orientation_.normalize();
}

void RigidRotation::step(const Vector3d& torque, double dt, FreeRotationScheme scheme) {
  kick(torque, 0.5 * dt);
  rotate_free(dt, scheme);
  kick(torque, 0.5 * dt);
}

RigidTranslation::RigidTranslation(double mass, const Vector3d& position, const Vector3d& velocity)
    : mass_(mass), position_(position), velocity_(velocity) {
  require_positive("mass", mass);
}

}  // namespace wiregrain
