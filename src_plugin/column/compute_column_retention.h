/* compute column/retention: the fraction of grains retained inside the wire (paper
   Sec. 3, φ_p).

   compute ID grain-group column/retention (wire-group | radius r) [axis cx cy]

   The cylinder: vertical, about the axis through (cx, cy) (default: the centre of the
   simulation box in x and y), of radius R̄ = the mean horizontal distance of the beads of
   wire-group from the axis, or the fixed radius r (a column without wire, measured in the
   cylinder its wire would have had). vector = [φ_p = grains with their centre inside the cylinder /
   grains of grain-group, R̄, grains inside, grains] (core/column/observables.h). */

#ifdef COMPUTE_CLASS

ComputeStyle(column/retention,ComputeColumnRetention)

#else

#ifndef LMP_COMPUTE_COLUMN_RETENTION_H
#define LMP_COMPUTE_COLUMN_RETENTION_H

#include <string>

#include "common/grain_atoms.h"
#include "compute.h"

namespace LAMMPS_NS {

class ComputeColumnRetention : public Compute {
 public:
  ComputeColumnRetention(class LAMMPS *, int &iarg, int, char **);
  ~ComputeColumnRetention();
  void init();
  void compute_vector();

 private:
  wiregrain_lmp::GrainAtoms grains_;
  std::string wire_group_;
  int wire_groupbit_;
  bool axis_given_;
  double axis_[2];
  double fixed_radius_;  // > 0: `radius r` given instead of a wire group
};

}  // namespace LAMMPS_NS

#endif
#endif
