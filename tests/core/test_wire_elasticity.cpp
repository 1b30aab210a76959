// Elastic wire: kernels against finite differences of their own energy, invariances,
// the Euler–Bernoulli continuum limit, a free vibration with the Gear integrator and
// the Verlet stability limit.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "core/common/errors.h"
#include "core/wire/gear_integrator.h"
#include "core/wire/wire_elasticity.h"

using namespace wiregrain;
using Eigen::Vector3d;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Coordinates rounded to multiples of 2^-40, so x ± h and x ± 2h are exact for the
// power-of-two steps h used below (|x| < 4 needs at most 43 significant bits).
Vector3d quantised(const Vector3d& x) {
  const double q = std::ldexp(1.0, 40);
  return Vector3d(std::round(x.x() * q) / q, std::round(x.y() * q) / q,
                  std::round(x.z() * q) / q);
}

// −∂U/∂x by the fourth-order central stencil (−U(+2h) + 8U(+h) − 8U(−h) + U(−2h)) / 12h.
std::vector<Vector3d> finite_difference_forces(
    std::vector<Vector3d> x, const std::function<double(const std::vector<Vector3d>&)>& energy,
    double h) {
  std::vector<Vector3d> f(x.size());
  for (std::size_t a = 0; a < x.size(); ++a) {
    for (int c = 0; c < 3; ++c) {
      const double x0 = x[a][c];
      double u[4];
      const double offsets[4] = {2.0, 1.0, -1.0, -2.0};
      for (int s = 0; s < 4; ++s) {
        x[a][c] = x0 + offsets[s] * h;
        u[s] = energy(x);
      }
      x[a][c] = x0;
      f[a][c] = -(-u[0] + 8.0 * u[1] - 8.0 * u[2] + u[3]) / (12.0 * h);
    }
  }
  return f;
}

double max_norm(const std::vector<Vector3d>& v) {
  double m = 0.0;
  for (const auto& x : v) m = std::max(m, x.norm());
  return m;
}

// Three nodes: x_j random, |e1|, |e2| in [0.15, 0.25], angle θ between e1 and e2.
std::vector<Vector3d> bend_configuration(std::mt19937& rng, double theta) {
  std::uniform_real_distribution<double> coord(-1.0, 1.0), len(0.15, 0.25);
  const Vector3d xj(coord(rng), coord(rng), coord(rng));
  const Vector3d a = Vector3d(coord(rng), coord(rng), coord(rng)).normalized();
  const Vector3d p = a.cross(Vector3d(coord(rng), coord(rng), coord(rng))).normalized();
  const Vector3d b = std::cos(theta) * a + std::sin(theta) * p;
  return {quantised(xj - len(rng) * a), quantised(xj), quantised(xj + len(rng) * b)};
}

double bend_energy(const std::vector<Vector3d>& x, double kappa) {
  return wire_bend(x[0], x[1], x[2], kappa).energy;
}

std::vector<Vector3d> bend_forces(const std::vector<Vector3d>& x, double kappa) {
  const BendResult r = wire_bend(x[0], x[1], x[2], kappa);
  return {r.force_i, r.force_j, r.force_k};
}

