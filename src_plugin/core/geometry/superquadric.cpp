#include "core/geometry/superquadric.h"

#include <cmath>
#include <string>

#include "core/common/errors.h"
#include "core/common/validation.h"

namespace wiregrain {

namespace {

// |x|^e, with the exponents of blockiness 2 and 3 (ellipsoids and the column's default:
// e = n, n − 1, n/(n − 1), 1/(n − 1), (n − 1)/n) by sqrt and cbrt: std::pow was 40 % of a
// superquadric column's run time (perf, bench/grain_models.py)
double pow_abs(double x, double e) {
  const double a = std::abs(x);
  if (e == 1.0) return a;
  if (e == 2.0) return a * a;
  if (e == 3.0) return a * a * a;
  if (e == 0.5) return std::sqrt(a);
  if (e == 1.5) return a * std::sqrt(a);
  if (e == 2.0 / 3.0) return std::cbrt(a * a);
  return std::pow(a, e);
}

}  // namespace

void check_superquadric(const Superquadric& shape) {
  for (int d = 0; d < 3; ++d)
    if (!(shape.half_axes[d] > 0.0) || !std::isfinite(shape.half_axes[d]))
      throw InvalidArgument("half_axes", "superquadric half-axes must be finite and > 0, got " +
                                             format_number(shape.half_axes[0]) + " " + format_number(shape.half_axes[1]) + " " +
                                             format_number(shape.half_axes[2]));
  if (!(shape.n1 >= 2.0) || !(shape.n2 >= 2.0) || !std::isfinite(shape.n1) || !std::isfinite(shape.n2))
    throw InvalidArgument("blockiness", "superquadric blockiness must be finite and >= 2, got " + format_number(shape.n1) +
                                            " " + format_number(shape.n2));
}

double superquadric_shape_function(const Superquadric& s, const Eigen::Vector3d& x) {
  const Eigen::Vector3d& h = s.half_axes;
  return pow_abs(pow_abs(x.x() / h.x(), s.n2) + pow_abs(x.y() / h.y(), s.n2), s.n1 / s.n2) +
         pow_abs(x.z() / h.z(), s.n1) - 1.0;
}

Eigen::Vector3d superquadric_gradient(const Superquadric& s, const Eigen::Vector3d& x) {
  // F = ν^(n1/n2) + |z/c|^n1, ν = |x/a|^n2 + |y/b|^n2:
  // ∂F/∂x = (n1/n2) ν^(n1/n2 − 1) n2 |x/a|^(n2−1) sgn(x) / a, likewise y; ∂F/∂z = n1 |z/c|^(n1−1) sgn(z) / c
  const Eigen::Vector3d& h = s.half_axes;
  const double nu = pow_abs(x.x() / h.x(), s.n2) + pow_abs(x.y() / h.y(), s.n2);
  const double outer = nu > 0.0 ? s.n1 * std::pow(nu, s.n1 / s.n2 - 1.0) : 0.0;
  const auto sign = [](double v) { return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0); };
  return Eigen::Vector3d(outer * pow_abs(x.x() / h.x(), s.n2 - 1.0) * sign(x.x()) / h.x(),
                         outer * pow_abs(x.y() / h.y(), s.n2 - 1.0) * sign(x.y()) / h.y(),
                         s.n1 * pow_abs(x.z() / h.z(), s.n1 - 1.0) * sign(x.z()) / h.z());
}

Eigen::Vector3d superquadric_support(const Superquadric& s, const Eigen::Vector3d& e) {
  const Eigen::Vector3d& h = s.half_axes;
  const double p = h.x() * e.x(), q = h.y() * e.y(), r = h.z() * e.z();
  const double m1 = s.n1 / (s.n1 - 1.0), m2 = s.n2 / (s.n2 - 1.0);
  const double k1 = 1.0 / (s.n1 - 1.0), k2 = 1.0 / (s.n2 - 1.0);  // m − 1
  // the norms with the largest component factored out (no overflow or underflow)
  const auto norm = [](double x, double y, double m) {
    const double big = std::max(std::abs(x), std::abs(y));
    if (!(big > 0.0)) return 0.0;
    return big * pow_abs(pow_abs(x / big, m) + pow_abs(y / big, m), 1.0 / m);
  };
  const double sq = norm(p, q, m2);
  const double t = norm(sq, r, m1);
  if (!(t > 0.0)) return Eigen::Vector3d::Zero();
  const double rho = pow_abs(sq / t, k1);
  const double w = std::copysign(pow_abs(r / t, k1), r);
  const double u = sq > 0.0 ? std::copysign(pow_abs(p / sq, k2), p) : 0.0;
  const double v = sq > 0.0 ? std::copysign(pow_abs(q / sq, k2), q) : 0.0;
  return Eigen::Vector3d(h.x() * rho * u, h.y() * rho * v, h.z() * w);
}

