// NSCD Gauss–Seidel solver: a cube on a plane and on an incline, columns of cubes,
// impacts (restitution, gap anticipation, θ), a conveyor belt, reduced problems and the
// Siconos error, options and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/common/errors.h"
#include "core/nscd/nscd_solver.h"
#include "cube_lattice.h"

using namespace wiregrain;
using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Unit cubes (side 1, mass 1, inertia 1/6 about any axis through the centre).
constexpr double kMass = 1.0;
constexpr double kInertia = 1.0 / 6.0;

NscdBody cube_body(const Vector3d& velocity, const Vector3d& gravity, double h) {
  NscdBody body;
  body.inverse_mass = 1.0 / kMass;
  body.inverse_inertia = Matrix3d::Identity() / kInertia;
  body.velocity_begin = velocity;
  body.velocity_free = velocity + h * gravity;
  return body;
}

// Four contact points at the corners of the unit square face between body `lower`
// (−1: the ground) and body `upper` centred at z = face_z ∓ 1/2; normal +z.
void add_square_face(NscdStep& step, int lower, int upper, double face_z, double mu,
                     double gap = 0.0) {
  const Matrix3d frame = contact_frame(Vector3d::UnitZ());
  for (double x : {-0.5, 0.5}) {
    for (double y : {-0.5, 0.5}) {
      NscdContact contact;
      contact.body_a = lower;
      contact.body_b = upper;
      contact.friction = mu;
      contact.gap = gap;
      contact.jacobian_b = contact_jacobian(frame, Vector3d(x, y, -0.5), +1.0);
      if (lower >= 0) contact.jacobian_a = contact_jacobian(frame, Vector3d(x, y, 0.5), -1.0);
      step.contacts.push_back(contact);
      (void)face_z;
    }
  }
}

// A column of n unit cubes on the ground, at rest, under gravity (0, 0, −g).
NscdStep cube_column(int n, double h, double g, double mu) {
  NscdStep step;
  step.time_step = h;
  for (int k = 0; k < n; ++k) {
    step.bodies.push_back(cube_body(Vector3d::Zero(), Vector3d(0.0, 0.0, -g), h));
    add_square_face(step, k - 1, k, k, mu);
  }
  return step;
}

// Sum of the world-frame impulses of contacts [first, first + count).
Vector3d world_impulse_sum(const NscdStepResult& result, int first, int count) {
  const Matrix3d frame = contact_frame(Vector3d::UnitZ());
  Vector3d sum = Vector3d::Zero();
  for (int c = first; c < first + count; ++c) sum += frame * result.contacts.impulses[c];
  return sum;
}

// Largest relative error of the interface loads of cube_column(n, h, g, ·): the normal
// impulses summed over the interface under cube j must be (n − j) m g h.
double worst_column_load_error(const NscdStepResult& result, int n, double g, double h) {
  double worst = 0.0;
  for (int j = 0; j < n; ++j) {
    const double expected = (n - j) * kMass * g * h;
    worst = std::max(worst, std::abs(world_impulse_sum(result, 4 * j, 4)[2] - expected) / expected);
  }
  return worst;
}

double largest_speed(const NscdStepResult& result) {
  double v_max = 0.0;
  for (const Vector3d& v : result.velocities) v_max = std::max(v_max, v.norm());
  return v_max;
}

// Converged to round-off on the impulse increment.
SolverSettings tight(double tolerance = 1e-13) {
  SolverSettings options;
  options.tolerance = tolerance;
  options.measure = ConvergenceMeasure::increment;
  options.max_iterations = 100000;
  return options;
}

}  // namespace

// A cube at rest on a frictional plane, 4 corner contacts: the normal impulses sum to
// m g h, the tangential ones to zero, and the cube stays at rest.
TEST(NscdBox, RestingOnPlane) {
  const double h = 1e-3, g = 9.81;
  NscdStep step = cube_column(1, h, g, 0.5);
  const NscdStepResult result = solve_nscd_step(step, tight());
  const Vector3d sum = world_impulse_sum(result, 0, 4);
  EXPECT_NEAR(sum[2], kMass * g * h, 1e-12 * kMass * g * h);
  EXPECT_NEAR(sum[0], 0.0, 1e-15);
  EXPECT_NEAR(sum[1], 0.0, 1e-15);
  EXPECT_LT(result.velocities[0].norm(), 1e-13);
  EXPECT_LT(result.angular_velocities[0].norm(), 1e-13);
  EXPECT_FALSE(result.contacts.report.hit_iteration_cap);
  EXPECT_LT(result.contacts.report.siconos_error, 1e-10);
  for (const Vector3d& r : result.contacts.impulses) EXPECT_GE(r[0], 0.0);
}

