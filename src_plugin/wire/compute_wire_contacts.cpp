#include "compute_wire_contacts.h"

#include <mpi.h>

#include <algorithm>
#include <string>

#include "atom.h"
#include "error.h"
#include "atom_vec_wire.h"
#include "fix.h"
#include "force.h"
#include "modify.h"
#include "update.h"

#include "atom_kinds.h"
#include "contact_publisher.h"
#include "core/contact/contact_list.h"
#include "plugin_args.h"

using namespace LAMMPS_NS;

ComputeWireContacts::ComputeWireContacts(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg), kind_(0), smallest_radius_(0.0), segments_(0) {
  wiregrain_lmp::StyleArgs args(error, "compute", "wire/contacts", id, narg, arg, iarg, {"kind"});
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "kind") {
      const std::string v = args.value_word(key);
      if (v == "wire_wire") kind_ = int(wiregrain::ContactKind::wire_wire);
      else if (v == "wire_grain") kind_ = int(wiregrain::ContactKind::wire_grain);
      else if (v == "wire_wall") kind_ = int(wiregrain::ContactKind::wire_wall);
      else args.fail("value of 'kind' must be wire_wire, wire_grain or wire_wall, got '" + v + "'");
    } else {
      args.unknown_keyword(key);
    }
  }
  iarg = narg;
  vector_flag = 1;
  size_vector = 5;
  extvector = 0;
  vector = new double[size_vector];
}

ComputeWireContacts::~ComputeWireContacts() { delete[] vector; }

// The style that publishes the kind, the smallest bead radius and the segments (a bead
// of the group with a next bead) of the group.
void ComputeWireContacts::init() {
  const wiregrain::ContactKind kind = wiregrain::ContactKind(kind_);
  const char *needed = kind == wiregrain::ContactKind::wire_grain  ? "wire/grain"
                       : kind == wiregrain::ContactKind::wire_wall ? "wire/wall"
                                                                   : NULL;
  if (!needed && !force->pair_match("wire/contact", 1))
    wiregrain_lmp::style_error(error, "compute", "wire/contacts", id, "needs pair_style wire/contact");
  if (needed) {
    bool found = false;
    for (int k = 0; k < modify->nfix; k++) found = found || std::string(modify->fix[k]->style) == needed;
    if (!found)
      wiregrain_lmp::style_error(error, "compute", "wire/contacts", id,
                                 std::string("kind ") + wiregrain::contact_kind_name(kind) + " needs a fix " + needed);
  }
  AtomVecWire *wire = AtomVecWire::of(atom);
  const wiregrain_lmp::AtomKinds kinds(lmp);
  double local = 1e300;
  long segments = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || kinds.is_grain(i)) continue;  // the beads of the group
    local = std::min(local, atom->radius[i]);
    if (wire && wire->wire_next[i]) segments++;
  }
  MPI_Allreduce(&local, &smallest_radius_, 1, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(&segments, &segments_, 1, MPI_LONG, MPI_SUM, world);
}

void ComputeWireContacts::compute_vector() {
  invoked_vector = update->ntimestep;
  const wiregrain::ContactSummary summary =
      wiregrain_lmp::global_contact_summary(lmp, wiregrain::ContactKind(kind_));
  vector[0] = summary.contacts;
  vector[1] = summary.max_overlap;
  vector[2] = smallest_radius_ > 0.0 && smallest_radius_ < 1e300 ? vector[1] / smallest_radius_ : 0.0;
  vector[3] = summary.evaluations;
  vector[4] = wiregrain::coordination_number(summary.contacts, segments_);
}
