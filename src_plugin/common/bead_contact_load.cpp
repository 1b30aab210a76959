#include "bead_contact_load.h"

namespace wiregrain_lmp {

void add_bead_contact_load(double *row, double weight, const wiregrain::SpringDashpot &contact,
                           const Eigen::Vector3d &normal) {
  wiregrain::BeadContactLoad one;
  one.add(weight, contact, normal);
  for (int e = 0; e < 9; e++) {
    row[e] += one.stiffness(e);
    row[9 + e] += one.damping(e);
  }
  row[18] += one.contacts;
}

wiregrain::BeadContactLoad bead_contact_load(const double *row) {
  wiregrain::BeadContactLoad load;
  for (int e = 0; e < 9; e++) {
    load.stiffness(e) = row[e];
    load.damping(e) = row[9 + e];
  }
  load.contacts = int(row[18]);
  return load;
}

}  // namespace wiregrain_lmp