// On an incline of angle α (gravity tilted in the plane's frame), from rest, over one
// step: for tan α < μ the cube sticks (zero velocity, impulses m g h (sin α, cos α));
// for tan α > μ it slides with acceleration g (sin α − μ cos α), without rotating.
TEST(NscdBox, Incline) {
  const double h = 1e-3, g = 9.81, mu = 0.5;
  for (double degrees : {10.0, 20.0, 26.0, 27.0, 35.0, 60.0}) {
    const double alpha = degrees * kPi / 180.0;
    const Vector3d gravity(g * std::sin(alpha), 0.0, -g * std::cos(alpha));
    NscdStep step;
    step.time_step = h;
    step.bodies.push_back(cube_body(Vector3d::Zero(), gravity, h));
    add_square_face(step, -1, 0, 0.0, mu);
    const NscdStepResult result = solve_nscd_step(step, tight());
    const Vector3d sum = world_impulse_sum(result, 0, 4);
    EXPECT_NEAR(sum[2], kMass * g * std::cos(alpha) * h, 1e-12 * g * h) << degrees;
    if (std::tan(alpha) < mu) {
      EXPECT_LT(result.velocities[0].norm(), 1e-13) << degrees;
      EXPECT_NEAR(sum[0], -kMass * g * std::sin(alpha) * h, 1e-12 * g * h) << degrees;
      // The tangential split among the 4 points is not unique; GS may leave some of them
      // on the cone boundary (counted as slide with u_t = 0), none open.
      EXPECT_EQ(result.contacts.report.open, 0) << degrees;
    } else {
      const double expected = g * (std::sin(alpha) - mu * std::cos(alpha)) * h;
      EXPECT_NEAR(result.velocities[0][0], expected, 1e-10 * expected) << degrees;
      EXPECT_NEAR(result.velocities[0][1], 0.0, 1e-14) << degrees;
      EXPECT_NEAR(result.velocities[0][2], 0.0, 1e-14) << degrees;
      EXPECT_LT(result.angular_velocities[0].norm(), 1e-13) << degrees;
      EXPECT_EQ(result.contacts.report.slide, 4) << degrees;
    }
  }
}

// Sliding continues over many steps with warm starts: v_n = n g (sin α − μ cos α) h, and
// the warm-started solves need few sweeps.
TEST(NscdBox, SlidingOverManySteps) {
  const double h = 1e-3, g = 9.81, mu = 0.4, alpha = 40.0 * kPi / 180.0;
  const Vector3d gravity(g * std::sin(alpha), 0.0, -g * std::cos(alpha));
  Vector3d v = Vector3d::Zero(), omega = Vector3d::Zero();
  std::vector<Vector3d> warm;
  int iterations = 0, last_iterations = 0;
  const int steps = 200;
  for (int n = 0; n < steps; ++n) {
    NscdStep step;
    step.time_step = h;
    NscdBody body = cube_body(v, gravity, h);
    body.angular_velocity_begin = body.angular_velocity_free = omega;
    step.bodies.push_back(body);
    add_square_face(step, -1, 0, 0.0, mu);
    const NscdStepResult result = solve_nscd_step(step, tight(1e-12), warm);
    v = result.velocities[0];
    omega = result.angular_velocities[0];
    warm = result.contacts.impulses;
    iterations += result.contacts.report.iterations;
    last_iterations = result.contacts.report.iterations;
  }
  const double expected = steps * g * (std::sin(alpha) - mu * std::cos(alpha)) * h;
  EXPECT_NEAR(v[0], expected, 1e-10 * expected);
  EXPECT_LT(std::abs(v[2]) + omega.norm(), 1e-12);
  std::printf("  sliding 200 steps: %d sweeps in all, %d in the last step\n", iterations,
              last_iterations);
  EXPECT_LE(last_iterations, 3);
}

// Columns of N cubes (4 points per interface) at rest: the normal impulse summed over the
// interface under the k-th cube from the top is k m g h, checked to 1e-4 relative
// with a Siconos-error tolerance of 1e-6 (default measure: increment, then the Siconos
// error; 1e-5 leaves load errors up to 2e-4 at N = 20). Sweep counts per order are
// printed; the forward order is slow on tall frictional columns (N = 20: ~2.3e5 sweeps,
// about a second).
TEST(NscdStack, ColumnInterfaceLoads) {
  const double h = 1e-3, g = 9.81;
  for (int n : {1, 5, 20}) {
    for (SweepOrder order : {SweepOrder::forward, SweepOrder::alternating, SweepOrder::random, SweepOrder::coloured}) {
      NscdStep step = cube_column(n, h, g, 0.5);
      SolverSettings options;
      options.tolerance = 1e-6;
      options.max_iterations = 400000;
      options.order = order;
      const NscdStepResult result = solve_nscd_step(step, options);
      const NscdReport& report = result.contacts.report;
      ASSERT_FALSE(report.hit_iteration_cap) << n;
      const double worst = worst_column_load_error(result, n, g, h);
      EXPECT_LE(worst, 1e-4) << "N " << n;
      const double v_max = largest_speed(result);
      std::printf("  N=%2d %-11s sweeps %5d increment %.2e siconos error %.2e worst load "
                  "error %.2e max |v| %.1e\n",
                  n,
                  order == SweepOrder::forward       ? "forward"
                  : order == SweepOrder::alternating ? "alternating"
                  : order == SweepOrder::random      ? "random"
                                                     : "coloured",
                  report.iterations, report.increment, report.siconos_error, worst, v_max);
    }
  }
}

// Freezing (SolverSettings::freeze) on the columns of ColumnInterfaceLoads (random order,
// Siconos error 1e-6): contacts that have settled are skipped for 5 sweeps, yet the loads
// are k m g h to 1e-4 as without it, the stop still at a Siconos error within the
// tolerance (computed on every contact).
TEST(NscdStack, FreezingKeepsTheColumnLoads) {
  const double h = 1e-3, g = 9.81;
  for (int n : {5, 20}) {
    SolverSettings options;
    options.tolerance = 1e-6;
    options.max_iterations = 400000;
    options.freeze = 5;
    const NscdStepResult result = solve_nscd_step(cube_column(n, h, g, 0.5), options);
    const NscdReport& report = result.contacts.report;
    ASSERT_FALSE(report.hit_iteration_cap) << n;
    EXPECT_LE(worst_column_load_error(result, n, g, h), 1e-4) << "N " << n;
    EXPECT_LE(report.siconos_error, options.tolerance) << "N " << n;
    EXPECT_GT(report.frozen_updates, 0) << "N " << n;
    std::printf("  N=%2d freeze 5: sweeps %d, updates skipped %ld of %ld\n", n, report.iterations,
                report.frozen_updates, long(report.iterations) * 4 * n);
  }
}

