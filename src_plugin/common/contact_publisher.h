/* The one way outputs read contacts: a style that computes contacts derives from
   ContactPublisher and fills its core ContactList (core/contact/contact_list.h) on every
   force call or solve; computes find all publishers with contact_publishers() and combine
   their summaries over the ranks. Each contact is published by one rank only. */

#ifndef WIREGRAIN_CONTACT_PUBLISHER_H
#define WIREGRAIN_CONTACT_PUBLISHER_H

#include <vector>

// declared in core/contact/contact_list.h; not included here, so that style headers, which
// LIGGGHTS' own sources include, need no Eigen
namespace wiregrain {
class ContactList;
struct ContactSummary;
enum class ContactKind;
}

namespace LAMMPS_NS {
class LAMMPS;
}

namespace wiregrain_lmp {

class ContactPublisher {
 public:
  virtual ~ContactPublisher() = default;
  // this rank's part of the contacts of the last force call or solve
  virtual const wiregrain::ContactList &published_contacts() const = 0;
};

// The pair style (when it publishes) and every fix that publishes, in definition order.
std::vector<const ContactPublisher *> contact_publishers(LAMMPS_NS::LAMMPS *lmp);

// Summary of one kind over all publishers and all ranks (sums and maxima by MPI_Allreduce;
// collective: every rank must call it).
wiregrain::ContactSummary global_contact_summary(LAMMPS_NS::LAMMPS *lmp, wiregrain::ContactKind kind);

}  // namespace wiregrain_lmp

#endif
