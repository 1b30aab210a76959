#include "bead_contact_load.h"

namespace wiregrain_lmp {

wiregrain::BeadContactLoad bead_contact_load(const double *row) {
  wiregrain::ContactLoadEntries sums;
  for (int e = 0; e < 6; e++) {
    sums.stiffness[e] = row[e];
    sums.damping[e] = row[6 + e];
  }
  wiregrain::BeadContactLoad load;
  load.add(1.0, sums);
  load.contacts = int(row[12]);
  return load;
}

}  // namespace wiregrain_lmp
