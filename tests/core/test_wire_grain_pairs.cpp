// The wire–grain pair cache (core/contact/wire_grain_pairs.h) against a brute-force search
// over every (segment, grain) pair with the exact distance: the touching pairs it visits
// must be exactly the touching pairs, in tag order, while segments and grains move and
// turn by random amounts, some of them beyond the skin; and it must visit fewer pairs
// than a search every step.
#include <gtest/gtest.h>

#include <cstdio>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "core/common/errors.h"
#include "core/contact/wire_grain_pairs.h"

using namespace wiregrain;
using Eigen::Quaterniond;
using Eigen::Vector3d;

namespace {

constexpr double kWireRadius = 0.1;

struct Segment {
  Vector3d x0, x1;
};

Quaterniond random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
}

// A small turn about a random axis by an angle in [0, max_angle).
Quaterniond random_turn(std::mt19937_64& rng, double max_angle) {
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, max_angle);
  return Quaterniond(Eigen::AngleAxisd(u(rng), Vector3d(n(rng), n(rng), n(rng)).normalized()));
}

Vector3d random_step(std::mt19937_64& rng, double length) {
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, length);
  return u(rng) * Vector3d(n(rng), n(rng), n(rng)).normalized();
}

// The exact gap of segment s and grain k; a stock sphere by the general geometry of a
// one-vertex grain (not the closed form HeldGrains uses for it).
double exact_gap(const HeldGrains& held, int k, const Segment& s) {
  const HeldGrain& g = held.grain(k);
  if (g.shape != HeldGrain::kSphere) return segment_contact(held.posed(k), s.x0, s.x1, kWireRadius).gap;
  const ConvexShape ball = ConvexShape::sphere(g.sphere_radius);
  return segment_contact(PosedShape(ball, g.position, Quaterniond::Identity()), s.x0, s.x1, kWireRadius).gap;
}

// Tags of the grains touching the segment, by the exact gap against every grain.
std::vector<long> touching_brute_force(const HeldGrains& held, const Segment& s) {
  std::vector<long> tags;
  for (int k = 0; k < held.size(); ++k)
    if (exact_gap(held, k, s) <= 0.0) tags.push_back(held.grain(k).tag);
  std::sort(tags.begin(), tags.end());
  return tags;
}

// Grains on a jittered 4 × 4 × 2 lattice (spacing 1.9, bounding radius ≤ 1.05), tags in
// scrambled order, and wire segments threaded between them. The grains are cubes,
// ellipsoids and stock spheres (radius 0.8) in turn.
class PairCache : public ::testing::Test {
 protected:
  PairCache() : rng(20261124) {
    library.add(ConvexShape::cube(1.2, 0.05));
    library.add(ConvexShape::random_ellipsoid(7, 12, 0.9, 0.8, 0.6, 0.05));
    std::vector<long> tags;
    for (int t = 0; t < 32; ++t) tags.push_back(1000 - 7 * t);
    std::shuffle(tags.begin(), tags.end(), rng);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int l = 0; l < 2; ++l) {
          HeldGrain g;
          g.tag = tags[grains.size()];
          g.shape = static_cast<int>(grains.size() % 3);
          if (g.shape == 2) {
            g.shape = HeldGrain::kSphere;
            g.sphere_radius = 0.8;
          }
          g.position = Vector3d(1.9 * i + jitter(rng), 1.9 * j + jitter(rng), 1.9 * l + jitter(rng));
          g.orientation = random_rotation(rng);
          g.motion.mass = 1.0;
          grains.push_back(g);
        }
    std::uniform_real_distribution<double> where(-0.5, 6.2), height(-0.5, 2.5);
    for (int s = 0; s < 300; ++s) {
      Segment seg;
      seg.x0 = Vector3d(where(rng), where(rng), height(rng));
      seg.x1 = seg.x0 + random_step(rng, 0.3);
      segments.push_back(seg);
    }
  }
  HeldGrains hold() const { return HeldGrains(grains, library, PeriodicBox(), 1.0); }
  std::mt19937_64 rng;
  ShapeLibrary library;
  std::vector<HeldGrain> grains;
  std::vector<Segment> segments;
};

}  // namespace