// 15 steps of a 20-cube column at the default tolerance (1e-4), the bodies carrying their
// end-of-step velocities into the next step: warm-starting every step from the last
// impulses (persistent contacts) takes less than half the sweeps of cold starts, and
// most warm-started steps need only a few sweeps. (Residual velocities of the slow
// bending-like modes of the welded column make occasional steps expensive.)
TEST(NscdStack, WarmStart) {
  const double h = 1e-3, g = 9.81;
  const int n = 20;
  long totals[2] = {0, 0};
  int cheap_warm_steps = 0;
  for (int warm = 0; warm < 2; ++warm) {
    NscdStep step = cube_column(n, h, g, 0.5);
    SolverSettings options;
    options.max_iterations = 100000;
    std::vector<Vector3d> impulses;
    for (int k = 0; k < 15; ++k) {
      const NscdStepResult result = solve_nscd_step(step, options, impulses);
      ASSERT_FALSE(result.contacts.report.hit_iteration_cap);
      totals[warm] += result.contacts.report.iterations;
      if (warm && result.contacts.report.iterations <= 100) ++cheap_warm_steps;
      for (int b = 0; b < n; ++b) {
        step.bodies[b].velocity_begin = result.velocities[b];
        step.bodies[b].velocity_free = result.velocities[b] + h * Vector3d(0.0, 0.0, -g);
        step.bodies[b].angular_velocity_begin = step.bodies[b].angular_velocity_free =
            result.angular_velocities[b];
      }
      if (warm) impulses = result.contacts.impulses;
      if (k == 14) {
        for (int j = 0; j < n; ++j) {
          const double expected = (n - j) * kMass * g * h;
          EXPECT_NEAR(world_impulse_sum(result, 4 * j, 4)[2], expected, 1e-3 * expected);
        }
      }
    }
  }
  std::printf("  N=20, 15 steps: cold starts %ld sweeps, warm starts %ld sweeps (%d steps "
              "with <= 100)\n",
              totals[0], totals[1], cheap_warm_steps);
  EXPECT_LT(totals[1], totals[0] / 2);
  EXPECT_GE(cheap_warm_steps, 8);
}

// Method subspace on the same columns, cold start: the closed contacts solved together
// carry the loads k m g h to 1e-10 in a handful of sweeps for N = 20 and 60, where plain
// Gauss–Seidel (random order) stops at its cap of 10000 sweeps: 1.5e-7 off at N = 20,
// 1e-2 at N = 60.
TEST(NscdSubspace, TallColumnFromColdStart) {
  const double h = 1e-3, g = 9.81;
  for (int n : {20, 60}) {
    for (SolverMethod method : {SolverMethod::subspace, SolverMethod::gauss_seidel}) {
      NscdStep step = cube_column(n, h, g, 0.5);
      SolverSettings options;
      options.tolerance = 1e-12;
      options.max_iterations = 10000;
      options.method = method;
      const NscdStepResult result = solve_nscd_step(step, options);
      const NscdReport& report = result.contacts.report;
      const double worst = worst_column_load_error(result, n, g, h);
      const double v_max = largest_speed(result);
      std::printf("  N=%2d %-12s sweeps %5d stick solves %d (kept %d) worst load error %.2e max |v| %.1e\n", n,
                  method == SolverMethod::subspace ? "subspace" : "gauss_seidel", report.iterations,
                  report.subspace_solves, report.subspace_accepted, worst, v_max);
      if (method == SolverMethod::subspace) {
        EXPECT_FALSE(report.hit_iteration_cap);
        EXPECT_LE(report.iterations, 20);
        EXPECT_LT(worst, 1e-10);
        EXPECT_LT(v_max, 1e-8 * g * h);
        EXPECT_LT(report.siconos_error, 1e-12);
      } else {
        EXPECT_TRUE(report.hit_iteration_cap);
        if (n == 60) EXPECT_GT(worst, 1e-3);
      }
    }
  }
}

// Where contacts slide, the stick solve comes out of the cones: on an incline steeper
// than the friction angle the cube still slides at g (sin α − μ cos α) h after one step
// (the exact value of NscdBox.Incline), and sticks below it.
TEST(NscdSubspace, InclineSlidesAndSticksAsGaussSeidel) {
  const double h = 1e-3, g = 9.81, mu = 0.5;
  for (double degrees : {20.0, 26.0, 27.0, 35.0, 60.0}) {
    const double alpha = degrees * kPi / 180.0;
    NscdStep step;
    step.time_step = h;
    step.bodies.push_back(cube_body(Vector3d::Zero(), Vector3d(g * std::sin(alpha), 0.0, -g * std::cos(alpha)), h));
    add_square_face(step, -1, 0, 0.0, mu);
    SolverSettings options;
    options.tolerance = 1e-13;
    options.max_iterations = 100000;
    options.method = SolverMethod::subspace;
    const NscdStepResult result = solve_nscd_step(step, options);
    EXPECT_FALSE(result.contacts.report.hit_iteration_cap) << degrees;
    const double expected = std::tan(alpha) < mu ? 0.0 : g * (std::sin(alpha) - mu * std::cos(alpha)) * h;
    EXPECT_NEAR(result.velocities[0][0], expected, 1e-10 * g * h) << degrees;
    EXPECT_NEAR(result.velocities[0][2], 0.0, 1e-13) << degrees;
    EXPECT_LT(result.angular_velocities[0].norm(), 1e-10) << degrees;
  }
}

