/* fix nve/gear: integrates point masses (wire beads, or any atom with a mass) with the
   6-value fifth-order Gear predictor–corrector, or with velocity Verlet.

   fix ID group nve/gear [scheme gear5|verlet] [forces position|velocity] [check_every N]

   The Gear history (x'' ... x^(5) per atom; for verlet the last step's x'', used by the
   next step's first half kick) migrates with the atoms and is written to restart files,
   so a restarted run, or a run after another, continues the same trajectory.

   Every check_every-th step (default 10; 0: never) it checks every bead's time step
   against the springs and dashpots the contact styles put on it in that step (atom_style
   wire's contact_load; the formula in core/contact/contact_time_step.h) and warns the
   first 10 times one is beyond the limit of the scheme. Vector: checked steps with such a
   bead since the fix was defined, the largest timestep / limit of the last checked step
   (exact above 0.5; below, the bound from the traces of the loads, which is at least the
   exact value). */

#ifdef FIX_CLASS

FixStyle(nve/gear,FixNVEGear)

#else

#ifndef LMP_FIX_NVE_GEAR_H
#define LMP_FIX_NVE_GEAR_H

#include "common/point_mass_integrator.h"
#include "fix.h"

namespace LAMMPS_NS {

class FixNVEGear : public Fix, public wiregrain_lmp::PointMassIntegrator {
 public:
  FixNVEGear(class LAMMPS *, int, char **);
  ~FixNVEGear();
  int setmask();
  void init();
  void setup(int);
  void initial_integrate(int);
  void pre_force(int);
  void final_integrate();
  void reset_dt();
  double compute_vector(int);
  int pack_reverse_comm(int, int, double *);
  void unpack_reverse_comm(int, int *, double *);
  double memory_usage();
  bool uses_gear() const { return scheme_ == GEAR5; }  // PointMassIntegrator

  void grow_arrays(int);
  void copy_arrays(int, int, int);
  void set_arrays(int);
  int pack_exchange(int, double *);
  int unpack_exchange(int, double *);
  int pack_restart(int, double *);
  void unpack_restart(int, int);
  int size_restart(int);
  int maxsize_restart();

 private:
  enum Scheme { GEAR5, VERLET };
  Scheme scheme_;
  bool velocity_forces_;   // Gear c0 = 3/20 instead of 3/16
  double dt_;
  // per atom: 12 history values (x'', x''', x^(4), x^(5)) and a started flag
  double **history_;
  double mass_of(int i) const;
  void start_history(int i);
  // the contact loads of the beads (atom_style wire; NULL without it)
  class AtomVecWire *wire_;
  void check_contact_loads();
  int check_every_;          // the steps between two checks (0: none)
  bool checking_this_step_;  // set in pre_force of a checked step
  long unstable_steps_;
  double largest_ratio_;
  int load_warnings_;
};

}  // namespace LAMMPS_NS

#endif
#endif