double superquadric_bounding_radius(const Superquadric& s) { return s.half_axes.norm(); }

double superquadric_volume(const Superquadric& s) {
  const double e1 = 2.0 / s.n1, e2 = 2.0 / s.n2;
  return 2.0 * s.half_axes.prod() * e1 * e2 * std::beta(0.5 * e1, e1 + 1.0) * std::beta(0.5 * e2, 0.5 * e2 + 1.0);
}

Eigen::Vector3d superquadric_unit_inertia(const Superquadric& s) {
  const double e1 = 2.0 / s.n1, e2 = 2.0 / s.n2;
  const double a = s.half_axes.x(), b = s.half_axes.y(), c = s.half_axes.z();
  const double front = 0.5 * a * b * c * e1 * e2;
  const double planar = std::beta(1.5 * e2, 0.5 * e2) * std::beta(0.5 * e1, 2.0 * e1 + 1.0);
  const double axial = 4.0 * std::beta(0.5 * e2, 0.5 * e2 + 1.0) * std::beta(1.5 * e1, e1 + 1.0);
  return Eigen::Vector3d(front * (b * b * planar + c * c * axial), front * (a * a * planar + c * c * axial),
                         front * (a * a + b * b) * planar);
}

Superquadric superquadric_standing_in(double volume, const Eigen::Vector3d& unit_inertia, double n1, double n2) {
  if (!(volume > 0.0) || !std::isfinite(volume))
    throw InvalidArgument("volume", "volume must be finite and > 0, got " + format_number(volume));
  const Eigen::Vector3d& I = unit_inertia;
  const Eigen::Vector3d squares(I.y() + I.z() - I.x(), I.x() + I.z() - I.y(), I.x() + I.y() - I.z());
  if (!(squares.minCoeff() > 0.0) || !I.allFinite())
    throw InvalidArgument("inertia", "principal moments " + format_number(I.x()) + " " + format_number(I.y()) + " " +
                                         format_number(I.z()) + " are no solid's (triangle inequality)");
  Superquadric out;
  out.half_axes = (2.5 / volume * squares).cwiseSqrt();
  out.n1 = n1;
  out.n2 = n2;
  check_superquadric(out);
  out.half_axes *= std::cbrt(volume / superquadric_volume(out));
  return out;
}

PosedSuperquadric::PosedSuperquadric(const Superquadric& shape, const Eigen::Vector3d& position,
                                     const Eigen::Quaterniond& orientation)
    : shape_(shape), position_(position) {
  check_superquadric(shape);
  if (!position.allFinite()) throw InvalidArgument("position", "superquadric position is not finite");
  if (!orientation.coeffs().allFinite() || !(orientation.squaredNorm() > 0.0))
    throw InvalidArgument("orientation", "superquadric orientation must be a finite non-zero quaternion");
  rotation_ = orientation.normalized().toRotationMatrix();
}

Eigen::Vector3d PosedSuperquadric::normal_at(const Eigen::Vector3d& world_point) const {
  const Eigen::Vector3d body = rotation_.transpose() * (world_point - position_);
  Eigen::Vector3d g = superquadric_gradient(shape_, body);
  if (!(g.squaredNorm() > 0.0)) g = body;  // the centre: ∇F = 0
  if (!(g.squaredNorm() > 0.0)) g = Eigen::Vector3d::UnitZ();
  return (rotation_ * g).normalized();
}

}  // namespace wiregrain
