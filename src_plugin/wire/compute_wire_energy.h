/* compute wire/energy: elastic energy and length of the wire beads in a group, from the
   forces fix wire/elastic computed this step (several wires can be told apart by group).

   compute ID group wire/energy [fix fix-ID]

   fix: the fix wire/elastic to read (default: the only one defined).
   vector = [stretching energy, bending energy, elastic energy U_s, wire length L, U_s/L]
   summed over the beads of the group (the length counts each segment once, with its
   first bead); per-atom array = [stretching energy, bending energy, segment length].
   Reads the fix through the WireEnergySource interface; the sums are core's
   WireEnergyTotals. */

#ifdef COMPUTE_CLASS

ComputeStyle(wire/energy,ComputeWireEnergy)

#else

#ifndef LMP_COMPUTE_WIRE_ENERGY_H
#define LMP_COMPUTE_WIRE_ENERGY_H

#include "compute.h"
#include "common/wire_energy_source.h"

namespace LAMMPS_NS {

class ComputeWireEnergy : public Compute {
 public:
  ComputeWireEnergy(class LAMMPS *, int &iarg, int, char **);
  ~ComputeWireEnergy();
  void init();
  void compute_vector();
  void compute_peratom();
  double memory_usage();

 private:
  char *fix_id_;
  const wiregrain_lmp::WireEnergySource *source_;  // the fix wire/elastic read
  double **bead_values_;
  int nmax_;
  void check_current();
};

}  // namespace LAMMPS_NS

#endif
#endif
