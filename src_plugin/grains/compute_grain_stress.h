/* compute grain/stress: per grain, the Love–Weber stress of its contact forces,
   σ_i = (1/V_i) Σ_c (x_c − x_i) ⊗ f_c (core/contact/contact_stress.h), from the contacts the
   plugin's styles published in the last force call or solve (grain–grain and grain–wall of
   fix nscd/polyhedra, wire–grain of fix wire/grain).

   compute ID group grain/stress

   per-atom array, 10 columns: σ_xx σ_yy σ_zz σ_xy σ_xz σ_yz σ_yx σ_zx σ_zy, and the pressure
   p = −(σ_xx + σ_yy + σ_zz)/3; zero for atoms outside the group and for wire beads.
   docs/commands/compute_grain_stress.md. */

#ifdef COMPUTE_CLASS

ComputeStyle(grain/stress,ComputeGrainStress)

#else

#ifndef LMP_COMPUTE_GRAIN_STRESS_H
#define LMP_COMPUTE_GRAIN_STRESS_H

#include "compute.h"

namespace wiregrain_lmp {
class GrainShapeSource;
}

namespace LAMMPS_NS {

class ComputeGrainStress : public Compute {
 public:
  ComputeGrainStress(class LAMMPS *, int &iarg, int, char **);
  ~ComputeGrainStress();
  void init();
  void compute_peratom();
  int pack_reverse_comm(int, int, double *);
  void unpack_reverse_comm(int, int *, double *);
  double memory_usage();

 private:
  const wiregrain_lmp::GrainShapeSource *grains_;
  double **moments_;  // Σ (x_c − x_i) ⊗ f_c per owned and ghost atom, row-major 3×3
  double **values_;   // the output
  int nmax_;
  void grow();
  void add_contact(long body, const double *point, const double *force);
};

}  // namespace LAMMPS_NS

#endif
#endif
