#include "contact_publisher.h"

#include "core/contact/contact_list.h"

#include <mpi.h>

#include "force.h"
#include "lammps.h"
#include "modify.h"
#include "fix.h"
#include "pair.h"

namespace wiregrain_lmp {

std::vector<const ContactPublisher *> contact_publishers(LAMMPS_NS::LAMMPS *lmp) {
  std::vector<const ContactPublisher *> found;
  if (lmp->force->pair)
    if (const auto *p = dynamic_cast<const ContactPublisher *>(lmp->force->pair)) found.push_back(p);
  for (int k = 0; k < lmp->modify->nfix; k++)
    if (const auto *p = dynamic_cast<const ContactPublisher *>(lmp->modify->fix[k])) found.push_back(p);
  return found;
}

wiregrain::ContactSummary global_contact_summary(LAMMPS_NS::LAMMPS *lmp, wiregrain::ContactKind kind) {
  wiregrain::ContactSummary local;
  for (const ContactPublisher *p : contact_publishers(lmp)) local.merge(wiregrain::summarize(p->published_contacts(), kind));
  double sums[4] = {double(local.contacts), double(local.points), local.normal_force_sum, double(local.evaluations)};
  double totals[4];
  MPI_Allreduce(sums, totals, 4, MPI_DOUBLE, MPI_SUM, lmp->world);
  wiregrain::ContactSummary global;
  global.contacts = long(totals[0]);
  global.points = long(totals[1]);
  global.normal_force_sum = totals[2];
  global.evaluations = long(totals[3]);
  MPI_Allreduce(&local.max_overlap, &global.max_overlap, 1, MPI_DOUBLE, MPI_MAX, lmp->world);
  return global;
}

}  // namespace wiregrain_lmp
