/* compute grain/shape: per grain, what a post-processor needs to redraw it from a dump
   (through dump custom, for existing DEM post-processing).

   compute ID group grain/shape

   per-atom array: [shape, qw, qi, qj, qk, bounding radius, top]
     shape: the library index of a polyhedron (atom_style polyhedron; `grain_shapes write`
     writes the library), −1 for a stock sphere, −3 for a stock superquadric
     (common/grain_atoms.h), −2 for an atom that is no grain (a wire bead) or outside the
     group (its other columns 0);
     q: orientation body → space (a sphere: 1 0 0 0); bounding radius: the farthest surface
     point from the centre of mass (a sphere's radius; a superquadric's is LIGGGHTS' own
     bounding radius); top: the grain's highest point
     (what compute column/height takes the quantile of).

   In a dump:  dump d all custom N f.dump id type x y z vx vy vz radius c_gs[1] c_gs[2] ... */

#ifdef COMPUTE_CLASS

ComputeStyle(grain/shape,ComputeGrainShape)

#else

#ifndef LMP_COMPUTE_GRAIN_SHAPE_H
#define LMP_COMPUTE_GRAIN_SHAPE_H

#include "common/grain_atoms.h"
#include "compute.h"

namespace LAMMPS_NS {

class ComputeGrainShape : public Compute {
 public:
  ComputeGrainShape(class LAMMPS *, int &iarg, int, char **);
  ~ComputeGrainShape();
  void init() {}
  void compute_peratom();
  double memory_usage();

 private:
  wiregrain_lmp::GrainAtoms grains_;
  double **values_;
  int nmax_;
};

}  // namespace LAMMPS_NS

#endif
#endif
