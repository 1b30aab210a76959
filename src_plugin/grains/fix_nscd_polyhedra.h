/* fix nscd/polyhedra: Non-Smooth Contact Dynamics of the grains (atom_style polyhedron),
   Moreau–Jean time stepping with the exact Signorini–Coulomb law solved by nonlinear
   Gauss–Seidel over contact points (docs/design.md, "Grains: rigid spheropolyhedra, NSCD"
   and "The NSCD step and its solver"; core/nscd/nscd_solver.h).

   fix ID group nscd/polyhedra keyword value ...
   Every keyword (walls included), its values and its default:
   docs/commands/fix_nscd_polyhedra.md.

   Each step: at the end of step n, with the forces and torques of step n (gravity
   and every other style's), the free velocities v + h F/m, L + h T are corrected by the
   contact impulses of all contact points whose gap g at the current positions is below
   the activation distance; non-penetration is imposed with gap anticipation,
   g + h((1 − θ) u_n^n + θ u_n^{n+1}) ≥ 0. The positions follow at the start of step n+1:
   x += h((1 − θ) v_n + θ v_{n+1}), the orientation by the exact torque-free rotation with
   (1 − θ) L_n + θ L_{n+1} (θ = 1 by default). v_n and L_n of each grain are kept per atom
   (they migrate and restart), so velocities set between runs are honoured. Walls are planes of
   infinite mass, each with its own friction and velocity. The step itself is the core's
   (core/nscd/grain_step.h); this fix gathers, schedules, scatters and reports.

   wall_fix ID: the plane of fix ID (style wire/wall, which the wire beads feel) is also a
   wall of the grains, at the fix's current position and velocity at every solve: a
   container wall defined once for grains and wire. `plate m_p load F | spring k v_drive`
   after it makes that plane a plate, a body of mass m_p in the contact problem that the
   fix moves (grains/nscd_plate.h).

   every N (or timestep h = N dt, an integer multiple of the LIGGGHTS timestep): the solve
   runs with h = N dt at the end of the steps whose number is a multiple of N, with the
   forces and torques averaged over the N steps since the last solve; the grains move
   once at the start of the following step and are held in between (paper Fig. 5:
   LIGGGHTS step = wire sub-step, grains every N). A force that acts in one sub-step only
   (fix wire/grain adds the sum of its sub-steps at the last one) thus gives the grain the
   impulse dt·ΣF.

   project τ, project_passes N: at the end of each solve, pairs that the step's poses leave
   overlapping by more than τ × their size (the smaller bounding radius) are pushed out
   by moving the poses, never the velocities, in at most N Gauss–Seidel passes
   (core/nscd/overlap_projection.h); τ = 0: off.

   sleep v_sleep t_sleep (default 0: off; also fix_modify ID sleep v t): grains slower than
   v_sleep (|v| + |ω| R) for t_sleep are held and drop out of detection and solve among
   themselves until something moves them (core/nscd/grain_step.h, "Sleeping").

   MPI, solve auto (the default): distributed on more than one rank, replicated on one rank
   and with the keywords distributed does not carry (sleep, rolling_friction, plate,
   write_problems, warm_geometry yes, a triclinic box). solve replicated: every rank
   gathers all grains of the group, solves the same contact problem in the same order and
   keeps its own grains' results, so 1 and N ranks give the same state to the last bit;
   the cost of the solve does not shrink with more ranks. The contact detection is shared
   (detection shared, the default): each rank computes the contact points of a block of
   the candidate pairs and the blocks are all-gathered, the same points to the bit;
   detection replicated: every rank computes all.
   solve distributed (fix_nscd_polyhedra_distributed.cpp, grains/rank_grains.h): each rank
   steps the pairs of its own grains with LIGGGHTS' ghost grains, nothing gathered
   (core/nscd/grain_step.h, GrainPartition); the answer agrees with the replicated one
   within the solver's tolerance.

   Periodic boundaries (boundary p, orthogonal box): every grain pair is taken in its
   minimum image (core/geometry/periodic_box.h); the walls must be parallel to the
   periodic dimensions, each periodic length at least 2 (2 R_max + skin + margin), R_max
   the largest bounding radius (checked at each run start; the core checks the reach with
   the step's activation distance at every step), so that only the nearest image of a
   partner can touch. The grains the fix moves are put back into the box at once with
   their image flags (Domain::remap), so a grain wraps at the step it crosses on any
   number of ranks and across restarts.

   Outputs: vector [sweeps, residual, contact points, largest overlap at the step start,
   largest predicted penetration, steps that hit the iteration cap, then for each wall
   the force the grains exert on it (x, y, z), then the wall-clock seconds of the last
   step spent in gathering + contact detection and in the solve, then the largest overlap
   of all steps since the fix was defined, stick solves tried and kept, pair-cache builds
   and reuses, pair corrections of the overlap projection since the fix was defined, the
   deepest end-of-step overlap it found in the last solve / pair size, grains asleep after
   the last solve, grains woken in it, frozen contact points in it]; per-atom array [contact force (3),
   contact torque about the centre (3)] of each grain (impulses / h).

   Warnings (the first 10 of each kind): a step that hits the iteration cap; grains of
   the group lost (deleted at a fixed boundary); an overlap at a step start beyond half the
   smallest sweep radius r_p of the grains (sharp grains, r_p = 0: a tenth of their
   bounding radius), named with h and the fastest grain's speed v (h v / r_p). */

