/* compute wire/contacts: statistics of the wire's contacts of one kind in the current
   step, read from the published contact lists (common/contact_publisher.h).

   compute ID group wire/contacts [kind wire_wire|wire_grain|wire_wall]

   kind: wire_wire (default; pair wire/contact), wire_grain (fix wire/grain), wire_wall
   (fix wire/wall). vector = [number of contacts, largest overlap, largest overlap /
   smallest bead radius of the group, exact distance evaluations, contacts per wire
   segment of the group (a bead with a next bead): for wire_grain the paper's wire–grain
   coordination z_wpc]. */

#ifdef COMPUTE_CLASS

ComputeStyle(wire/contacts,ComputeWireContacts)

#else

#ifndef LMP_COMPUTE_WIRE_CONTACTS_H
#define LMP_COMPUTE_WIRE_CONTACTS_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeWireContacts : public Compute {
 public:
  ComputeWireContacts(class LAMMPS *, int &iarg, int, char **);
  ~ComputeWireContacts();
  void init();
  void compute_vector();

 private:
  int kind_;  // a wiregrain::ContactKind
  double smallest_radius_;
  long segments_;
};

}  // namespace LAMMPS_NS

#endif
#endif