// The backoff carried between solves: while skip > 0 a solve makes no stick solve and
// counts skip down; a kept stick solve (a 20-cube column from a cold start) sets the
// wait back to 0.
TEST(NscdSubspace, BackoffSkipsSolvesAndAKeptOneResetsIt) {
  const double h = 1e-3, g = 9.81;
  SolverSettings options;
  options.method = SolverMethod::subspace;
  options.max_iterations = 10000;
  StickSolveBackoff backoff;
  backoff.skip = 2;
  backoff.wait = 2;
  for (int expected_skip : {1, 0}) {
    const NscdStepResult skipped = solve_nscd_step(cube_column(20, h, g, 0.5), options, {}, &backoff);
    EXPECT_EQ(skipped.contacts.report.subspace_solves, 0);
    EXPECT_EQ(backoff.skip, expected_skip);
    EXPECT_EQ(backoff.wait, 2);
  }
  const NscdStepResult solved = solve_nscd_step(cube_column(20, h, g, 0.5), options, {}, &backoff);
  EXPECT_GE(solved.contacts.report.subspace_accepted, 1);
  EXPECT_EQ(backoff.skip, 0);
  EXPECT_EQ(backoff.wait, 0);
  EXPECT_LT(worst_column_load_error(solved, 20, g, h), 1e-10);
}

// The closing stick solve of a converged solve (header) is made unless the Siconos error
// is already at most subspace_closing × tolerance. A 20-cube column warm-started from its
// exact loads scaled by 1 + 1e-6 (the next step of a column at rest that something
// disturbed) converges in the first sweep, to an error between 1e-12 and the tolerance:
// with subspace_closing 0 (the default) the closing solve makes every interface carry the
// statics, W_i = (n − i) m g h, to round-off; with 1 none is made and the loads are left
// within the tolerance only; with 1e-9 (a threshold below that error) it is made. The
// same problem solved again reuses the factors (no factorisation).
TEST(NscdSubspace, ClosingStickSolveOnlyAboveItsShareOfTheTolerance) {
  const double h = 1e-3, g = 9.81;
  const int n = 20;
  const auto options_with = [](double closing) {
    SolverSettings options;
    options.method = SolverMethod::subspace;
    options.max_iterations = 10000;
    options.subspace_closing = closing;
    return options;
  };
  SolverSettings exact = options_with(0.0);
  exact.tolerance = 1e-13;
  const NscdStepResult reference = solve_nscd_step(cube_column(n, h, g, 0.5), exact);
  ASSERT_LT(worst_column_load_error(reference, n, g, h), 1e-10);
  std::vector<Vector3d> disturbed = reference.contacts.impulses;
  for (Vector3d& r : disturbed) r *= 1.0 + 1e-6;

  for (double closing : {0.0, 1.0, 1e-9}) {
    const NscdStepResult result = solve_nscd_step(cube_column(n, h, g, 0.5), options_with(closing), disturbed);
    const NscdReport& report = result.contacts.report;
    const double worst = worst_column_load_error(result, n, g, h);
    std::printf("  subspace_closing %g: sweeps %d, stick solves %d (kept %d), Siconos error %.1e, worst load error %.1e\n",
                closing, report.iterations, report.subspace_solves, report.subspace_accepted, report.siconos_error, worst);
    EXPECT_EQ(report.iterations, 1) << closing;
    EXPECT_LE(report.siconos_error, 1e-4) << closing;
    if (closing == 1.0) {
      EXPECT_EQ(report.subspace_solves, 0);
      EXPECT_GT(worst, 1e-9);  // what the closing solve removes
    } else {
      EXPECT_EQ(report.subspace_accepted, 1) << closing;
      EXPECT_LT(worst, 1e-10) << closing;
    }
  }
  const NscdStepResult again = solve_nscd_step(cube_column(n, h, g, 0.5), options_with(0.0), disturbed);
  EXPECT_EQ(again.contacts.report.subspace_solves, 1);
  EXPECT_EQ(again.contacts.report.subspace_factorizations, 0);
}

// Each subspace option outside its range is refused naming its keyword.
TEST(NscdSubspace, OptionsOutOfRangeNameTheirKeyword) {
  struct Case {
    const char* keyword;
    double SolverSettings::*option;
    std::vector<double> bad;
  };
  for (const Case& c : {Case{"subspace_regularization", &SolverSettings::subspace_regularization, {0.0, -1e-9, 1.0, std::nan("")}},
                        Case{"subspace_closing", &SolverSettings::subspace_closing, {-0.1, 1.5, std::nan("")}}}) {
    for (double bad : c.bad) {
      SolverSettings options;
      options.*c.option = bad;
      try {
        options.validate();
        ADD_FAILURE() << c.keyword << " " << bad;
      } catch (const InvalidArgument& e) {
        EXPECT_EQ(e.argument(), c.keyword);
      }
    }
  }
}