#ifdef FIX_CLASS

FixStyle(nscd/polyhedra,FixNSCDPolyhedra)

#else

#ifndef LMP_FIX_NSCD_POLYHEDRA_H
#define LMP_FIX_NSCD_POLYHEDRA_H

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "common/contact_publisher.h"
#include "common/moving_plane_wall.h"
#include "core/common/work_share.h"
#include "fix.h"

namespace wiregrain_lmp {
template <class Target>
class KeywordTable;
class RankGrains;
}

namespace wiregrain {
struct GrainState;
struct PeriodicBox;
struct GrainStepResult;
struct GrainStepProblem;
struct NscdStep;
}

namespace LAMMPS_NS {

class FixNSCDPolyhedra : public Fix, public wiregrain_lmp::ContactPublisher {
 public:
  FixNSCDPolyhedra(class LAMMPS *, int, char **);
  int setmask();
  void init();
  void setup(int);
  void post_run();
  void initial_integrate(int);
  void final_integrate();
  double compute_vector(int);
  int modify_param(int, char **);
  ~FixNSCDPolyhedra();
  void write_restart(FILE *);
  void restart(char *);
  void grow_arrays(int);
  void copy_arrays(int, int, int);
  void set_arrays(int);
  int pack_exchange(int, double *);
  int unpack_exchange(int, double *);
  int pack_restart(int, double *);
  void unpack_restart(int, int);
  int size_restart(int);
  int maxsize_restart();
  double memory_usage();
  // solve distributed: the ghost grains' exchange (grains/rank_grains.h) and the ghost
  // cutoff the contact reach needs
  int pack_comm(int, int *, double *, int, int *);
  void unpack_comm(int, int, double *);
  int pack_reverse_comm(int, int, double *);
  void unpack_reverse_comm(int, int *, double *);
  double extend_cut_ghost();

  // the contacts of the last solve whose grain b this rank owns
  const wiregrain::ContactList &published_contacts() const;
  // steps per solve (N), and whether the solve comes at the end of `step`
  int solve_interval() const;
  bool solves_at_end_of_step(bigint step) const;
  // changes whenever the grains have moved (or a run was set up): held poses are stale
  long pose_version() const { return pose_version_; }
  // `solve distributed`: each rank holds its own grains and their ghosts only
  bool solves_distributed() const { return distributed_; }

