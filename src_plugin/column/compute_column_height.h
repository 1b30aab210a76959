/* compute column/height: the height of a granular column, robust to a few stray grains
   (paper Sec. 3: H_n is this height over its value just before the walls move; form the
   ratio in the deck, see below).

   compute ID grain-group column/height [quantile 0.98]

   scalar = the q-quantile of the grains' top heights (each grain's highest point: core
   vertex + sweep radius; stock spheres, common/grain_atoms.h: centre + radius), linear interpolation between order statistics
   (core/column/observables.h); q = 1 is the highest point of all. With q = 0.98 the top
   2 % of the grains are ignored (18 of the paper's 915), so one grain resting on top of
   the column or caught on the wire above it does not change the height.

   H_n in a deck:   variable H0 equal $(c_h)      (immediate: before the walls move)
                    variable Hn equal c_h/${H0} */

#ifdef COMPUTE_CLASS

ComputeStyle(column/height,ComputeColumnHeight)

#else

#ifndef LMP_COMPUTE_COLUMN_HEIGHT_H
#define LMP_COMPUTE_COLUMN_HEIGHT_H

#include "common/grain_atoms.h"
#include "compute.h"

namespace LAMMPS_NS {

class ComputeColumnHeight : public Compute {
 public:
  ComputeColumnHeight(class LAMMPS *, int &iarg, int, char **);
  void init();
  double compute_scalar();

 private:
  double quantile_;
  wiregrain_lmp::GrainAtoms grains_;
};

}  // namespace LAMMPS_NS

#endif
#endif