TEST_F(PairCache, VisitsEveryTouchingPairInTagOrderWhileSegmentsAndGrainsMove) {
  WireGrainPairCache cache(0.05);
  long visits = 0, full_search_visits = 0, touching_total = 0;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int step = 0; step < 200; ++step) {
    // every 10th step the grains move (an NSCD step); now and then one jumps far
    if (step % 10 == 0 && step > 0)
      for (HeldGrain& g : grains) {
        g.position += random_step(rng, u(rng) < 0.02 ? 0.5 : 0.01);
        g.orientation = random_turn(rng, u(rng) < 0.02 ? 0.5 : 0.004) * g.orientation;
      }
    for (Segment& s : segments) {  // beads move every step, a few far
      const double reach = u(rng) < 0.01 ? 0.2 : 0.003;
      s.x0 += random_step(rng, reach);
      s.x1 += random_step(rng, reach);
    }
    const HeldGrains held = hold();
    cache.hold(held);
    for (std::size_t key = 0; key < segments.size(); ++key) {
      const Segment& s = segments[key];
      std::vector<long> visited, touching;
      cache.for_each_pair(long(key), held, s.x0, s.x1, kWireRadius,
                          [&](int k, const Vector3d& shift, double exact_gap_below, GjkSimplex*) {
                            EXPECT_EQ(shift, Vector3d::Zero());
                            visited.push_back(held.grain(k).tag);
                            const double gap = exact_gap(held, k, s);
                            if (gap <= 0.0) touching.push_back(held.grain(k).tag);
                            // beyond exact_gap_below the contract allows any lower bound of
                            // the gap above it (a superquadric's GJK early exit): return the
                            // loosest one, halfway
                            return gap < exact_gap_below ? gap : exact_gap_below + 0.5 * (gap - exact_gap_below);
                          });
      visits += long(visited.size());
      EXPECT_TRUE(std::is_sorted(visited.begin(), visited.end())) << "step " << step << " segment " << key;
      const std::vector<long> expected = touching_brute_force(held, s);
      ASSERT_EQ(touching, expected) << "step " << step << " segment " << key;
      touching_total += long(expected.size());
      held.for_each_candidate(s.x0, s.x1, kWireRadius, 0.0, [&](int, const Vector3d&) { full_search_visits++; });
    }
  }
  EXPECT_GT(touching_total, 1000);  // the test sees contacts
  EXPECT_GT(cache.resets(), 3);     // the far jumps reset the reference
  // the cache rebuilds far fewer entries than there are segment visits, and visits fewer
  // pairs than the search every step finds (a measured ratio, not a bar: about 0.5)
  EXPECT_LT(cache.rebuilds(), 200L * long(segments.size()) / 4);
  EXPECT_LT(visits, full_search_visits);
  EXPECT_GT(cache.skipped(), 0);  // listed pairs still apart were not evaluated, yet every touching one was
  std::printf("  visits %ld (a search every step: %ld), listed pairs skipped as apart %ld\n", visits,
              full_search_visits, cache.skipped());
}

TEST_F(PairCache, ATurnOfAGrainAboutItsCentreIsBoundedByItsBoundingRadius) {
  // a segment just beyond the skin from the cube's corner region: turning the cube moves
  // its corner towards the segment although its centre stays put
  grains.resize(1);
  grains[0].shape = 0;  // cube of edge 1.2, sweep 0.05
  grains[0].position = Vector3d::Zero();
  grains[0].orientation = Quaterniond::Identity();
  const double skin = 0.05;
  // along the x axis beyond the face centre: gap 0.1 > skin; a 45° turn about z brings the
  // cube's vertical edge out to √2 · 0.6 = 0.849 from the axis
  const Segment s{Vector3d(0.6 + 0.05 + kWireRadius + 0.1, -0.1, 0.0), Vector3d(0.6 + 0.05 + kWireRadius + 0.1, 0.1, 0.0)};
  WireGrainPairCache cache(skin);
  int touching = 0;
  for (int step = 0; step <= 45; ++step) {
    grains[0].orientation = Quaterniond(Eigen::AngleAxisd(step * M_PI / 180.0, Vector3d::UnitZ()));
    const HeldGrains held = hold();
    cache.hold(held);
    bool found = false;
    cache.for_each_pair(1, held, s.x0, s.x1, kWireRadius, [&](int k, const Vector3d&, double, GjkSimplex*) {
      const double gap = segment_contact(held.posed(k), s.x0, s.x1, kWireRadius).gap;
      found = found || gap <= 0.0;
      return gap;
    });
    EXPECT_EQ(found, !touching_brute_force(held, s).empty()) << "turned by " << step << " degrees";
    touching += found;
  }
  EXPECT_GT(touching, 0);  // the turn does bring the edge into contact
}