Vector3d total_torque(const std::vector<Vector3d>& x, const std::vector<Vector3d>& f) {
  Vector3d t = Vector3d::Zero();
  for (std::size_t a = 0; a < x.size(); ++a) t += x[a].cross(f[a]);
  return t;
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Material

TEST(WireMaterial, DefaultsAreTable1AndDerivedQuantitiesFollowTheFormulas) {
  const WireMaterial m;
  EXPECT_NO_THROW(m.validate());
  EXPECT_EQ(m.youngs_modulus, 100.0);
  EXPECT_EQ(m.radius, 0.1);
  EXPECT_EQ(m.segment_length, 0.2);
  EXPECT_EQ(m.elongation_multiplier, 1.0);
  EXPECT_EQ(m.rotation_multiplier, 0.1);
  EXPECT_EQ(m.density, 0.5);
  const double r = 0.1, l = 0.2, E = 100.0;
  EXPECT_NEAR(m.cross_section_area(), kPi * 0.01, 1e-15);
  EXPECT_NEAR(m.second_moment_of_area(), kPi * 1e-4 / 4.0, 1e-18);
  EXPECT_NEAR(m.node_mass(), 0.5 * kPi * 0.01 * 0.2, 1e-16);
  // the paper's k_elo = m_elo E π r²/l², k_rot = m_rot E π r⁴/(4 l²) are k_s/l, κ/l
  EXPECT_NEAR(m.axial_stiffness() / l, 1.0 * E * kPi * r * r / (l * l), 1e-12);
  EXPECT_NEAR(m.bending_stiffness() / l, 0.1 * E * kPi * r * r * r * r / (4.0 * l * l), 1e-14);
}

TEST(WireMaterial, ValidateNamesTheParameter) {
  const auto expect_invalid = [](WireMaterial m, const std::string& name) {
    try {
      m.validate();
      ADD_FAILURE() << "no error for " << name;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.argument(), name);
      EXPECT_NE(std::string(e.what()).find(name + " must be"), std::string::npos) << e.what();
    }
  };
  WireMaterial m;
  m.youngs_modulus = -1.0;
  expect_invalid(m, "E");
  m = WireMaterial();
  m.radius = 0.0;
  expect_invalid(m, "radius");
  m = WireMaterial();
  m.segment_length = -0.2;
  expect_invalid(m, "segment_length");
  m = WireMaterial();
  m.density = 0.0;
  expect_invalid(m, "density");
  m = WireMaterial();
  m.elongation_multiplier = -0.1;
  expect_invalid(m, "m_elo");
  m = WireMaterial();
  m.rotation_multiplier = -1e-9;
  expect_invalid(m, "m_rot");
  m = WireMaterial();
  m.youngs_modulus = std::nan("");
  expect_invalid(m, "E");
  m = WireMaterial();
  m.elongation_multiplier = 0.0;
  m.rotation_multiplier = 0.0;
  EXPECT_NO_THROW(m.validate());
  try {
    WireMaterial bad;
    bad.youngs_modulus = -1.0;
    bad.validate();
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "E must be a finite number > 0, got -1");
  }
}

// ---------------------------------------------------------------------------------------
// Forces are −∇U

TEST(WireStretch, ForcesAreMinusGradientOfEnergy) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  const double k_s = 15.7, l0 = 0.2;
  for (int trial = 0; trial < 50; ++trial) {
    const std::vector<Vector3d> x{quantised(Vector3d(coord(rng), coord(rng), coord(rng))),
                                  quantised(Vector3d(coord(rng), coord(rng), coord(rng)))};
    const StretchResult r = wire_stretch(x[0], x[1], k_s, l0);
    const auto energy = [&](const std::vector<Vector3d>& y) {
      return wire_stretch(y[0], y[1], k_s, l0).energy;
    };
    const auto fd = finite_difference_forces(x, energy, std::ldexp(1.0, -14));
    const std::vector<Vector3d> f{r.force_i, r.force_j};
    const double scale = max_norm(f);
    for (int a = 0; a < 2; ++a) EXPECT_LT((f[a] - fd[a]).norm(), 1e-6 * scale);
    EXPECT_NEAR(r.tension, k_s * ((x[1] - x[0]).norm() - l0), 1e-12 * k_s);
    EXPECT_LT((f[0] + f[1]).norm(), 1e-12 * scale);
    EXPECT_LT(total_torque(x, f).norm(), 1e-12 * scale);
  }
}

