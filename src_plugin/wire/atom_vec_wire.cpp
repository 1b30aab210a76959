#include "atom_vec_wire.h"

#include <cstdlib>
#include <string>

#include "atom.h"
#include "atom_vec_hybrid.h"
#include "error.h"
#include "memory.h"

#include "bead_contact_load.h"
#include "plugin_args.h"

using namespace LAMMPS_NS;

// The per-bead arrays and the buffers they travel in (common/plugin_atom_vec.h). These
// lists fix the layout of restart records: a restart file is read with the lists it was
// written with. contact_load is grown with the beads but travels nowhere.
AtomVecWire::AtomVecWire(LAMMPS *lmp) : PluginAtomVec(lmp, "wire") {
  atom->radius_flag = atom->rmass_flag = 1;
  radius = rmass = NULL;
  wire_prev = wire_next = NULL;
  wire_rest = NULL;
  contact_load = NULL;
  contact_load_wanted = false;

  add_field("radius", &atom->radius, &radius);
  add_field("rmass", &atom->rmass, &rmass);
  add_field("wire_prev", &wire_prev, nullptr);
  add_field("wire_next", &wire_next, nullptr);
  add_field("wire_rest", &wire_rest, nullptr);
  add_field("contact_load", &contact_load, wiregrain_lmp::kBeadContactLoadSize, nullptr);
  lists_.border = fields({"radius", "rmass", "wire_prev", "wire_next", "wire_rest"});
  lists_.data_atom = fields({"wire_prev", "wire_next", "wire_rest", "radius", "rmass"});
  fields_declared();
}

AtomVecWire::~AtomVecWire() {
  memory->destroy(wire_prev);
  memory->destroy(wire_next);
  memory->destroy(wire_rest);
  memory->destroy(contact_load);
}

AtomVecWire *AtomVecWire::of(Atom *atom) {
  if (AtomVecWire *w = dynamic_cast<AtomVecWire *>(atom->avec)) return w;
  if (AtomVecHybrid *h = dynamic_cast<AtomVecHybrid *>(atom->avec))
    for (int k = 0; k < h->nstyles; k++)
      if (AtomVecWire *w = dynamic_cast<AtomVecWire *>(h->styles[k])) return w;
  return NULL;
}

int AtomVecWire::linked_bead(int link_tag) const {
  if (link_tag <= 0 || link_tag > atom->map_tag_max) return -1;
  return atom->map(link_tag);
}

// Beads find their chain neighbours by tag, so the style needs an atom map; it turns
// the array map on unless the user chose one (atom_modify map hash).
void AtomVecWire::settings(int narg, char **arg) {
  wiregrain_lmp::StyleArgs args(error, "atom_style", "wire", "", narg, arg, 0);
  if (!args.done()) args.unknown_keyword(args.next_keyword());
  if (atom->map_style == 0) atom->map_style = 1;
}

void AtomVecWire::init() {
  AtomVec::init();
  comm_x_only = 1;
  size_forward = 3;
}

// A bead made by create_atoms or an insertion fix: unlinked, the paper's wire radius,
// the mass of one Table 1 segment (ρ_w π r_w² l_w = 0.5·π·0.01·0.2). create_wire sets
// the real values.
void AtomVecWire::create_atom_defaults(int i) {
  radius[i] = 0.1;
  rmass[i] = 0.5 * 3.14159265358979323846 * 0.01 * 0.2;
}

// a link of a data file line: a bead ID >= 0 (0: a free end)
int AtomVecWire::data_link(const char *word, const char *name) const {
  char *end = NULL;
  const long value = std::strtol(word, &end, 10);
  if (end == word || *end != '\0' || value < 0)
    data_error("Atoms", std::string(name) + " must be a bead ID >= 0 (0: free end), got '" + word + "'");
  return (int)value;
}

// a finite number > 0 (positive) or >= 0 of a data file line
double AtomVecWire::data_value(const char *word, const char *name, bool positive) const {
  double value = 0.0;
  if (!wiregrain_lmp::parse_finite_number(word, value) || !(positive ? value > 0.0 : value >= 0.0))
    data_error("Atoms", std::string(name) + (positive ? " must be a finite number > 0" : " must be a finite number >= 0") +
                            ", got '" + word + "'");
  return value;
}

int AtomVecWire::data_atom_hybrid(int nlocal, char **values) {
  wire_prev[nlocal] = data_link(values[0], "wire-prev");
  wire_next[nlocal] = data_link(values[1], "wire-next");
  wire_rest[nlocal] = data_value(values[2], "rest-length", false);
  if (wire_next[nlocal] != 0 && wire_rest[nlocal] <= 0.0)
    data_error("Atoms", std::string("rest-length must be > 0 for a bead with a next bead, got '") + values[2] + "'");
  radius[nlocal] = data_value(values[3], "radius", true);
  rmass[nlocal] = data_value(values[4], "mass", true);
  return 5;
}

