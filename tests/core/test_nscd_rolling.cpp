// A sphere rolling and sliding under the Moreau–Jean step exactly as fix nscd/polyhedra
// runs it (core/nscd/grain_step.h: grain_step, then advance_grain_pose), against the
// rigid-body answers of a uniform sphere (I = 2/5 m r²) on a plane with Coulomb friction:
//  - on an incline of angle α with μ ≥ (2/7) tan α it rolls without slipping,
//        a = (5/7) g sin α,  ω = v / r;
//    below that friction it slides and spins up,
//        a = g (sin α − μ cos α),  dω/dt = (5/2) μ g cos α / r;
//  - launched on a level floor at v0 without spin it slides until v = (5/7) v0 (the
//    angular momentum about the contact point, m r v + I ω, is kept by the friction
//    impulse, which acts at that point), at t* = 2 v0 / (7 μ g), then rolls on at that v.
// Each is a linear update per step with the contact frame fixed, so the scheme reproduces
// them to round-off. Energy (θ-method algebra, one persistent sticking contact at zero gap,
// a sphere so the rotation is exact): E_{k+1} − E_k = h (θ − ½) m g·(v_k − v_{k+1}), i.e.
// conserved at θ = ½ and lost as −(h/2) m g·v(T) over the roll at θ = 1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "core/geometry/convex_shape.h"
#include "core/geometry/shape_library.h"
#include "core/nscd/grain_step.h"

using namespace wiregrain;
using Eigen::Vector3d;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 0.5, kDensity = 1.5;

struct Sphere {
  ShapeLibrary library;
  GrainState state;
  Sphere() {
    library.add(ConvexShape::sphere(kRadius));
    state.tag = 1;
    state.shape = 0;
    state.mass = kDensity * library[0].volume;
    state.inertia = kDensity * library[0].unit_inertia;
    state.position = Vector3d(0, 0, kRadius);  // resting on z = 0
  }
  double moment() const { return state.inertia.x(); }
  double energy(const Vector3d& gravity) const {
    return 0.5 * state.mass * state.velocity.squaredNorm() +
           0.5 * moment() * state.angular_velocity.squaredNorm() - state.mass * gravity.dot(state.position);
  }
};

// `steps` steps of the fix's scheme against the floor z = 0 under `gravity` (a tilted
// gravity is an incline), friction mu, Siconos' error driven to 1e-14.
void run(Sphere& s, const Vector3d& gravity, double mu, double h, double theta, int steps) {
  GrainStepOptions options;
  options.friction = mu;
  options.solver.tolerance = 1e-14;
  options.solver.max_iterations = 1000;
  options.solver.theta = theta;
  std::vector<PlaneWall> walls(1);  // the floor: through 0, normal +z
  walls[0].friction = mu;
  GrainImpulseMemory memory;
  for (int k = 0; k < steps; ++k) {
    GrainState& g = s.state;
    g.force = g.mass * gravity;
    const GrainStepResult r = grain_step({g}, s.library, walls, h, options, (std::uint64_t)k, memory);
    ASSERT_FALSE(r.stats.hit_iteration_cap) << "step " << k;
    const Vector3d momentum_begin = s.moment() * g.angular_velocity;  // a sphere: L = I ω in any frame
    const Vector3d momentum_end = s.moment() * r.angular_velocities[0];
    const GrainPose pose = advance_grain_pose({g.position, g.orientation}, g.inertia, g.velocity, r.velocities[0],
                                              momentum_begin, momentum_end, h, theta);
    g.position = pose.position;
    g.orientation = pose.orientation;
    g.velocity = r.velocities[0];
    g.angular_velocity = r.angular_velocities[0];
  }
}

Vector3d incline_gravity(double alpha) { return Vector3d(std::sin(alpha), 0.0, -std::cos(alpha)); }

}  // namespace

