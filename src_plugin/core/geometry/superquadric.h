// Superquadric grains as LIGGGHTS 3.8 defines them (atom_style superquadric; its
// superquadric.cpp): in the body frame, with half-axes a, b, c and blockiness n1, n2,
//
//     F(x, y, z) = (|x/a|^n2 + |y/b|^n2)^(n1/n2) + |z/c|^n1 − 1 ≤ 0,
//
// an ellipsoid for n1 = n2 = 2, a rounded box as n1, n2 grow. LIGGGHTS requires n ≥ 2;
// the body is convex for n ≥ 1 and smooth for n > 1.
//
// Support point (the point of the body farthest along a body-frame direction e), in
// closed form by nesting two Hölder maxima. With p = a e_x, q = b e_y, r = c e_z and the
// conjugate exponents m_k = n_k / (n_k − 1), write (x, y, z) = (a ρ u, b ρ v, c w),
// |u|^n2 + |v|^n2 = 1, ρ^n1 + |w|^n1 = 1. Then e·x = ρ (p u + q v) + r w, and
//   max over (u, v) of p u + q v = s = ‖(p, q)‖_{m2}, at u = sgn p |p/s|^(m2−1),
//                                                    v = sgn q |q/s|^(m2−1);
//   max over (ρ, w) of ρ s + r w = ‖(s, r)‖_{m1},    at ρ = |s/t|^(m1−1),
//                                                    w = sgn r |r/t|^(m1−1), t = ‖(s, r)‖_{m1}
// (Hölder's inequality is an equality exactly there). m − 1 = 1/(n − 1).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace wiregrain {

struct Superquadric {
  Eigen::Vector3d half_axes = Eigen::Vector3d::Ones();  // a, b, c
  double n1 = 2.0, n2 = 2.0;                            // blockiness (LIGGGHTS' blockiness1, blockiness2)
};

// Throws InvalidArgument("half_axes" or "blockiness"): half-axes not finite and > 0,
// blockiness not finite and ≥ 2 (LIGGGHTS' own bound).
void check_superquadric(const Superquadric& shape);

// F of the body-frame point (< 0 inside, 0 on the surface).
double superquadric_shape_function(const Superquadric& shape, const Eigen::Vector3d& body_point);
// ∇F at a body-frame point (not normalised; the outward normal direction on the surface).
Eigen::Vector3d superquadric_gradient(const Superquadric& shape, const Eigen::Vector3d& body_point);
// The support point in the body frame for a body-frame direction (any length; zero gives
// the origin).
Eigen::Vector3d superquadric_support(const Superquadric& shape, const Eigen::Vector3d& body_direction);
// A radius about the centre that contains the body: the half-diagonal of its box,
// √(a² + b² + c²).
double superquadric_bounding_radius(const Superquadric& shape);

// Volume and principal moments at density 1 (body axes) of a superquadric, in closed form
// with Euler's beta function B (Jaklič, Leonardis & Solina, "Segmentation and Recovery of
// Superquadrics", 2000, ch. 2; ε_k = 2/n_k):
//   V = 2 a b c ε₁ ε₂ B(ε₁/2, ε₁ + 1) B(ε₂/2, ε₂/2 + 1),
//   I_xx = ½ a b c ε₁ ε₂ [b² B(3ε₂/2, ε₂/2) B(ε₁/2, 2ε₁ + 1) + 4 c² B(ε₂/2, ε₂/2 + 1) B(3ε₁/2, ε₁ + 1)],
//   I_yy likewise with a² for b², I_zz = ½ a b c ε₁ ε₂ (a² + b²) B(3ε₂/2, ε₂/2) B(ε₁/2, 2ε₁ + 1).
double superquadric_volume(const Superquadric& shape);
Eigen::Vector3d superquadric_unit_inertia(const Superquadric& shape);

// The superquadric of blockiness n1, n2 that stands in for a grain of volume V and
// principal moments I (at density 1, about its principal axes): the half-axes of the
// ellipsoid with the same moments per volume, a² = 5 (I_y + I_z − I_x) / (2 V) and
// cyclically, scaled by s = (V / V_sq)^(1/3) so that the superquadric has the volume V.
// Its axes are the grain's principal axes. Throws InvalidArgument("inertia") when the
// moments violate the triangle inequality (no such ellipsoid), ("volume") for V ≤ 0.
Superquadric superquadric_standing_in(double volume, const Eigen::Vector3d& unit_inertia, double n1, double n2);

// A superquadric placed in the world: x_world = R(q) x_body + position.
class PosedSuperquadric {
 public:
  // orientation: body → world, any non-zero finite quaternion (normalised here); the
  // shape is copied (it is small).
  PosedSuperquadric(const Superquadric& shape, const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation);

  const Superquadric& shape() const { return shape_; }
  const Eigen::Vector3d& position() const { return position_; }
  const Eigen::Matrix3d& rotation() const { return rotation_; }
  Eigen::Vector3d support(const Eigen::Vector3d& world_direction) const {
    return position_ + rotation_ * superquadric_support(shape_, rotation_.transpose() * world_direction);
  }
  // the outward unit normal at (or, inside, in the direction of ∇F at) a world point
  Eigen::Vector3d normal_at(const Eigen::Vector3d& world_point) const;
  double shape_function(const Eigen::Vector3d& world_point) const {
    return superquadric_shape_function(shape_, rotation_.transpose() * (world_point - position_));
  }

 private:
  Superquadric shape_;
  Eigen::Vector3d position_;
  Eigen::Matrix3d rotation_;
};

}  // namespace wiregrain