// Random configurations over the whole range of θ, including θ = 1e-8 and π − 1e-6.
TEST(WireBend, ForcesAreMinusGradientOfEnergy) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> angle(0.0, kPi);
  const double kappa = 0.0785;
  struct Case {
    double theta;
    double step;  // finite-difference step
  };
  // Near the fold U has a cone-shaped maximum at transverse distance ρ ≈ (π − θ)|e| from
  // the node; the stencil error goes as (h/ρ)⁴, so h is a power of two below ρ/100.
  const auto step_for = [](double theta) {
    const double rho = 0.15 * std::min(1.0, kPi - theta);
    return std::ldexp(1.0, std::min(-14, static_cast<int>(std::floor(std::log2(0.01 * rho)))));
  };
  std::vector<Case> cases;
  for (int t = 0; t < 40; ++t) {
    const double theta = angle(rng);
    cases.push_back({theta, step_for(theta)});
  }
  // U = ½κθ² is smooth at θ = 0 but varies on the scale of the chord: the stencil error
  // (h/l)⁴ must stay below 1e-6 θ, hence the step 2^-20 ≈ 1e-6
  for (int t = 0; t < 10; ++t) cases.push_back({1e-8, std::ldexp(1.0, -20)});
  // ρ ≈ 1e-6 |e| ≥ 1.5e-7: the step is 2^-30 ≈ 9e-10
  for (int t = 0; t < 10; ++t) cases.push_back({kPi - 1e-6, step_for(kPi - 1e-6)});
  double worst[3] = {0.0, 0.0, 0.0};  // largest relative deviation: generic, θ = 1e-8, π − 1e-6
  for (std::size_t n = 0; n < cases.size(); ++n) {
    const Case& c = cases[n];
    const auto x = bend_configuration(rng, c.theta);
    const BendResult r = wire_bend(x[0], x[1], x[2], kappa);
    // the angle itself: rounding the nodes to 2^-40 moves it by < 1e-11
    EXPECT_NEAR(r.angle, c.theta, 1e-10);
    EXPECT_NEAR(r.energy, 0.5 * kappa * r.angle * r.angle, 1e-15);
    const auto f = bend_forces(x, kappa);
    const auto fd = finite_difference_forces(
        x, [&](const std::vector<Vector3d>& y) { return bend_energy(y, kappa); }, c.step);
    const double scale = max_norm(f);
    ASSERT_GT(scale, 0.0);
    for (int a = 0; a < 3; ++a) {
      EXPECT_LT((f[a] - fd[a]).norm(), 1e-6 * scale)
          << "theta=" << c.theta << " node " << a << " f=" << f[a].transpose()
          << " fd=" << fd[a].transpose();
      double& w = worst[n < 40 ? 0 : (n < 50 ? 1 : 2)];
      w = std::max(w, (f[a] - fd[a]).norm() / scale);
    }
    // |F_k| = κθ/|e2|: the end force is the moment κθ over the lever arm
    EXPECT_NEAR(f[2].norm(), kappa * r.angle / (x[2] - x[1]).norm(),
                1e-12 * kappa * r.angle / (x[2] - x[1]).norm());
  }
  std::printf("bend forces vs finite differences, worst relative deviation: generic %.1e, "
              "theta=1e-8 %.1e, theta=pi-1e-6 %.1e\n",
              worst[0], worst[1], worst[2]);
}

TEST(WireBend, NetForceAndNetTorqueVanish) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0.0, kPi);
  const double kappa = 0.0785;
  std::vector<double> thetas{1e-8, 1e-4, kPi - 1e-6, kPi - 1e-3};
  for (int t = 0; t < 100; ++t) thetas.push_back(angle(rng));
  for (double theta : thetas) {
    const auto x = bend_configuration(rng, theta);
    const auto f = bend_forces(x, kappa);
    double scale = 0.0;  // largest single torque |x_a| |F_a|
    for (int a = 0; a < 3; ++a) scale = std::max(scale, x[a].norm() * f[a].norm());
    EXPECT_LT((f[0] + f[1] + f[2]).norm(), 1e-12 * max_norm(f)) << "theta=" << theta;
    EXPECT_LT(total_torque(x, f).norm(), 1e-12 * scale) << "theta=" << theta;
  }
}

// The two ends of the documented behaviour: a straight chain has no bending force; a
// chain folded back exactly (sin θ = 0) gets zero forces and energy ½κπ².
TEST(WireBend, StraightAndExactlyFoldedChains) {
  const double kappa = 0.5;
  const Vector3d xi(0.1, 0.2, 0.3), xj(0.3, 0.2, 0.3), xk(0.5, 0.2, 0.3);
  const BendResult straight = wire_bend(xi, xj, xk, kappa);
  EXPECT_EQ(straight.angle, 0.0);
  EXPECT_EQ(straight.energy, 0.0);
  EXPECT_EQ(straight.force_i.norm() + straight.force_j.norm() + straight.force_k.norm(), 0.0);
  const BendResult folded = wire_bend(xi, xj, Vector3d(0.2, 0.2, 0.3), kappa);
  EXPECT_DOUBLE_EQ(folded.angle, kPi);
  EXPECT_DOUBLE_EQ(folded.energy, 0.5 * kappa * kPi * kPi);
  EXPECT_EQ(folded.force_i.norm() + folded.force_j.norm() + folded.force_k.norm(), 0.0);
  // just off the fold the force is finite and equals κθ/|e2| at the end node
  const BendResult near = wire_bend(xi, xj, Vector3d(0.1, 0.2 + 1e-9, 0.3), kappa);
  EXPECT_NEAR(near.force_k.norm(), kappa * near.angle / 0.2, 1e-9);
  // zero-length segment: no bending plane, no force
  const BendResult degenerate = wire_bend(xi, xi, xk, kappa);
  EXPECT_EQ(degenerate.force_i.norm() + degenerate.force_j.norm() + degenerate.force_k.norm(),
            0.0);
}

