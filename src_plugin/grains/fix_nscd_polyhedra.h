/* fix nscd/polyhedra: Non-Smooth Contact Dynamics of the grains (atom_style polyhedron),
   Moreau–Jean time stepping with the exact Signorini–Coulomb law solved by nonlinear
   Gauss–Seidel over contact points (DESIGN.md section 3; core/nscd_solver.h).

   fix ID group nscd/polyhedra [friction 0.5] [tolerance 1e-4] [max_iterations 1000]
       [order forward|alternating|random] [seed 1] [warm_start yes|no] [restitution 0]
       [theta 1] [overlap_recovery 1] [overlap_speed 0.1] [damping 0]
       [convergence natural_map|increment|both]
       [margin 0] [write_problems N file_*.txt] [wall px py pz nx ny nz [wall_friction mu] [wall_velocity vx vy vz]] ...

   Each step: at the end of step n, with the forces and torques of step n (gravity
   and every other style's), the free velocities v + h F/m, L + h T are corrected by the
   contact impulses of all contact points whose gap g at the current positions is below
   the activation distance; non-penetration is imposed with gap anticipation,
   g + h((1 − θ) u_n^n + θ u_n^{n+1}) ≥ 0. The positions follow at the start of step n+1:
   x += h((1 − θ) v_n + θ v_{n+1}), the orientation by the exact torque-free rotation with
   (1 − θ) L_n + θ L_{n+1} (θ = 1 by default). v_n and L_n of each grain are kept per atom
   (they migrate and restart), so velocities set between runs are honoured. Walls are planes of
   infinite mass, each with its own friction and velocity.

   MPI: every rank gathers all grains of the group, detects and solves the same contact
   problem in the same order and keeps its own grains' results (replicated solve), so 1
   and N ranks give the same state to the last bit; the cost of the solve does not
   shrink with more ranks.

   Outputs: vector [sweeps, residual, contact points, largest overlap at the step start,
   largest predicted penetration, steps that hit the iteration cap, then for each wall
   the force the grains exert on it (x, y, z), then the wall-clock seconds of the last
   step spent in gathering + contact detection and in the solve, then the largest overlap
   of all steps since the fix was defined]; per-atom array [contact force (3),
   contact torque about the centre (3)] of each grain (impulses / h). */

#ifdef FIX_CLASS

FixStyle(nscd/polyhedra,FixNSCDPolyhedra)

#else

#ifndef LMP_FIX_NSCD_POLYHEDRA_H
#define LMP_FIX_NSCD_POLYHEDRA_H

#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "fix.h"

namespace wiregrain {
struct NscdStep;
struct NscdOptions;
}

namespace LAMMPS_NS {

class FixNSCDPolyhedra : public Fix {
 public:
  FixNSCDPolyhedra(class LAMMPS *, int, char **);
  int setmask();
  void init();
  void setup(int);
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

  struct Wall {
    double point[3], normal[3], velocity[3];
    double friction;
  };
  // one impulse of the last step, kept for the warm start: world-frame position and
  // impulse of a contact point of the pair (tag_a, tag_b); tag_a < 0 for wall −tag_a−1
  struct StoredImpulse {
    double position[3];
    double impulse[3];
  };

 private:
  double friction_, tolerance_, restitution_, margin_, theta_, overlap_recovery_, overlap_speed_, damping_;
  int max_iterations_, order_, convergence_;
  long seed_;
  bool warm_start_;
  std::vector<Wall> walls_;         // current positions, moved by velocity·h every step
  class AtomVecPolyhedron *grains_;
  bool solved_once_;                // a contact solve happened (setup of the first run)
  std::map<std::pair<int, int>, std::vector<StoredImpulse> > impulses_;
  double stats_[6];
  double largest_overlap_ = 0.0;         // over all steps since the fix was made
  double timings_[2];                     // wall-clock seconds of the last step: gather+detection, solve
  std::vector<double> wall_forces_;       // 3 per wall
  double **contact_force_;                // per grain: force, torque
  double **step_start_velocity_;          // per grain: v_n, L_n of the last solve (θ-method)

  void solve_step();
  int problem_every_ = 0;      // write the reduced problem every N steps (0: never)
  std::string problem_file_;  // its file name, '*' replaced by the step
  void write_problem(const wiregrain::NscdStep &, const wiregrain::NscdOptions &);
};

}  // namespace LAMMPS_NS

#endif
#endif