TEST_F(PairCache, ASegmentAndAGrainClosingTheGapTogetherAreFound) {
  // gap 0.052 > skin 0.05 at the build; then the segment moves 0.03 towards the cube and
  // the cube 0.024 towards it (below skin/2: no reset): each alone keeps the pair apart,
  // together they overlap by 0.002
  grains.resize(1);
  grains[0].shape = 0;  // cube of edge 1.2, sweep 0.05
  grains[0].position = Vector3d::Zero();
  grains[0].orientation = Quaterniond::Identity();
  const double x = 0.6 + 0.05 + kWireRadius + 0.052;
  Segment s{Vector3d(x, -0.1, 0.0), Vector3d(x, 0.1, 0.0)};
  WireGrainPairCache cache(0.05);
  const auto touches = [&](const HeldGrains& held) {
    bool found = false;
    cache.for_each_pair(1, held, s.x0, s.x1, kWireRadius, [&](int k, const Vector3d&, double, GjkSimplex*) {
      const double gap = segment_contact(held.posed(k), s.x0, s.x1, kWireRadius).gap;
      found = found || gap <= 0.0;
      return gap;
    });
    return found;
  };
  {
    const HeldGrains held = hold();
    cache.hold(held);
    EXPECT_FALSE(touches(held));
  }
  s.x0.x() -= 0.03;
  s.x1.x() -= 0.03;
  grains[0].position.x() += 0.024;
  const HeldGrains held = hold();
  cache.hold(held);
  EXPECT_EQ(cache.resets(), 1);
  ASSERT_FALSE(touching_brute_force(held, s).empty());
  EXPECT_TRUE(touches(held));
}

TEST_F(PairCache, AGrainAddedOrRemovedResetsTheReference) {
  WireGrainPairCache cache(0.05);
  cache.hold(hold());
  EXPECT_EQ(cache.resets(), 1);
  cache.hold(hold());
  EXPECT_EQ(cache.resets(), 1);
  grains.pop_back();
  cache.hold(hold());
  EXPECT_EQ(cache.resets(), 2);
  grains[0].shape = 1 - grains[0].shape;
  cache.hold(hold());
  EXPECT_EQ(cache.resets(), 3);
  ASSERT_EQ(grains[2].shape, HeldGrain::kSphere);
  grains[2].sphere_radius *= 1.01;  // a sphere that grew (fix adapt/radius, insertion)
  cache.hold(hold());
  EXPECT_EQ(cache.resets(), 4);
}

TEST_F(PairCache, ASphereNeedsAFinitePositiveRadius) {
  for (double bad : {0.0, -0.8, std::nan(""), double(INFINITY)}) {
    grains[2].sphere_radius = bad;
    try {
      hold();
      FAIL() << "accepted sphere radius " << bad;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(std::string(e.argument()), "sphere_radius");
    }
  }
}

TEST_F(PairCache, AGrainHeldTwiceIsAnError) {
  grains.push_back(grains[5]);  // a periodic image gathered as a second grain
  try {
    hold();
    FAIL() << "accepted grain " << grains[5].tag << " twice";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(std::string(e.argument()), "grains");
    EXPECT_EQ(std::string(e.what()), "grain " + std::to_string(grains[5].tag) + " is held twice (one copy per tag)");
  }
}

TEST(PairCacheArguments, SkinMustBePositiveAndFinite) {
  for (double bad : {0.0, -0.1, std::nan(""), double(INFINITY)}) {
    try {
      WireGrainPairCache cache(bad);
      FAIL() << "accepted skin " << bad;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(std::string(e.argument()), "skin");
    }
  }
}
