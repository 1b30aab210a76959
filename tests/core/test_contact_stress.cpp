// Love–Weber grain stress (core/contact/contact_stress.h) against statics worked out by
// hand and against the boundary identity of a packing.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "core/common/errors.h"
#include "core/contact/contact_stress.h"

using namespace wiregrain;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {
Matrix3d stress_of(const std::vector<std::pair<Vector3d, Vector3d>>& arms_and_forces, double volume) {
  ContactMomentSum sum;
  for (const auto& [arm, force] : arms_and_forces) sum.add(arm, force);
  return love_weber_stress(sum.sum, volume);
}
}  // namespace

// A 1 × 2 × 3 box (V = 6) squeezed along z by F = 12 on its top and bottom faces, each
// face's load shared by its four corners: σ_zz = −F h / V = −12 · 3 / 6 = −6, the rest 0;
// p = 2.
TEST(ContactStress, BoxSqueezedBetweenTwoPlates) {
  std::vector<std::pair<Vector3d, Vector3d>> contacts;
  for (double sx : {-0.5, 0.5})
    for (double sy : {-1.0, 1.0}) {
      contacts.push_back({Vector3d(sx, sy, 1.5), Vector3d(0, 0, -3.0)});
      contacts.push_back({Vector3d(sx, sy, -1.5), Vector3d(0, 0, 3.0)});
    }
  const Matrix3d sigma = stress_of(contacts, 6.0);
  Matrix3d expected = Matrix3d::Zero();
  expected(2, 2) = -6.0;
  EXPECT_LT((sigma - expected).cwiseAbs().maxCoeff(), 1e-15) << sigma;
  EXPECT_DOUBLE_EQ(pressure(sigma), 2.0);
}

// A unit cube (V = 1) sheared: F = 1 along +x on its top face (z = 0.5), −x on its
// bottom, and the balancing pair along z on the faces x = ±0.5 (F = 1, no net torque):
// σ_zx = 0.5 + 0.5 = 1 and σ_xz = 1 (symmetric at equilibrium), the rest 0, p = 0.
TEST(ContactStress, CubeInSimpleShearIsSymmetric) {
  const std::vector<std::pair<Vector3d, Vector3d>> contacts = {
      {Vector3d(0, 0, 0.5), Vector3d(1, 0, 0)},
      {Vector3d(0, 0, -0.5), Vector3d(-1, 0, 0)},
      {Vector3d(0.5, 0, 0), Vector3d(0, 0, 1)},
      {Vector3d(-0.5, 0, 0), Vector3d(0, 0, -1)}};
  const Matrix3d sigma = stress_of(contacts, 1.0);
  Matrix3d expected = Matrix3d::Zero();
  expected(0, 2) = expected(2, 0) = 1.0;
  EXPECT_LT((sigma - expected).cwiseAbs().maxCoeff(), 1e-15) << sigma;
  EXPECT_DOUBLE_EQ(pressure(sigma), 0.0);
}

// Random grains joined by random inner contacts (each force on both grains with opposite
// signs) and random boundary contacts: Σ_i V_i σ_i = Σ_boundary x_c ⊗ f_c − Σ_i x_i ⊗ F_i,
// F_i the total contact force on grain i.
TEST(ContactStress, VolumeSumEqualsTheBoundaryTermOfAnyPacking) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto random_vector = [&] { return Vector3d(u(rng), u(rng), u(rng)); };
  const int n = 6;
  std::vector<Vector3d> centre(n), total(n, Vector3d::Zero());
  std::vector<double> volume(n);
  std::vector<ContactMomentSum> sums(n);
  for (int i = 0; i < n; i++) {
    centre[i] = 3.0 * random_vector();
    volume[i] = 1.0 + 0.5 * (u(rng) + 1.0);
  }
  Matrix3d boundary = Matrix3d::Zero();
  for (int k = 0; k < 20; k++) {  // inner: f on grain b, −f on grain a
    const int a = k % n, b = (k * 5 + 1) % n;
    if (a == b) continue;
    const Vector3d x = random_vector() + 0.5 * (centre[a] + centre[b]), f = random_vector();
    sums[b].add(x - centre[b], f);
    sums[a].add(x - centre[a], -f);
    total[b] += f;
    total[a] -= f;
  }
  for (int k = 0; k < 8; k++) {  // boundary: walls on grain k % n
    const int i = k % n;
    const Vector3d x = centre[i] + random_vector(), f = random_vector();
    sums[i].add(x - centre[i], f);
    total[i] += f;
    boundary += x * f.transpose();
  }
  Matrix3d volume_sum = Matrix3d::Zero(), expected = boundary;
  for (int i = 0; i < n; i++) {
    volume_sum += volume[i] * love_weber_stress(sums[i].sum, volume[i]);
    expected -= centre[i] * total[i].transpose();
  }
  EXPECT_LT((volume_sum - expected).cwiseAbs().maxCoeff(), 1e-13) << volume_sum << "\n\n" << expected;
}

TEST(ContactStress, VolumeMustBePositiveAndFinite) {
  for (double v : {0.0, -1.0, std::nan("")}) {
    try {
      love_weber_stress(Matrix3d::Identity(), v);
      FAIL() << "accepted volume " << v;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.argument(), "volume");
    }
  }
}