TEST(NscdRolling, SphereRollsDownAnInclineAtFiveSeventhsOfGSinAlpha) {
  const double alpha = 30.0 * kPi / 180.0, h = 1e-3;
  const int steps = 2000;
  for (double theta : {1.0, 0.5}) {
    Sphere s;
    const Vector3d gravity = incline_gravity(alpha);
    const double E0 = s.energy(gravity);
    run(s, gravity, 0.5, h, theta, steps);  // μ = 0.5 > (2/7) tan 30° = 0.165
    const double T = steps * h, v = s.state.velocity.x();
    const double v_exact = 5.0 / 7.0 * std::sin(alpha) * T;
    const double energy_change = s.energy(gravity) - E0;
    const double theta_term = -(theta - 0.5) * h * s.state.mass * gravity.dot(s.state.velocity);
    std::printf("[rolling] theta %.1f: v/v_exact - 1 = %.1e, omega r/v - 1 = %.1e, z - r = %.1e, dE %.3e (theta term "
                "%.3e, difference / (m v^2) %.1e)\n",
                theta, v / v_exact - 1.0, s.state.angular_velocity.y() * kRadius / v - 1.0,
                s.state.position.z() - kRadius, energy_change, theta_term,
                (energy_change - theta_term) / (s.state.mass * v * v));
    // measured: 8.9e-16, 0, 0 and 1.1e-14 m v² (both θ)
    EXPECT_NEAR(v / v_exact, 1.0, 1e-14);
    EXPECT_NEAR(s.state.angular_velocity.y() * kRadius / v, 1.0, 1e-14);  // rolls: ω r = v
    EXPECT_NEAR(s.state.position.z(), kRadius, 1e-14);
    EXPECT_NEAR(energy_change, theta_term, 1e-13 * s.state.mass * v * v);
  }
}

TEST(NscdRolling, SphereSlidesAndSpinsUpBelowTheRollingFriction) {
  const double alpha = 30.0 * kPi / 180.0, mu = 0.1, h = 1e-3;  // μ < (2/7) tan α
  const int steps = 2000;
  Sphere s;
  run(s, incline_gravity(alpha), mu, h, 1.0, steps);
  const double T = steps * h;
  const double v_exact = (std::sin(alpha) - mu * std::cos(alpha)) * T;
  const double omega_exact = 2.5 * mu * std::cos(alpha) / kRadius * T;
  std::printf("[sliding] v/v_exact - 1 = %.1e, omega/omega_exact - 1 = %.1e\n", s.state.velocity.x() / v_exact - 1.0,
              s.state.angular_velocity.y() / omega_exact - 1.0);
  // measured: 2.2e-14 and 2.7e-14 (the round-off of 2000 increments)
  EXPECT_NEAR(s.state.velocity.x() / v_exact, 1.0, 2e-13);
  EXPECT_NEAR(s.state.angular_velocity.y() / omega_exact, 1.0, 2e-13);
}

TEST(NscdRolling, LaunchedSphereSlidesThenRollsAtFiveSeventhsOfItsSpeed) {
  const double v0 = 1.0, mu = 0.2, h = 1e-3;
  const double t_roll = 2.0 * v0 / (7.0 * mu);  // 1.43
  Sphere s;
  s.state.velocity = Vector3d(v0, 0, 0);
  const Vector3d gravity(0, 0, -1.0);
  run(s, gravity, mu, h, 1.0, 1000);  // t = 1 < t*: still sliding, v = v0 − μ g t
  std::printf("[launch] at t = 1 v - (v0 - mu g t) = %.1e\n", s.state.velocity.x() - (v0 - mu * 1.0));
  EXPECT_NEAR(s.state.velocity.x(), v0 - mu * 1.0, 2e-13);  // measured 2.2e-14
  run(s, gravity, mu, h, 1.0, 2000);  // t = 3 > t*: rolling
  const double v = s.state.velocity.x();
  std::printf("[launch] rolls at v/v0 = %.15f (5/7 = %.15f) after t* = %.3f, omega r - v = %.1e\n", v / v0, 5.0 / 7.0,
              t_roll, s.state.angular_velocity.y() * kRadius - v);
  EXPECT_NEAR(v / v0, 5.0 / 7.0, 2e-13);                          // measured 2.1e-14
  EXPECT_NEAR(s.state.angular_velocity.y() * kRadius, v, 1e-14);  // measured 0
}
