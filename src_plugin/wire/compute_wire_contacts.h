/* compute wire/contacts: statistics of the wire–wire contacts of pair wire/contact in
   the current step, read from the published contact lists (common/contact_publisher.h).

   compute ID all wire/contacts

   vector = [number of contacts, largest overlap, largest overlap / smallest bead radius,
             exact segment–segment distance evaluations] */

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
  double smallest_radius_;
};

}  // namespace LAMMPS_NS

#endif
#endif
