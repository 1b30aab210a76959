/* The springs and dashpots the contacts of one step put on each bead (the formula:
   core/contact/contact_time_step.h, BeadContactLoad), kept as a row of doubles
   per bead by atom_style wire (contact_load: the six entries xx, yy, zz, xy, xz, yz of K,
   the same of Γ, then the count of contacts). The contact styles (pair wire/contact, fix
   wire/wall, fix wire/grain) form each contact's entries once and add them to its beads
   where they add its forces, owned and ghost; fix nve/gear clears the rows before the
   forces, sums the ghosts' rows to their owners after them and checks each bead: a bead
   wedged between grains carries many contacts at once, and the single-contact check at
   the run start does not see it. Included by .cpp files only (Eigen stays out of the
   headers LIGGGHTS' style lists include). */

#ifndef WIREGRAIN_BEAD_CONTACT_LOAD_H
#define WIREGRAIN_BEAD_CONTACT_LOAD_H

#include "core/contact/contact_time_step.h"

namespace wiregrain_lmp {

constexpr int kBeadContactLoadSize = 13;

inline void add_bead_contact_load(double *row, double weight, const wiregrain::ContactLoadEntries &contact) {
  for (int e = 0; e < 6; e++) {
    row[e] += weight * contact.stiffness[e];
    row[6 + e] += weight * contact.damping[e];
  }
  row[12] += 1.0;
}
wiregrain::BeadContactLoad bead_contact_load(const double *row);

}  // namespace wiregrain_lmp

#endif
