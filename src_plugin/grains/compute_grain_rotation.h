/* compute grain/rotation: orientation and rotation of grains (atom_style polyhedron).

   compute ID group grain/rotation

   per-atom array: [qw, qi, qj, qk (body → space), ω₁, ω₂, ω₃ (angular velocity in the
   body frame, principal axes with ascending moments), rotational kinetic energy ½ ω·L]
   vector: [rotational kinetic energy of the group, Lx, Ly, Lz (total angular momentum
   about the grains' own centres, space frame)]
   Only the grains with a shape count: other atoms of the group (wire beads, atoms without a
   shape) get zero rows and add nothing. */

#ifdef COMPUTE_CLASS

ComputeStyle(grain/rotation,ComputeGrainRotation)

#else

#ifndef LMP_COMPUTE_GRAIN_ROTATION_H
#define LMP_COMPUTE_GRAIN_ROTATION_H

#include "common/atom_kinds.h"
#include "compute.h"

namespace LAMMPS_NS {

class ComputeGrainRotation : public Compute {
 public:
  ComputeGrainRotation(class LAMMPS *, int &iarg, int, char **);
  ~ComputeGrainRotation();
  void init() {}
  void compute_vector();
  void compute_peratom();
  double memory_usage();

 private:
  double **values_;
  int nmax_;
  wiregrain_lmp::AtomKinds kinds_;

  bool counts(int i) const;  // a grain of the group with a shape
};

}  // namespace LAMMPS_NS

#endif
#endif