// ---------------------------------------------------------------------------------------
// Continuum limits

// N segments each stretched by δ: every segment carries m_elo E A δ / l_w, the inner
// nodes are in equilibrium and the ends are pulled back by that force.
TEST(WireChain, AxialStretchGivesHookeForce) {
  for (double m_elo : {1.0, 0.2}) {
    WireMaterial m;
    m.elongation_multiplier = m_elo;
    const double l = m.segment_length, delta = 0.01 * l;
    const int segments = 10;
    std::vector<Vector3d> nodes;
    for (int k = 0; k <= segments; ++k) nodes.emplace_back(k * (l + delta), 0.0, 0.0);
    const double expected = m_elo * 100.0 * kPi * 0.1 * 0.1 * delta / 0.2;  // m_elo E A δ/l
    for (int s = 0; s < segments; ++s)
      EXPECT_NEAR(wire_stretch(nodes[s], nodes[s + 1], m.axial_stiffness(), l).tension,
                  expected, 1e-12 * expected);
    const WireChainElasticity c = wire_chain_elasticity(nodes, m);
    EXPECT_NEAR(c.forces.front().x(), expected, 1e-12 * expected);
    EXPECT_NEAR(c.forces.back().x(), -expected, 1e-12 * expected);
    for (int k = 1; k < segments; ++k) EXPECT_LT(c.forces[k].norm(), 1e-12 * expected);
    // energies: ½ k δ² per segment, half to each end node
    const double segment_energy = 0.5 * expected * delta;
    EXPECT_NEAR(c.stretching_energy, segments * segment_energy, 1e-12 * segment_energy);
    EXPECT_EQ(c.bending_energy, 0.0);
    EXPECT_NEAR(c.node_energy.front(), 0.5 * segment_energy, 1e-12 * segment_energy);
    EXPECT_NEAR(c.node_energy.back(), 0.5 * segment_energy, 1e-12 * segment_energy);
    for (int k = 1; k < segments; ++k)
      EXPECT_NEAR(c.node_energy[k], segment_energy, 1e-12 * segment_energy);
  }
}

// Nodes on a circle of radius ρ with chord l = l_w: θ = 2 asin(l/2ρ), and the moment at a
// node, measured from the end force as |e2 × F_k|, is κθ = (m_rot E I / l) θ, which tends
// to the Euler–Bernoulli moment E I / ρ (m_rot = 1) as l/ρ → 0. Relative error
// asin(x)/x − 1 ≈ (l/ρ)²/24: second order.
TEST(WireChain, UniformCurvatureMomentConvergesToEulerBernoulli) {
  const double rho = 1.0;
  std::vector<double> errors;
  for (double l : {0.4, 0.2, 0.1, 0.05}) {
    WireMaterial m;
    m.rotation_multiplier = 1.0;
    m.segment_length = l;
    const double half_step = std::asin(l / (2.0 * rho));
    std::vector<Vector3d> nodes;
    for (int k = -1; k <= 1; ++k)
      nodes.emplace_back(rho * std::cos(2.0 * k * half_step), rho * std::sin(2.0 * k * half_step),
                         0.0);
    const BendResult r = wire_bend(nodes[0], nodes[1], nodes[2], m.bending_stiffness());
    EXPECT_NEAR(r.angle, 2.0 * half_step, 1e-14);
    const double moment = (nodes[2] - nodes[1]).cross(r.force_k).norm();
    const double EI = 100.0 * kPi * std::pow(0.1, 4) / 4.0;
    EXPECT_NEAR(moment, EI / l * 2.0 * half_step, 1e-12 * EI / rho);
    const double error = std::abs(moment - EI / rho) / (EI / rho);
    EXPECT_NEAR(error, l * l / (24.0 * rho * rho), 0.05 * l * l / (24.0 * rho * rho));
    errors.push_back(error);
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double order = std::log2(errors[i - 1] / errors[i]);
    RecordProperty("moment_order_" + std::to_string(i), std::to_string(order));
    std::printf("uniform curvature: moment error %.3e -> %.3e, observed order %.3f\n",
                errors[i - 1], errors[i], order);
    EXPECT_NEAR(order, 2.0, 0.05);
  }
}