// A cube falling flat onto the ground. Gap anticipation: with gap g > 0 and
// g + h v_free < 0 it arrives exactly: v_z = −g/h (θ = 1). With restitution e the impact
// law u_n ≥ −e u_n^k applies: v_z = e v0. θ = 1/2: the predicted gap
// g + h (u^k + u^{k+1})/2 is zero at the end of the step.
TEST(NscdImpact, GapAnticipationRestitutionTheta) {
  const double h = 1e-3, grav = 9.81, v0 = 3.0, gap = 1e-3;
  auto falling = [&]() {
    NscdStep step;
    step.time_step = h;
    step.bodies.push_back(cube_body(Vector3d(0.0, 0.0, -v0), Vector3d(0.0, 0.0, -grav), h));
    add_square_face(step, -1, 0, 0.0, 0.5, gap);
    return step;
  };
  const SolverSettings options = tight();
  MoreauJeanLaw law;
  const auto with_law = [&](NscdStep step) {
    step.law = law;
    return step;
  };
  NscdStepResult result = solve_nscd_step(with_law(falling()), options);
  EXPECT_NEAR(result.velocities[0][2], -gap / h, 1e-12);
  EXPECT_LT(result.max_predicted_penetration, 1e-15);

  law.restitution = 0.5;
  result = solve_nscd_step(with_law(falling()), options);
  EXPECT_NEAR(result.velocities[0][2], 0.5 * v0, 1e-12);

  // Far from the ground (no impact predicted): restitution does nothing, free flight.
  NscdStep far = falling();
  for (NscdContact& c : far.contacts) c.gap = 1.0;
  result = solve_nscd_step(with_law(far), options);
  EXPECT_NEAR(result.velocities[0][2], -v0 - grav * h, 1e-15);
  EXPECT_EQ(result.contacts.report.open, 4);

  law.restitution = 0.0;
  law.theta = 0.5;
  result = solve_nscd_step(with_law(falling()), options);
  // g + h (−v0 + v)/2 = 0.
  EXPECT_NEAR(result.velocities[0][2], v0 - 2.0 * gap / h, 1e-12);
  EXPECT_LT(result.max_predicted_penetration, 1e-15);

  // Overlap g < 0 with θ = 1 at rest: pushed out at −g/h.
  law.theta = 1.0;
  NscdStep overlap = cube_column(1, h, grav, 0.5);
  for (NscdContact& c : overlap.contacts) c.gap = -1e-5;
  result = solve_nscd_step(with_law(overlap), options);
  EXPECT_NEAR(result.velocities[0][2], 1e-5 / h, 1e-12);
  EXPECT_DOUBLE_EQ(result.max_overlap, 1e-5);
}

// A cube at rest on a conveyor belt moving at V along x (the belt's velocity enters as
// the contact's velocity offset, u = v_cube − V): friction accelerates it at μ g.
TEST(NscdBox, ConveyorBelt) {
  const double h = 1e-3, g = 9.81, mu = 0.3, belt = 1.0;
  NscdStep step = cube_column(1, h, g, mu);
  const Matrix3d frame = contact_frame(Vector3d::UnitZ());
  for (NscdContact& c : step.contacts) c.velocity_offset = -frame.transpose() * Vector3d(belt, 0, 0);
  const NscdStepResult result = solve_nscd_step(step, tight());
  EXPECT_NEAR(result.velocities[0][0], mu * g * h, 1e-12 * mu * g * h);
  EXPECT_NEAR(result.velocities[0][2], 0.0, 1e-14);
}

// A plate of infinite mass (inverse mass 0, a body in the list) rising at V under a cube
// resting on it: the cube leaves with the plate's velocity (perfectly inelastic), the
// plate's velocity is untouched. No contacts at all: free flight.
TEST(NscdBox, KinematicPlateAndNoContacts) {
  const double h = 1e-3, g = 9.81, V = 0.3;
  NscdStep step;
  step.time_step = h;
  NscdBody plate;
  plate.velocity_begin = plate.velocity_free = Vector3d(0.0, 0.0, V);
  step.bodies.push_back(plate);
  step.bodies.push_back(cube_body(Vector3d::Zero(), Vector3d(0.0, 0.0, -g), h));
  add_square_face(step, 0, 1, 0.0, 0.5);
  const NscdStepResult result = solve_nscd_step(step, tight());
  EXPECT_NEAR(result.velocities[1][2], V, 1e-13);
  EXPECT_EQ(result.velocities[0], Vector3d(0.0, 0.0, V));
  EXPECT_NEAR(world_impulse_sum(result, 0, 4)[2], kMass * (V + g * h), 1e-13);

  step.contacts.clear();
  const NscdStepResult free = solve_nscd_step(step, SolverSettings());
  EXPECT_EQ(free.velocities[1], Vector3d(0.0, 0.0, -g * h));
  EXPECT_EQ(free.contacts.report.iterations, 1);
  EXPECT_FALSE(free.contacts.report.hit_iteration_cap);
}

