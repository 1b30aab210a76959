// fix nscd/polyhedra's state that its two source files share (fix_nscd_polyhedra.cpp, the
// fix; fix_nscd_polyhedra_distributed.cpp, solve distributed): the core step's options,
// walls, warm starts and pair cache, and the layouts of its per-grain records. Included by
// those two files only (the style header is compiled without Eigen).
#ifndef WIREGRAIN_FIX_NSCD_POLYHEDRA_STATE_H
#define WIREGRAIN_FIX_NSCD_POLYHEDRA_STATE_H

#include <memory>
#include <vector>

#include "fix_nscd_polyhedra.h"
#include "nscd_plate.h"

#include "core/contact/contact_list.h"
#include "core/nscd/grain_step.h"

namespace fix_nscd_polyhedra_layout {

// per grain: its sleep state, asleep (0/1), quiet time, drift v (3), ω (3), checked load
// impulse (3) and moment (3) (GrainState)
constexpr int kSleepState = 14;
// per grain, its state: tag shape x(3) q(4) v(3) ω(3) F(3) T(3) m I(3) (F, T in force units)
constexpr int kStateRecord = 25;
// per grain in the all-gather: the state, the sleep state
constexpr int kGrainRecord = kStateRecord + kSleepState;
// per warm-start point in a distributed restart: pair (2), position, impulse, normal (9),
// gap, status, couple (3)
constexpr int kImpulseRecord = 16;
// per grain in exchange and restart: v_n, L_n (6), Σ F, Σ T (6), sleep state
constexpr int kAtomRecord = 12 + kSleepState;
// per grain in exchange only: the restart record, then whether the last run's end saw
// the grain and its v, L then (7)
constexpr int kExchangeRecord = kAtomRecord + 7;

}  // namespace fix_nscd_polyhedra_layout

// keyword skin's default (measured: docs/benchmarks.md, "The column's run time")
constexpr double kDefaultPairSkin = 0.1;
// keyword project's defaults: the overlap (relative to the pair's smaller bounding radius)
// beyond which the end-of-step poses are projected, and the cap on the passes
// (core/nscd/overlap_projection.h; docs/commands/fix_nscd_polyhedra.md, "Why the defaults")
constexpr double kDefaultProjectTolerance = 5e-5;
constexpr int kDefaultProjectPasses = 20;

// The grain of a state record (kStateRecord numbers), F and T times ftm2v (velocity units);
// its orientation as recorded.
inline wiregrain::GrainState grain_from_record(const double *r, double ftm2v) {
  wiregrain::GrainState g;
  g.tag = (long)r[0];
  g.shape = (int)r[1];
  g.position = Eigen::Vector3d(r[2], r[3], r[4]);
  g.orientation = Eigen::Quaterniond(r[5], r[6], r[7], r[8]);
  g.velocity = Eigen::Vector3d(r[9], r[10], r[11]);
  g.angular_velocity = Eigen::Vector3d(r[12], r[13], r[14]);
  g.force = ftm2v * Eigen::Vector3d(r[15], r[16], r[17]);
  g.torque = ftm2v * Eigen::Vector3d(r[18], r[19], r[20]);
  g.mass = r[21];
  g.inertia = Eigen::Vector3d(r[22], r[23], r[24]);
  return g;
}

// What of a grain's state is not finite: 0 none, 1 its position or orientation, 2 its
// velocity, 3 its force or torque; and the words of the ERROR that names it.
inline int non_finite_part(const wiregrain::GrainState &g) {
  if (!(g.position.allFinite() && g.orientation.coeffs().allFinite())) return 1;
  if (!(g.velocity.allFinite() && g.angular_velocity.allFinite())) return 2;
  if (!(g.force.allFinite() && g.torque.allFinite())) return 3;
  return 0;
}
inline const char *non_finite_words(int part) {
  return part == 1 ? "position or orientation" : part == 2 ? "velocity" : "force or torque (from another style)";
}

struct LAMMPS_NS::FixNSCDPolyhedra::CoreState {
  wiregrain::GrainStepOptions options;
  std::vector<wiregrain::PlaneWall> walls;
  // per wall: its own 'wall_friction' given; the others take the grains' 'friction' (at
  // init and on fix_modify friction), whatever the keyword order
  std::vector<bool> own_wall_friction;
  void walls_take_grain_friction() {
    for (size_t w = 0; w < walls.size(); w++)
      if (!own_wall_friction[w]) walls[w].friction = options.friction;
  }
  wiregrain::GrainImpulseMemory impulses;
  double pair_skin = kDefaultPairSkin;               // keyword skin
  std::unique_ptr<wiregrain::GrainPairCache> pairs;  // skin > 0
  wiregrain::ContactList published;
  wiregrain_lmp::NscdPlates plates;  // keyword plate (nscd_plate.h)
};

#endif