// The same circle, as a chain: bending energy per unit length at an inner node tends to
// the beam's E I / (2 ρ²), also at second order; node energies add up to the total.
TEST(WireChain, UniformCurvatureEnergyDensityConvergesToEulerBernoulli) {
  const double rho = 2.0;
  const double EI = 100.0 * kPi * std::pow(0.1, 4) / 4.0;
  std::vector<double> errors;
  for (double l : {0.4, 0.2, 0.1}) {
    WireMaterial m;
    m.rotation_multiplier = 1.0;
    m.segment_length = l;
    const double step = 2.0 * std::asin(l / (2.0 * rho));
    std::vector<Vector3d> nodes;
    for (int k = 0; k < 12; ++k)
      nodes.emplace_back(rho * std::cos(k * step), rho * std::sin(k * step), 0.3);
    const WireChainElasticity c = wire_chain_elasticity(nodes, m);
    double sum = 0.0;
    for (double e : c.node_energy) sum += e;
    EXPECT_NEAR(sum, c.total_energy(), 1e-14 * c.total_energy());
    EXPECT_NEAR(c.bending_energy, 10 * 0.5 * m.bending_stiffness() * step * step,
                1e-12 * c.bending_energy);
    EXPECT_LT(c.stretching_energy, 1e-20);
    EXPECT_LT(c.node_energy.front(), 1e-20);  // an end node has stretching only
    const double density = c.node_energy[5] / l;
    const double beam = EI / (2.0 * rho * rho);
    errors.push_back(std::abs(density - beam) / beam);
  }
  for (std::size_t i = 1; i < errors.size(); ++i)
    EXPECT_NEAR(std::log2(errors[i - 1] / errors[i]), 2.0, 0.05);
}

// ---------------------------------------------------------------------------------------
// Dynamics