namespace {

// Random bodies and contacts with random frames, lever arms, masses, inertias.
NscdStep random_step(std::mt19937_64& rng, int bodies, int contacts) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0), positive(0.5, 2.0), friction(0.1, 1.0);
  NscdStep step;
  step.time_step = 1e-3;
  for (int b = 0; b < bodies; ++b) {
    NscdBody body;
    body.inverse_mass = positive(rng);
    Matrix3d A;
    for (int i = 0; i < 9; ++i) A(i / 3, i % 3) = unit(rng);
    body.inverse_inertia = A * A.transpose() + 0.5 * Matrix3d::Identity();
    body.velocity_begin = 0.1 * Vector3d(unit(rng), unit(rng), unit(rng));
    body.velocity_free = body.velocity_begin + Vector3d(0.0, 0.0, -9.81e-3);
    body.angular_velocity_begin = 0.1 * Vector3d(unit(rng), unit(rng), unit(rng));
    body.angular_velocity_free = body.angular_velocity_begin;
    step.bodies.push_back(body);
  }
  std::uniform_int_distribution<int> pick(-1, bodies - 1);
  for (int c = 0; c < contacts; ++c) {
    NscdContact contact;
    contact.body_b = static_cast<int>(rng() % bodies);
    do contact.body_a = pick(rng); while (contact.body_a == contact.body_b);
    const Matrix3d frame = contact_frame(Vector3d(unit(rng), unit(rng), unit(rng)));
    contact.jacobian_b = contact_jacobian(frame, 0.5 * Vector3d(unit(rng), unit(rng), unit(rng)), 1.0);
    if (contact.body_a >= 0) {
      contact.jacobian_a = contact_jacobian(frame, 0.5 * Vector3d(unit(rng), unit(rng), unit(rng)), -1.0);
    }
    contact.friction = friction(rng);
    contact.gap = 1e-4 * unit(rng);
    step.contacts.push_back(contact);
  }
  return step;
}

}  // namespace

// The assembled reduced problem is W = H M⁻¹ Hᵀ computed from the global matrices, and
// solve_reduced on it reproduces solve_nscd_step (same sweep) to round-off.
TEST(NscdReduced, AssemblyAndBodySolverAgree) {
  std::mt19937_64 rng(99);
  const NscdStep step = random_step(rng, 8, 30);
  SolverSettings options;
  options.tolerance = 1e-12;
  options.max_iterations = 20000;
  const ReducedProblem reduced = assemble_reduced(step);

  const int nb = 8, nc = 30;
  MatrixXd H = MatrixXd::Zero(3 * nc, 6 * nb), Minv = MatrixXd::Zero(6 * nb, 6 * nb);
  for (int c = 0; c < nc; ++c) {
    const NscdContact& k = step.contacts[c];
    H.block<3, 6>(3 * c, 6 * k.body_b) += k.jacobian_b;
    if (k.body_a >= 0) H.block<3, 6>(3 * c, 6 * k.body_a) += k.jacobian_a;
  }
  for (int b = 0; b < nb; ++b) {
    Minv.block<3, 3>(6 * b, 6 * b) = step.bodies[b].inverse_mass * Matrix3d::Identity();
    Minv.block<3, 3>(6 * b + 3, 6 * b + 3) = step.bodies[b].inverse_inertia;
  }
  const MatrixXd W = H * Minv * H.transpose();
  EXPECT_LT((reduced.W.to_dense() - W).norm(), 1e-13 * W.norm());

  const NscdStepResult bodies = solve_nscd_step(step, options);
  const ContactSolution direct = solve_reduced(reduced, options);
  double difference = 0.0, size = 0.0;
  for (int c = 0; c < nc; ++c) {
    difference = std::max(difference, (bodies.contacts.impulses[c] - direct.impulses[c]).norm());
    size = std::max(size, direct.impulses[c].norm());
  }
  EXPECT_LT(difference, 1e-12 * size);
  EXPECT_EQ(bodies.contacts.report.iterations, direct.report.iterations);
  EXPECT_NEAR(bodies.contacts.report.siconos_error, direct.report.siconos_error, 1e-12);
  EXPECT_LT(siconos_error(reduced, direct.impulses), 1e-10);
}

// A random dense reduced problem (W = A Aᵀ/m + I/2, every block non-zero): each sweep
// order and each method converges, with the natural-map (Siconos) measure, below the
// tolerance (siconos_error is checked by hand in SiconosErrorByHand).
TEST(NscdReduced, RandomDenseProblemConverges) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), friction(0.1, 1.0);
  const int n = 20, m = 3 * n;
  MatrixXd A(m, m);
  for (int i = 0; i < m * m; ++i) A(i / m, i % m) = unit(rng);
  ReducedProblem problem;
  problem.W = BlockSparseMatrix3::from_dense(A * A.transpose() / m + 0.5 * MatrixXd::Identity(m, m));
  EXPECT_EQ(problem.W.stored_blocks(), long(n) * n);
  problem.q.resize(m);
  for (int i = 0; i < m; ++i) problem.q[i] = unit(rng);
  for (int c = 0; c < n; ++c) problem.mu.push_back(friction(rng));
  for (SolverMethod method : {SolverMethod::gauss_seidel, SolverMethod::subspace}) {
    for (SweepOrder order : {SweepOrder::forward, SweepOrder::alternating, SweepOrder::random}) {
      SolverSettings options;
      options.tolerance = 1e-8;
      options.measure = ConvergenceMeasure::natural_map;
      options.order = order;
      options.method = method;
      const ContactSolution s = solve_reduced(problem, options);
      EXPECT_FALSE(s.report.hit_iteration_cap);
      EXPECT_LT(s.report.siconos_error, 1e-8);
      EXPECT_LT(siconos_error(problem, s.impulses), 1e-8);
      std::printf("  dense n=%d %s: %d sweeps, open %d stick %d slide %d, stick solves %d (kept %d), error %.2e\n",
                  n, method == SolverMethod::subspace ? "subspace" : "gauss_seidel", s.report.iterations,
                  s.report.open, s.report.stick, s.report.slide, s.report.subspace_solves,
                  s.report.subspace_accepted, s.report.siconos_error);
      EXPECT_GT(s.report.open + s.report.stick + s.report.slide, 0);
    }
  }
}

