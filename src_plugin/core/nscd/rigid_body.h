// Rigid-body state and time-stepping building blocks for the grains.
//
// Rotation: the orientation is the unit quaternion q that maps body-frame vectors to the
// space frame, x_space = q · x_body (Eigen's q * x), with the body frame the principal
// axes of inertia (I_1, I_2, I_3 on its x, y, z). The momentum variable is the angular
// momentum L in the space frame; the body-frame momentum is π = qᵀ · L and the angular
// velocity ω_body = π / I (componentwise).
//
// Time stepping by splitting (the idea of Dullweber, Leimkuhler & McLachlan, J. Chem.
// Phys. 107, 5840 (1997), and of the NO_SQUISH scheme of Miller et al., J. Chem. Phys.
// 116, 8649 (2002): compose exact flows of integrable pieces of the Hamiltonian):
//   - kick:   L += T dt (torque T in the space frame; also impulses from a contact
//             solver, L += P);
//   - free rotation over dt: the torque-free Hamiltonian is written, with I_s the median
//     principal moment and a, c the two other axes,
//       H = |π|²/(2 I_s) + (π_a²/2)(1/I_a − 1/I_s) + (π_c²/2)(1/I_c − 1/I_s).
//     Each term's flow is an exact rotation: the first turns the body about the fixed
//     space vector L by |L| dt / I_s; the flow of (π_k²/2) c_k turns it about its own
//     axis k by c_k π_k dt, q ← q · (cos θ/2, sin θ/2 e_k). |π|² commutes with every π_k,
//     so only the two corrections need splitting:
//       Φ(dt) = S(dt) ∘ R_a(dt/2) R_c(dt) R_a(dt/2)      (S: the spherical rotation)
//     is second order, symplectic and time-reversible, and exact for a sphere and for
//     any symmetric top (one correction vanishes). Compared with splitting into the
//     three axis rotations R_1 R_2 R_3 R_2 R_1 (DLM), it measured 20–60 times smaller
//     energy and orientation errors for grain-like moments (0.8, 1, 1.2) and (0.3, 0.35,
//     0.45); for the very anisotropic (1, 2, 3) the energy error was 10 times larger and
//     the orientation error 6 times smaller. `splitting4` composes Φ as Yoshida's
//     triple jump (w1 = 1/(2 − 2^{1/3}), w0 = 1 − 2 w1) for fourth order at three times
//     the cost.
// L is never touched by the free rotation, so the angular-momentum vector is conserved
// exactly; the energy is not exactly conserved but its error stays bounded, O(dt²)
// (O(dt⁴) with splitting4), with no drift. The quaternion is renormalised after every
// free rotation (it only drifts by rounding).
//
// step() = kick(dt/2), free rotation(dt), kick(dt/2): second order overall for torques
// that depend on the configuration only (splitting4 raises the order of the torque-free
// part only). A Moreau–Jean NSCD step instead uses kick(impulses) then
// rotate_free(dt) with the end-of-step momentum (symplectic Euler, first order).
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>

namespace wiregrain {

enum class FreeRotationScheme { splitting2, splitting4 };

class RigidRotation {
 public:
  // principal_moments: I_1, I_2, I_3 > 0 (body axes x, y, z). orientation: body -> space,
  // any non-zero quaternion (normalised here). angular_momentum: L in the space frame.
  RigidRotation(const Eigen::Vector3d& principal_moments,
                const Eigen::Quaterniond& orientation,
                const Eigen::Vector3d& angular_momentum);
  // Same, from the angular velocity ω in the space frame: L = q I qᵀ ω.
  static RigidRotation from_angular_velocity(const Eigen::Vector3d& principal_moments,
                                             const Eigen::Quaterniond& orientation,
                                             const Eigen::Vector3d& angular_velocity);

  const Eigen::Vector3d& principal_moments() const { return principal_moments_; }
  const Eigen::Quaterniond& orientation() const { return orientation_; }
  const Eigen::Vector3d& angular_momentum() const { return angular_momentum_; }  // space

  Eigen::Vector3d angular_momentum_body() const;  // π = qᵀ L
  Eigen::Vector3d angular_velocity_body() const;  // π / I
  Eigen::Vector3d angular_velocity() const;       // space frame: q (π / I)
  Eigen::Matrix3d inertia_space() const;          // R diag(I) Rᵀ
  Eigen::Matrix3d inverse_inertia_space() const;  // R diag(1/I) Rᵀ
  double kinetic_energy() const;                  // Σ π_k² / (2 I_k)

  void set_orientation(const Eigen::Quaterniond& orientation);  // normalised
  void set_angular_momentum(const Eigen::Vector3d& angular_momentum) {
    angular_momentum_ = angular_momentum;
  }
  void set_angular_velocity(const Eigen::Vector3d& angular_velocity);  // space frame

  // L += impulse (space frame), e.g. from a contact solver.
  void apply_angular_impulse(const Eigen::Vector3d& impulse) { angular_momentum_ += impulse; }
  // L += torque · dt (space frame).
  void kick(const Eigen::Vector3d& torque, double dt);
  // Torque-free motion over dt (negative dt runs backwards); L is unchanged.
  void rotate_free(double dt, FreeRotationScheme scheme = FreeRotationScheme::splitting2);
  // kick(dt/2), rotate_free(dt), kick(dt/2) with the same torque.
  void step(const Eigen::Vector3d& torque, double dt,
            FreeRotationScheme scheme = FreeRotationScheme::splitting2);

 private:
  void rotate_about_body_axis(int axis, double rate_per_momentum, double dt);
  void rotate_about_momentum(double moment, double dt);
  void strang(double dt);

  Eigen::Vector3d principal_moments_;
  int median_axis_ = 1;  // index of the median principal moment
  Eigen::Quaterniond orientation_;
  Eigen::Vector3d angular_momentum_;
};

// Translation of the centre of mass: velocity Verlet pieces.
class RigidTranslation {
 public:
  RigidTranslation(double mass, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity);

  double mass() const { return mass_; }
  const Eigen::Vector3d& position() const { return position_; }
  const Eigen::Vector3d& velocity() const { return velocity_; }
  void set_position(const Eigen::Vector3d& position) { position_ = position; }
  void set_velocity(const Eigen::Vector3d& velocity) { velocity_ = velocity; }

  void apply_impulse(const Eigen::Vector3d& impulse) { velocity_ += impulse / mass_; }
  void kick(const Eigen::Vector3d& force, double dt) { velocity_ += force * (dt / mass_); }
  void drift(double dt) { position_ += velocity_ * dt; }
  double kinetic_energy() const { return 0.5 * mass_ * velocity_.squaredNorm(); }

 private:
  double mass_;
  Eigen::Vector3d position_;
  Eigen::Vector3d velocity_;
};

}  // namespace wiregrain
