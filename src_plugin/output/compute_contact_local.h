/* compute contact/local: every contact the plugin's styles published in the last force
   call or solve, one row each, for dump local (LIGGGHTS' own format for per-contact data):
   grain–grain and grain–wall (fix nscd/polyhedra), wire–grain (fix wire/grain), wire–wire
   (pair wire/contact), wire–wall (fix wire/wall).

   compute ID group contact/local [kind K ...]

   local array, 16 columns: kind, id_a, id_b, point (3), normal (3), f_n, force (3), f_t,
   overlap, status. docs/commands/compute_contact_local.md. */

#ifdef COMPUTE_CLASS

ComputeStyle(contact/local,ComputeContactLocal)

#else

#ifndef LMP_COMPUTE_CONTACT_LOCAL_H
#define LMP_COMPUTE_CONTACT_LOCAL_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeContactLocal : public Compute {
 public:
  ComputeContactLocal(class LAMMPS *, int &iarg, int, char **);
  ~ComputeContactLocal();
  void init();
  void compute_local();
  double memory_usage();

 private:
  bool kinds_[5];  // which wiregrain::ContactKind are listed
  double **rows_;
  int capacity_;
  bool in_group(long body) const;
};

}  // namespace LAMMPS_NS

#endif
#endif
