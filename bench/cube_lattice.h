// The generated pile of bench/fclib_nscd and bench/nscd_body_sweep: NX×NY columns of NZ
// unit cubes (mass 1, inertia 1/6) on a frictional ground, g = 1, h = 1e-3 (docs/units.md,
// "The decks' units"), in face contact with their neighbours (4 points per face, contacts
// listed body by body: ground or lower face, then the −x and −y faces). perturb: random
// start velocities of 0.1 g h and gaps of ±2e-7 (seeded); else at rest and touching.
#pragma once

#include <Eigen/Dense>

#include <cstdint>
#include <random>

#include "core/nscd/nscd_solver.h"

namespace wiregrain_bench {

inline wiregrain::NscdStep cube_lattice(int nx, int ny, int nz, std::uint64_t seed, double mu,
                                        bool perturb) {
  using namespace wiregrain;
  using Eigen::Matrix3d;
  using Eigen::Vector3d;
  const double h = 1e-3, g = 1.0;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  NscdStep step;
  step.time_step = h;
  auto index = [&](int i, int j, int k) { return (k * ny + j) * nx + i; };
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        NscdBody body;
        body.inverse_mass = 1.0;
        body.inverse_inertia = 6.0 * Matrix3d::Identity();
        if (perturb) {
          body.velocity_begin = 0.1 * g * h * Vector3d(unit(rng), unit(rng), unit(rng));
          body.angular_velocity_begin = 0.1 * g * h * Vector3d(unit(rng), unit(rng), unit(rng));
        }
        body.velocity_free = body.velocity_begin + Vector3d(0.0, 0.0, -g * h);
        body.angular_velocity_free = body.angular_velocity_begin;
        step.bodies.push_back(body);
      }
    }
  }
  // Four points at the corners of the unit face between `lower` (−1: ground) and `upper`,
  // normal along `axis` from lower to upper.
  auto add_face = [&](int lower, int upper, int axis) {
    const Vector3d n = Vector3d::Unit(axis);
    const Vector3d e1 = Vector3d::Unit((axis + 1) % 3), e2 = Vector3d::Unit((axis + 2) % 3);
    const Matrix3d frame = contact_frame(n);
    for (double s1 : {-0.5, 0.5}) {
      for (double s2 : {-0.5, 0.5}) {
        NscdContact contact;
        contact.body_a = lower;
        contact.body_b = upper;
        contact.friction = mu;
        contact.gap = perturb ? 2e-7 * unit(rng) : 0.0;
        const Vector3d in_face = s1 * e1 + s2 * e2;
        contact.jacobian_b = contact_jacobian(frame, -0.5 * n + in_face, 1.0);
        if (lower >= 0) contact.jacobian_a = contact_jacobian(frame, 0.5 * n + in_face, -1.0);
        step.contacts.push_back(contact);
      }
    }
  };
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        add_face(k == 0 ? -1 : index(i, j, k - 1), index(i, j, k), 2);
        if (i > 0) add_face(index(i - 1, j, k), index(i, j, k), 0);
        if (j > 0) add_face(index(i, j - 1, k), index(i, j, k), 1);
      }
    }
  }
  return step;
}

}  // namespace wiregrain_bench