// Siconos' measure by hand for one contact. W = I: r = 0, q = (−2, 0, 0) gives u = q,
// r − proj(r − û) = −(2, 0, 0), error 2/max(‖q‖, ‖r‖, ‖u‖) = 1; the solution r = (2, 0, 0)
// gives 0. W = 10 I, q = (−2, 0, 0), r = (1, 0, 0): u = (8, 0, 0), r − û = (−7, 0, 0)
// projects to 0, residual ‖r‖ = 1, divided by max(2, 1, 8): 0.125.
TEST(NscdReduced, SiconosErrorByHand) {
  ReducedProblem p;
  p.W = BlockSparseMatrix3::from_dense(Matrix3d::Identity());
  p.q = Vector3d(-2.0, 0.0, 0.0);
  p.mu = {0.5};
  EXPECT_DOUBLE_EQ(siconos_error(p, {Vector3d::Zero()}), 1.0);
  EXPECT_DOUBLE_EQ(siconos_error(p, {Vector3d(2.0, 0.0, 0.0)}), 0.0);
  // Sliding u_t = (1, 0) with r = (1, −0.5, 0) on the cone: û = (μ·1, 1, 0) = (0.5, 1, 0),
  // r − û = (0.5, −1.5, 0) projects to ((0.5 + 0.75)/1.25, −0.5, 0) = r: zero residual.
  p.q = Vector3d(-1.0, 1.5, 0.0);
  EXPECT_NEAR(siconos_error(p, {Vector3d(1.0, -0.5, 0.0)}), 0.0, 1e-16);
  p.W = BlockSparseMatrix3::from_dense(10.0 * Matrix3d::Identity());
  p.q = Vector3d(-2.0, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(siconos_error(p, {Vector3d(1.0, 0.0, 0.0)}), 0.125);
}

// Options: the cap is reported with the residual; relaxation converges to the same loads;
// random order is reproducible from its seed; the increment-then-natural-map measure
// (Siconos' default) ends below the tolerance in the natural-map error.
TEST(SolverSettings, CapRelaxationSeedMeasure) {
  const double h = 1e-3, g = 9.81;
  SolverSettings options;
  options.tolerance = 1e-6;
  options.max_iterations = 5;
  NscdStepResult result = solve_nscd_step(cube_column(5, h, g, 0.5), options);
  EXPECT_TRUE(result.contacts.report.hit_iteration_cap);
  EXPECT_EQ(result.contacts.report.iterations, 5);
  EXPECT_GT(result.contacts.report.residual, 1e-6);

  options.max_iterations = 50000;
  options.relaxation = 0.8;
  result = solve_nscd_step(cube_column(5, h, g, 0.5), options);
  EXPECT_FALSE(result.contacts.report.hit_iteration_cap);
  EXPECT_NEAR(world_impulse_sum(result, 0, 4)[2], 5 * g * h, 1e-4 * 5 * g * h);

  options.relaxation = 1.0;
  options.order = SweepOrder::random;
  options.seed = 7;
  const NscdStepResult a = solve_nscd_step(cube_column(5, h, g, 0.5), options);
  const NscdStepResult b = solve_nscd_step(cube_column(5, h, g, 0.5), options);
  EXPECT_EQ(a.contacts.report.iterations, b.contacts.report.iterations);
  for (int c = 0; c < 20; ++c) EXPECT_EQ(a.contacts.impulses[c], b.contacts.impulses[c]);

  options.order = SweepOrder::forward;
  options.measure = ConvergenceMeasure::increment_then_natural_map;
  options.tolerance = 1e-4;
  result = solve_nscd_step(cube_column(5, h, g, 0.5), options);
  EXPECT_LT(result.contacts.report.siconos_error, 1e-4);
  EXPECT_DOUBLE_EQ(result.contacts.report.residual, result.contacts.report.siconos_error);
}

TEST(SolverSettings, BadInput) {
  auto expect_argument = [](const std::string& argument, auto&& call) {
    try {
      call();
      ADD_FAILURE() << "accepted bad " << argument;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.argument(), argument) << e.what();
    }
  };
  const NscdStep good = cube_column(2, 1e-3, 9.81, 0.5);
  SolverSettings options;
  MoreauJeanLaw law;
  expect_argument("theta", [&] { law.theta = 0.3; law.validate(); });
  law = MoreauJeanLaw();
  expect_argument("relaxation", [&] { options.relaxation = 2.0; options.validate(); });
  options = SolverSettings();
  expect_argument("restitution", [&] { law.restitution = -0.1; law.validate(); });
  law = MoreauJeanLaw();
  expect_argument("overlap_recovery", [&] { law.overlap_recovery = 1.5; law.validate(); });
  law = MoreauJeanLaw();
  expect_argument("overlap_speed", [&] { law.overlap_speed = -1.0; law.validate(); });
  law = MoreauJeanLaw();
  expect_argument("max_iterations", [&] { options.max_iterations = 0; options.validate(); });
  options = SolverSettings();
  expect_argument("freeze", [&] { options.freeze = -1; options.validate(); });
  options = SolverSettings();
  expect_argument("freeze", [&] {  // the increment alone would not see the frozen contacts
    options.freeze = 5;
    options.measure = ConvergenceMeasure::increment;
    options.validate();
  });
  options = SolverSettings();
  expect_argument("time_step", [&] {
    NscdStep s = good;
    s.time_step = -1.0;
    solve_nscd_step(s, options);
  });
  expect_argument("theta", [&] {  // the step's law is checked with the step
    NscdStep s = good;
    s.law.theta = 0.3;
    solve_nscd_step(s, options);
  });
  expect_argument("overlap_recovery", [&] {
    NscdStep s = good;
    s.law.overlap_recovery = -0.5;
    assemble_reduced(s);
  });
  expect_argument("contacts", [&] {
    NscdStep s = good;
    s.contacts[0].body_b = 2;
    solve_nscd_step(s, options);
  });
  expect_argument("contacts", [&] {  // between the ground and an infinite mass
    NscdStep s = good;
    s.bodies[0].inverse_mass = 0.0;
    s.bodies[0].inverse_inertia.setZero();
    solve_nscd_step(s, options);
  });
  expect_argument("contacts", [&] {
    NscdStep s = good;
    s.contacts[3].friction = -0.5;
    solve_nscd_step(s, options);
  });
  expect_argument("bodies", [&] {
    NscdStep s = good;
    s.bodies[1].velocity_free[0] = std::nan("");
    solve_nscd_step(s, options);
  });
  expect_argument("warm_start", [&] {
    solve_nscd_step(good, options, std::vector<Vector3d>(3, Vector3d::Zero()));
  });
  expect_argument("mu", [&] {
    ReducedProblem p;
    p.W = BlockSparseMatrix3::from_dense(Matrix3d::Identity());
    p.q = Vector3d(-1.0, 0.0, 0.0);
    solve_reduced(p, options);
  });
  expect_argument("W", [&] {
    ReducedProblem p;
    p.W = BlockSparseMatrix3(1);
    p.q = Vector3d(-1.0, 0.0, 0.0);
    p.mu = {0.3};
    solve_reduced(p, options);
  });
}