// Two free nodes joined by one segment: the extension oscillates at ω = sqrt(2 k_s / m)
// (reduced mass m/2); for Table 1 ω² = 2 m_elo E / (ρ l²) = 10⁴. Fifth-order Gear at the
// paper's Δt_SP = 1e-4 over 100 periods.
TEST(WireDynamics, TwoNodeAxialVibrationWithGear) {
  const WireMaterial m;
  const double omega = std::sqrt(2.0 * 1.0 * 100.0 / (0.5 * 0.2 * 0.2));
  const double period = 2.0 * kPi / omega, dt = 1e-4;
  const double mass = m.node_mass(), l = m.segment_length;
  double x[2][3] = {{0.0, 0.0, 0.0}, {l + 0.01 * l, 0.0, 0.0}};
  double v[2][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  double hist[2][kGearHistorySize];
  const auto accelerations = [&](double acc[2][3]) {
    const StretchResult r = wire_stretch(Vector3d(x[0][0], x[0][1], x[0][2]),
                                         Vector3d(x[1][0], x[1][1], x[1][2]),
                                         m.axial_stiffness(), l);
    for (int d = 0; d < 3; ++d) {
      acc[0][d] = r.force_i[d] / mass;
      acc[1][d] = r.force_j[d] / mass;
    }
  };
  double acc[2][3];
  accelerations(acc);
  for (int n = 0; n < 2; ++n) gear5_start(hist[n], acc[n]);
  const GearCorrector corrector(GearCoefficients::position_forces(), dt);
  const long steps = std::lround(100.5 * period / dt);
  double previous = x[1][0] - x[0][0] - l;
  std::vector<double> upward_crossings;
  for (long s = 1; s <= steps; ++s) {
    for (int n = 0; n < 2; ++n) gear5_predict(x[n], v[n], hist[n], dt);
    accelerations(acc);
    for (int n = 0; n < 2; ++n) gear5_correct(x[n], v[n], hist[n], acc[n], corrector);
    const double extension = x[1][0] - x[0][0] - l;
    if (previous < 0.0 && extension >= 0.0)
      upward_crossings.push_back(
          dt * (static_cast<double>(s - 1) + previous / (previous - extension)));
    previous = extension;
  }
  ASSERT_GE(upward_crossings.size(), 99u);
  const double measured = (upward_crossings.back() - upward_crossings.front()) /
                          static_cast<double>(upward_crossings.size() - 1);
  const double relative_error = std::abs(measured - period) / period;
  RecordProperty("gear_period_relative_error", std::to_string(relative_error));
  std::printf("two-node vibration, gear5, dt*omega = %.3f: period error %.2e over %zu periods\n",
              dt * omega, relative_error, upward_crossings.size() - 1);
  EXPECT_LT(relative_error, 1e-4);
  // the centre of mass stays at rest
  EXPECT_LT(std::abs(v[0][0] + v[1][0]), 1e-12);
}

namespace {

enum class Scheme { verlet, gear5 };

// A straight free chain of `nodes` nodes along x, every node displaced by
// amplitude·(−1)^k along `axis` (the zigzag pattern, whose projection is largest on the
// highest modes), integrated from rest for `steps` steps at `dt`. Returns the largest
// total (kinetic + elastic) energy over the run divided by the initial one.
double energy_growth(Scheme scheme, const WireMaterial& m, int nodes, int axis,
                     double amplitude, double dt, long steps) {
  const double l = m.segment_length, mass = m.node_mass();
  std::vector<Vector3d> x(nodes), v(nodes, Vector3d::Zero());
  for (int k = 0; k < nodes; ++k) {
    x[k] = Vector3d(k * l, 0.0, 0.0);
    x[k][axis] += (k % 2 == 0 ? 1.0 : -1.0) * amplitude;
  }
  WireChainElasticity c = wire_chain_elasticity(x, m);
  std::vector<std::array<double, kGearHistorySize>> history(nodes);
  for (int k = 0; k < nodes; ++k) {
    const Vector3d a = c.forces[k] / mass;
    gear5_start(history[k].data(), a.data());
  }
  const GearCorrector corrector(GearCoefficients::position_forces(), dt);
  const auto kinetic = [&]() {
    double e = 0.0;
    for (const auto& vk : v) e += 0.5 * mass * vk.squaredNorm();
    return e;
  };
  const double e0 = c.total_energy();
  double largest = e0;
  for (long s = 0; s < steps; ++s) {
    if (scheme == Scheme::verlet) {
      for (int k = 0; k < nodes; ++k) {
        const Vector3d a = c.forces[k] / mass;
        verlet_kick_drift(x[k].data(), v[k].data(), a.data(), dt);
      }
      c = wire_chain_elasticity(x, m);
      for (int k = 0; k < nodes; ++k) {
        const Vector3d a = c.forces[k] / mass;
        verlet_kick(v[k].data(), a.data(), dt);
      }
    } else {
      for (int k = 0; k < nodes; ++k)
        gear5_predict(x[k].data(), v[k].data(), history[k].data(), dt);
      c = wire_chain_elasticity(x, m);
      for (int k = 0; k < nodes; ++k) {
        const Vector3d a = c.forces[k] / mass;
        gear5_correct(x[k].data(), v[k].data(), history[k].data(), a.data(), corrector);
      }
    }
    const double e = kinetic() + c.total_energy();
    largest = std::max(largest, e);
    if (!(e < 1e6 * e0)) return e / e0;  // blown up (or NaN)
  }
  return largest / e0;
}

// Spectral radius of one Gear step (predict + correct, c0 = 3/16) on x'' = −ω² x, as a
// function of ω dt: the 6×6 linear map of (x, v, x'', x''', x⁽⁴⁾, x⁽⁵⁾), column by column.
double gear5_spectral_radius(double omega_dt) {
  Eigen::Matrix<double, 6, 6> step;
  const GearCorrector corrector(GearCoefficients::position_forces(), 1.0);
  for (int col = 0; col < 6; ++col) {
    double x[3] = {0, 0, 0}, v[3] = {0, 0, 0}, h[kGearHistorySize] = {};
    double* state[6] = {&x[0], &v[0], &h[0], &h[3], &h[6], &h[9]};
    *state[col] = 1.0;
    gear5_predict(x, v, h, 1.0);
    const double a[3] = {-omega_dt * omega_dt * x[0], 0.0, 0.0};
    gear5_correct(x, v, h, a, corrector);
    for (int row = 0; row < 6; ++row) step(row, col) = *state[row];
  }
  return step.eigenvalues().cwiseAbs().maxCoeff();
}

}  // namespace

// dt_crit = 2/ω_max with ω_max² = 4 k_s/m + 16 κ/(m l²). Table 1: 4 k_s/m = 4 m_elo E/(ρ l²)
// = 20000 and 16 κ/(m l²) = 4 m_rot E r²/(ρ l⁴) = 500.
TEST(WireTimeStep, CriticalStepFormula) {
  const WireMaterial m;
  EXPECT_NEAR(wire_axial_frequency_max(m), std::sqrt(20000.0), 1e-9);
  EXPECT_NEAR(wire_bending_frequency_max(m), std::sqrt(500.0), 1e-10);
  EXPECT_NEAR(wire_critical_time_step(m), 2.0 / std::sqrt(20500.0), 1e-15);
  WireMaterial rigid_free = m;
  rigid_free.elongation_multiplier = 0.0;
  rigid_free.rotation_multiplier = 0.0;
  EXPECT_TRUE(std::isinf(wire_critical_time_step(rigid_free)));
}

// Axially excited chain (Table 1, stretching dominates): Verlet at 0.9 dt_crit keeps the
// energy bounded (the measured energy of Verlet oscillates by up to 1/(1 − (ω dt/2)²) ≈ 5
// at ω dt = 1.8), at 1.1 dt_crit it grows by more than 10³.
TEST(WireTimeStep, VerletStabilityLimitAxial) {
  const WireMaterial m;
  const double dt_crit = wire_critical_time_step(m);
  const double amplitude = 0.01 * m.segment_length;
  const double stable = energy_growth(Scheme::verlet, m, 64, 0, amplitude, 0.9 * dt_crit, 20000);
  const double unstable = energy_growth(Scheme::verlet, m, 64, 0, amplitude, 1.1 * dt_crit, 2000);
  std::printf("axial zigzag, Verlet: energy growth %.3g at 0.9 dt_crit, %.3g at 1.1 dt_crit\n",
              stable, unstable);
  EXPECT_LT(stable, 10.0);
  EXPECT_GT(unstable, 1e3);
}

// Transversely excited chain with bending dominating (m_rot = 1, m_elo = 0.01:
// 16 κ/(m l²) = 5000 against 4 k_s/m = 200), small amplitude so the motion is linear.
TEST(WireTimeStep, VerletStabilityLimitBending) {
  WireMaterial m;
  m.elongation_multiplier = 0.01;
  m.rotation_multiplier = 1.0;
  const double dt_crit = wire_critical_time_step(m);
  const double amplitude = 1e-6 * m.segment_length;
  const double stable = energy_growth(Scheme::verlet, m, 64, 1, amplitude, 0.9 * dt_crit, 20000);
  const double unstable = energy_growth(Scheme::verlet, m, 64, 1, amplitude, 1.1 * dt_crit, 2000);
  std::printf("bending zigzag, Verlet: energy growth %.3g at 0.9 dt_crit, %.3g at 1.1 dt_crit\n",
              stable, unstable);
  EXPECT_LT(stable, 10.0);
  EXPECT_GT(unstable, 1e3);
}

// The fifth-order Gear predictor–corrector has a much shorter stability interval than
// Verlet: its one-step map on a harmonic mode has spectral radius ≤ 1 only up to
// ω dt ≈ 0.31 (printed), beyond which the growth is slow at first (1e-4 per step at
// ω dt = 0.5) and fast later (0.3 per step at ω dt = 1). Hence the recommendation
// dt ≤ 0.1 dt_crit for Gear (ω_max dt ≤ 0.2). The chain at 0.1 dt_crit stays bounded;
// at 0.5 dt_crit (ω_max dt = 1) it blows up.
TEST(WireTimeStep, GearNeedsASmallerFraction) {
  double lo = 0.1, hi = 1.0;  // bisection for the end of the stable interval
  for (int it = 0; it < 50; ++it) {
    const double mid = 0.5 * (lo + hi);
    (gear5_spectral_radius(mid) <= 1.0 + 1e-12 ? lo : hi) = mid;
  }
  std::printf("gear5 stable for omega*dt < %.4f, i.e. dt < %.4f dt_crit\n", lo, lo / 2.0);
  EXPECT_GT(lo, 0.2);  // the recommended fraction 0.1 dt_crit is inside
  const WireMaterial m;
  const double dt_crit = wire_critical_time_step(m);
  const double amplitude = 0.01 * m.segment_length;
  const double stable = energy_growth(Scheme::gear5, m, 64, 0, amplitude, 0.1 * dt_crit, 20000);
  const double unstable = energy_growth(Scheme::gear5, m, 64, 0, amplitude, 0.5 * dt_crit, 2000);
  std::printf("axial zigzag, gear5: energy growth %.3g at 0.1 dt_crit, %.3g at 0.5 dt_crit\n",
              stable, unstable);
  EXPECT_LT(stable, 1.01);
  EXPECT_GT(unstable, 1e3);
}

// Sums of the per-bead output: a two-segment wire, bead energies by hand.
// Beads: (stretching, bending, segment length) = (0.5, 0, 0.2), (1.5, 2, 0.3), (1, 0, 0):
// U_str = 3, U_bend = 2, U_s = 5, L = 0.5, U_s/L = 10.
TEST(WireEnergyTotals, SumsOfBeadEnergies) {
  const std::vector<BeadElasticEnergy> beads = {{0.5, 0.0, 0.2}, {1.5, 2.0, 0.3}, {1.0, 0.0, 0.0}};
  const WireEnergyTotals t = wire_energy_totals(beads);
  EXPECT_EQ(t.stretching_energy, 3.0);
  EXPECT_EQ(t.bending_energy, 2.0);
  EXPECT_EQ(t.total_energy(), 5.0);
  EXPECT_DOUBLE_EQ(t.length, 0.5);
  EXPECT_DOUBLE_EQ(t.energy_per_length(), 10.0);
  // the parts of two ranks merged give the same totals
  WireEnergyTotals first = wire_energy_totals({beads[0]}), second = wire_energy_totals({beads[1], beads[2]});
  first.merge(second);
  EXPECT_EQ(first.stretching_energy, 3.0);
  EXPECT_EQ(first.bending_energy, 2.0);
  EXPECT_DOUBLE_EQ(first.length, 0.5);
  // no length: no energy per length
  EXPECT_EQ(wire_energy_totals({}).energy_per_length(), 0.0);
  EXPECT_EQ(wire_energy_totals({{1.0, 0.0, 0.0}}).energy_per_length(), 0.0);
}

// The chain's energies, written per bead as fix wire/elastic does (half of each segment's
// stretching energy to each end), add up to wire_chain_elasticity's totals.
TEST(WireEnergyTotals, AgreeWithChainElasticity) {
  WireMaterial m;
  const std::vector<Vector3d> nodes = {Vector3d(0, 0, 0), Vector3d(0.21, 0, 0), Vector3d(0.4, 0.05, 0),
                                       Vector3d(0.55, 0.2, 0.03)};
  const WireChainElasticity c = wire_chain_elasticity(nodes, m);
  std::vector<BeadElasticEnergy> beads(nodes.size());
  for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
    const double u = wire_stretch(nodes[k], nodes[k + 1], m.axial_stiffness(), m.segment_length).energy;
    beads[k].stretching += 0.5 * u;
    beads[k + 1].stretching += 0.5 * u;
    beads[k].segment_length = (nodes[k + 1] - nodes[k]).norm();
  }
  for (std::size_t k = 1; k + 1 < nodes.size(); ++k)
    beads[k].bending = wire_bend(nodes[k - 1], nodes[k], nodes[k + 1], m.bending_stiffness()).energy;
  const WireEnergyTotals t = wire_energy_totals(beads);
  EXPECT_NEAR(t.stretching_energy, c.stretching_energy, 1e-15);
  EXPECT_NEAR(t.bending_energy, c.bending_energy, 1e-15);
  EXPECT_NEAR(t.total_energy(), c.total_energy(), 1e-15);
  const double length = (nodes[1] - nodes[0]).norm() + (nodes[2] - nodes[1]).norm() + (nodes[3] - nodes[2]).norm();
  EXPECT_NEAR(t.length, length, 1e-15);
  EXPECT_NEAR(t.energy_per_length(), c.total_energy() / length, 1e-13);
}