 private:
  // the core step's options, the walls (current positions, moved by velocity·h every
  // solve), last solve's impulses (warm start, restart) and the published contacts;
  // defined in the .cpp (style headers are compiled without Eigen)
  struct CoreState;
  std::unique_ptr<CoreState> core_;
  // the keywords of the fix's line and their handlers (common/plugin_args.h)
  static const wiregrain_lmp::KeywordTable<FixNSCDPolyhedra> keywords_;
  std::vector<std::string> wall_fix_ids_;   // per wall: the fix wire/wall it comes from ("" : own)
  std::vector<const wiregrain_lmp::MovingPlaneWall *> wall_fixes_;  // of a wall_fix (fix wire/wall)
  int every_ = 1;                           // solve every N steps with h = N dt
  bool every_given_ = false;
  double nscd_timestep_ = 0.0;              // keyword timestep (0: use every_)
  int summed_steps_ = 0;                    // steps whose forces are in force_sum_
  bool move_pending_ = false;               // a solve happened: move at the next step start
  double last_h_ = 0.0;                     // h of that solve
  long pose_version_ = 0;
  class AtomVecPolyhedron *grains_;
  bool solved_once_;                        // a contact solve happened (setup of the first run)
  // v and ω of every grain (by tag, all ranks) as the last run left them, to tell at the
  // next setup whether the deck changed them in between (velocity set, set atom ...)
  double **run_end_velocity_ = nullptr;  // per grain: 1 if the last run's end saw it, its v and L then
  bool run_end_known_ = false;
  void pack_record(int i, double *buf) const;  // the kAtomRecord numbers of grain i
  void unpack_record(int i, const double *buf);
  double stats_[6];
  double largest_overlap_ = 0.0;            // over all steps since the fix was made
  double project_tolerance_;                // keyword project (0: off)
  int project_passes_;
  bool share_detection_ = true;             // keyword detection shared|replicated
  // keyword solve: auto (distributed on more than one rank when the keywords allow it,
  // else replicated), replicated or distributed; distributed_ the mode taken
  enum class SolveChoice { automatic, replicated, distributed };
  SolveChoice solve_choice_ = SolveChoice::automatic;
  bool distributed_ = false;
  std::unique_ptr<wiregrain_lmp::RankGrains> rank_grains_;  // solve distributed
  double largest_radius_ = 0.0;             // of the group's grains, at init
  double largest_activation_ = 0.0;         // of the steps so far (solve distributed)
  bigint shapes_released_at_ = -1;          // the reneighbouring at which the absent grains' shapes were dropped (solve distributed)
  long projections_ = 0;                    // pair corrections since the fix was made
  double projected_depth_ = 0.0;            // deepest end-of-step overlap / pair size, last solve
  double stick_solves_[3] = {0.0, 0.0, 0.0};  // method subspace: tried, kept, factorisations, since the fix was made
  double timings_[2];                       // wall-clock seconds of the last solve: gather+detection, solve
  double colours_ = 0.0;                    // order coloured: the contact graph's colours summed over the solves
  double solves_ = 0.0, sweeps_ = 0.0;      // solves and their Gauss–Seidel sweeps since the fix was made
  double clocks_[3] = {0.0, 0.0, 0.0};      // the same summed since the fix was made, and the scatter + overlap projection
  std::vector<double> wall_forces_;         // 3 per wall
  double **contact_force_;                  // per grain: force, torque
  double **step_start_velocity_;            // per grain: v_n, L_n of the last solve (θ-method)
  double **force_sum_;                      // per grain: Σ f, Σ torque since the last solve
  double **sleep_state_;                    // per grain: asleep (0/1), quiet time, drift (6), checked load (6) (keyword sleep)
  double sleep_stats_[4] = {0.0, 0.0, 0.0, 0.0}; // last solve: asleep, woken, frozen points, checks
  bigint grains_known_ = 0;                 // grains in the group at the run start or last solve
  int lost_warnings_ = 0;                   // warnings about lost grains so far
  int overlap_warnings_ = 0;                // warnings about large overlaps so far
  int problem_every_ = 0;                   // write the reduced problem every N steps (0: never)
  std::string problem_file_;                // its file name, '*' replaced by the step

  void solve_step();
  wiregrain::PeriodicBox periodic_box() const;
  void check_periodic_box();
  double largest_bounding_radius() const;
  void sync_wall_fixes();
  std::vector<wiregrain::GrainState> gather_grains();
  void write_grain_record(int i, double *record) const;
  // solve distributed (fix_nscd_polyhedra_distributed.cpp): this rank's own grains and
  // ghost grains, the checks of the ghost cutoff, the restart's warm starts of all ranks
  std::vector<wiregrain::GrainState> rank_grains();
  double needed_ghost_cutoff(double activation) const;
  void check_ghost_cutoff(double activation);
  void check_distributed_keywords();
  std::string distributed_refusal() const;  // what solve distributed does not take here ("": none)
  std::vector<double> all_ranks_impulses();
  void scatter_results(const std::vector<wiregrain::GrainState> &, const wiregrain::GrainStepResult &,
                       size_t grain_count);
  wiregrain::WorkShare rank_share();
  void project_overlaps(const std::vector<wiregrain::GrainState> &, const wiregrain::GrainStepProblem &,
                        const wiregrain::GrainStepResult &);
  void record_stats(const wiregrain::GrainStepResult &);
  void check_lost_grains(bigint);
  void check_overlap(const std::vector<wiregrain::GrainState> &, double max_overlap, double h);
  void publish_contacts(const wiregrain::GrainStepResult &);
  [[noreturn]] void solve_failed(const std::exception &);
  void write_problem(const wiregrain::NscdStep &);
};

}  // namespace LAMMPS_NS

#endif
#endif