namespace {

// The body operator with the interface's own normal_velocity (velocity(c)[0], the whole u).
class WholeVelocityOperator final : public ContactOperator {
 public:
  explicit WholeVelocityOperator(ContactOperator& inner) : inner_(inner) {}
  int contact_count() const override { return inner_.contact_count(); }
  const LocalDelassus& delassus_block(int c) const override { return inner_.delassus_block(c); }
  double friction_coefficient(int c) const override { return inner_.friction_coefficient(c); }
  Vector3d velocity(int c) const override { return inner_.velocity(c); }
  void add_impulse(int c, const Vector3d& delta) override { inner_.add_impulse(c, delta); }
  double free_velocity_norm() const override { return inner_.free_velocity_norm(); }
  const BlockSparseMatrix3& delassus_matrix() override { return inner_.delassus_matrix(); }

 private:
  ContactOperator& inner_;
};

}  // namespace

// The sweep passes over a contact without impulse whose u_n ≥ 0 after reading u_n alone
// (ContactOperator::normal_velocity). On the body operator that u_n must be velocity(c)[0]
// to the bit whatever the impulses, and a solve must give, to the bit, the impulses of a
// solve on the same operator that reads the whole u instead (that solve also runs the
// sweep through the virtual interface, the first through the sweep bound statically to
// the body operator: the two instantiations of sweep_contacts agree). The pile: 4×4×3 cubes with
// jittered velocities and gaps (bench/cube_lattice.h), its contacts open, sticking and
// sliding.
TEST(NscdOperators, OpenContactTestReadsTheNormalVelocityToTheBit) {
  const NscdStep step = wiregrain_bench::cube_lattice(4, 4, 3, 7, 0.5, true);
  SolverSettings options;
  options.tolerance = 0.0;  // exactly max_iterations sweeps
  options.max_iterations = 60;
  const std::unique_ptr<ContactOperator> op = body_contact_operator(step);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> impulse(-1e-3, 1e-3);
  for (int round = 0; round < 3; ++round) {
    for (int c = 0; c < op->contact_count(); ++c) {
      ASSERT_EQ(op->normal_velocity(c), op->velocity(c)[0]) << "round " << round << ", contact " << c;
    }
    for (int c = round; c < op->contact_count(); c += 3) {
      op->add_impulse(c, Vector3d(impulse(rng), impulse(rng), impulse(rng)));
    }
  }

  const std::unique_ptr<ContactOperator> fast = body_contact_operator(step);
  const std::unique_ptr<ContactOperator> plain = body_contact_operator(step);
  WholeVelocityOperator whole(*plain);
  const ContactSolution a = solve_frictional_contact(*fast, options);
  const ContactSolution b = solve_frictional_contact(whole, options);
  EXPECT_GT(a.report.open, 0);
  EXPECT_GT(a.report.stick + a.report.slide, 0);
  ASSERT_EQ(a.impulses.size(), b.impulses.size());
  for (std::size_t c = 0; c < a.impulses.size(); ++c) {
    EXPECT_EQ(a.impulses[c], b.impulses[c]) << "contact " << c;
    EXPECT_EQ(a.states[c], b.states[c]) << "contact " << c;
  }
  EXPECT_EQ(a.report.iterations, b.report.iterations);
  EXPECT_EQ(a.report.siconos_error, b.report.siconos_error);
}
