// The contact plane ⟂ a unit normal n: an orthonormal basis of it and 2D coordinates in
// it, where the contact manifolds clip the features' polygons (contact_manifold.h).
#pragma once

#include <Eigen/Dense>

namespace wiregrain {

// Orthonormal basis (u, w) of the plane ⟂ n (unit) with u × w = n: u = e_k × n / |e_k × n|,
// e_k the coordinate axis least aligned with n (the first of ties).
inline void plane_basis(const Eigen::Vector3d& n, Eigen::Vector3d& u, Eigen::Vector3d& w) {
  int k = 0;
  n.cwiseAbs().minCoeff(&k);
  u = Eigen::Vector3d::Unit(k).cross(n).normalized();
  w = n.cross(u);
}

// The contact plane: 2D coordinates ⟂ n about an origin.
struct ContactFrame {
  Eigen::Vector3d origin, n, u, w;
  ContactFrame(const Eigen::Vector3d& origin_, const Eigen::Vector3d& n_) : origin(origin_), n(n_) {
    plane_basis(n, u, w);
  }
  Eigen::Vector2d project(const Eigen::Vector3d& x) const {
    const Eigen::Vector3d d = x - origin;
    return Eigen::Vector2d(u.dot(d), w.dot(d));
  }
  Eigen::Vector3d lift(const Eigen::Vector2d& p) const { return origin + p.x() * u + p.y() * w; }
  // The point of the plane {N·x = offset} on the line through x parallel to n.
  Eigen::Vector3d onto_plane(const Eigen::Vector3d& x, const Eigen::Vector3d& N, double offset) const {
    return x + ((offset - N.dot(x)) / N.dot(n)) * n;
  }
};

}  // namespace wiregrain
