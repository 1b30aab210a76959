#include "compute_wire_contacts.h"

#include <mpi.h>

#include <algorithm>
#include <string>

#include "atom.h"
#include "error.h"
#include "force.h"
#include "update.h"

#include "contact_publisher.h"
#include "core/contact/contact_list.h"
#include "plugin_args.h"

using namespace LAMMPS_NS;

ComputeWireContacts::ComputeWireContacts(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg), smallest_radius_(0.0) {
  wiregrain_lmp::StyleArgs args(error, "compute", "wire/contacts", id, narg, arg, iarg);
  if (!args.done()) args.unknown_keyword(args.next_keyword());
  iarg = narg;
  vector_flag = 1;
  size_vector = 4;
  extvector = 0;
  vector = new double[size_vector];
}

ComputeWireContacts::~ComputeWireContacts() { delete[] vector; }

void ComputeWireContacts::init() {
  if (!force->pair_match("wire/contact", 1))
    wiregrain_lmp::style_error(error, "compute", "wire/contacts", id, "needs pair_style wire/contact");
  double local = 1e300;
  for (int i = 0; i < atom->nlocal; i++) local = std::min(local, atom->radius[i]);
  MPI_Allreduce(&local, &smallest_radius_, 1, MPI_DOUBLE, MPI_MIN, world);
}

void ComputeWireContacts::compute_vector() {
  invoked_vector = update->ntimestep;
  const wiregrain::ContactSummary wire_wire =
      wiregrain_lmp::global_contact_summary(lmp, wiregrain::ContactKind::wire_wire);
  vector[0] = wire_wire.contacts;
  vector[1] = wire_wire.max_overlap;
  vector[2] = smallest_radius_ > 0.0 && smallest_radius_ < 1e300 ? vector[1] / smallest_radius_ : 0.0;
  vector[3] = wire_wire.evaluations;
}
