#include "atom_vec_wire.h"

#include <cstdlib>
#include <cstring>
#include <string>

#include "atom.h"
#include "atom_vec_hybrid.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "memory.h"
#include "modify.h"

#include "bead_contact_load.h"
#include "plugin_args.h"
#include "plugin_comm.h"

using namespace LAMMPS_NS;

namespace {
constexpr int kDelta = 10000;
// values sent to a ghost besides its position: tag type mask radius rmass prev next rest
constexpr int kBeadValues = 8;
// values per bead in a restart record, besides the leading count
constexpr int kRestartValues = 15;
}  // namespace

AtomVecWire::AtomVecWire(LAMMPS *lmp) : PluginAtomVec(lmp) {
  molecular = 0;
  comm_x_only = 1;
  comm_f_only = 1;
  size_forward = 3;
  size_reverse = 3;
  size_border = 3 + kBeadValues;
  size_velocity = 3;
  size_data_atom = 10;
  size_data_vel = 4;
  xcol_data = 8;

  atom->radius_flag = atom->rmass_flag = 1;
  wire_prev = wire_next = NULL;
  wire_rest = NULL;
  contact_load = NULL;
  contact_load_wanted = false;
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

void AtomVecWire::grow(int n) {
  if (n == 0) nmax += kDelta;
  else nmax = n;
  atom->nmax = nmax;
  if (nmax < 0 || nmax > MAXSMALLINT) error->one(FLERR, "atom_style wire: per-processor system is too big");

  tag = memory->grow(atom->tag, nmax, "atom:tag");
  type = memory->grow(atom->type, nmax, "atom:type");
  mask = memory->grow(atom->mask, nmax, "atom:mask");
  image = memory->grow(atom->image, nmax, "atom:image");
  x = memory->grow(atom->x, nmax, 3, "atom:x");
  v = memory->grow(atom->v, nmax, 3, "atom:v");
  f = memory->grow(atom->f, nmax * comm->nthreads, 3, "atom:f");
  radius = memory->grow(atom->radius, nmax, "atom:radius");
  rmass = memory->grow(atom->rmass, nmax, "atom:rmass");
  memory->grow(wire_prev, nmax, "atom:wire_prev");
  memory->grow(wire_next, nmax, "atom:wire_next");
  memory->grow(wire_rest, nmax, "atom:wire_rest");
  memory->grow(contact_load, nmax, wiregrain_lmp::kBeadContactLoadSize, "atom:contact_load");

  if (atom->nextra_grow)
    for (int iextra = 0; iextra < atom->nextra_grow; iextra++)
      modify->fix[atom->extra_grow[iextra]]->grow_arrays(nmax);
}

void AtomVecWire::grow_reset() {
  tag = atom->tag;
  type = atom->type;
  mask = atom->mask;
  image = atom->image;
  x = atom->x;
  v = atom->v;
  f = atom->f;
  radius = atom->radius;
  rmass = atom->rmass;
}

void AtomVecWire::copy(int i, int j, int delflag) {
  tag[j] = tag[i];
  type[j] = type[i];
  mask[j] = mask[i];
  image[j] = image[i];
  for (int d = 0; d < 3; d++) {
    x[j][d] = x[i][d];
    v[j][d] = v[i][d];
  }
  radius[j] = radius[i];
  rmass[j] = rmass[i];
  wire_prev[j] = wire_prev[i];
  wire_next[j] = wire_next[i];
  wire_rest[j] = wire_rest[i];

  if (atom->nextra_grow)
    for (int iextra = 0; iextra < atom->nextra_grow; iextra++)
      modify->fix[atom->extra_grow[iextra]]->copy_arrays(i, j, delflag);
}

int AtomVecWire::pack_comm(int n, int *list, double *buf, int pbc_flag, int *pbc) {
  double s[3];
  wiregrain_lmp::periodic_image_shift(domain, pbc_flag, pbc, false, s);
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    buf[m++] = x[j][0] + s[0];
    buf[m++] = x[j][1] + s[1];
    buf[m++] = x[j][2] + s[2];
  }
  return m;
}

int AtomVecWire::pack_comm_vel(int n, int *list, double *buf, int pbc_flag, int *pbc) {
  double s[3];
  wiregrain_lmp::periodic_image_shift(domain, pbc_flag, pbc, false, s);
  double dv[3];
  wiregrain_lmp::deforming_image_velocity(pbc_flag, pbc, deform_vremap, h_rate, dv);
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    const bool remap = pbc_flag && deform_vremap && (mask[j] & deform_groupbit);
    for (int d = 0; d < 3; d++) buf[m++] = x[j][d] + s[d];
    for (int d = 0; d < 3; d++) buf[m++] = v[j][d] + (remap ? dv[d] : 0.0);
  }
  return m;
}

void AtomVecWire::unpack_comm(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int d = 0; d < 3; d++) x[i][d] = buf[m++];
}

void AtomVecWire::unpack_comm_vel(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++) {
    for (int d = 0; d < 3; d++) x[i][d] = buf[m++];
    for (int d = 0; d < 3; d++) v[i][d] = buf[m++];
  }
}

int AtomVecWire::pack_reverse(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int d = 0; d < 3; d++) buf[m++] = f[i][d];
  return m;
}

void AtomVecWire::unpack_reverse(int n, int *list, double *buf) {
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    for (int d = 0; d < 3; d++) f[j][d] += buf[m++];
  }
}

int AtomVecWire::pack_ghost(int j, double *buf) const {
  int m = 0;
  buf[m++] = ubuf(tag[j]).d;
  buf[m++] = ubuf(type[j]).d;
  buf[m++] = ubuf(mask[j]).d;
  buf[m++] = radius[j];
  buf[m++] = rmass[j];
  buf[m++] = ubuf(wire_prev[j]).d;
  buf[m++] = ubuf(wire_next[j]).d;
  buf[m++] = wire_rest[j];
  return m;
}

int AtomVecWire::unpack_ghost(int i, const double *buf) {
  int m = 0;
  tag[i] = (int)ubuf(buf[m++]).i;
  type[i] = (int)ubuf(buf[m++]).i;
  mask[i] = (int)ubuf(buf[m++]).i;
  radius[i] = buf[m++];
  rmass[i] = buf[m++];
  wire_prev[i] = (int)ubuf(buf[m++]).i;
  wire_next[i] = (int)ubuf(buf[m++]).i;
  wire_rest[i] = buf[m++];
  return m;
}

int AtomVecWire::pack_ghost_velocity(int j, double *buf, const double dv[3]) const {
  for (int d = 0; d < 3; d++) buf[d] = v[j][d] + dv[d];
  return 3;
}

int AtomVecWire::unpack_ghost_velocity(int i, const double *buf) {
  for (int d = 0; d < 3; d++) v[i][d] = buf[d];
  return 3;
}

int AtomVecWire::record_size() const { return kRestartValues; }

// In atom_style hybrid the base style packs x, tag, type, mask; the sub-style the rest.
int AtomVecWire::pack_border_hybrid(int n, int *list, double *buf) {
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    buf[m++] = radius[j];
    buf[m++] = rmass[j];
    buf[m++] = ubuf(wire_prev[j]).d;
    buf[m++] = ubuf(wire_next[j]).d;
    buf[m++] = wire_rest[j];
  }
  return m;
}

int AtomVecWire::unpack_border_hybrid(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++) {
    radius[i] = buf[m++];
    rmass[i] = buf[m++];
    wire_prev[i] = (int)ubuf(buf[m++]).i;
    wire_next[i] = (int)ubuf(buf[m++]).i;
    wire_rest[i] = buf[m++];
  }
  return m;
}

// One grain/bead as exchange and restart records carry it: x, v, image, then the
// values a ghost gets.
int AtomVecWire::pack_record(int i, double *buf) const {
  int m = 0;
  for (int d = 0; d < 3; d++) buf[m++] = x[i][d];
  for (int d = 0; d < 3; d++) buf[m++] = v[i][d];
  buf[m++] = ubuf(image[i]).d;
  return m + pack_ghost(i, &buf[m]);
}

int AtomVecWire::unpack_record(int i, const double *buf) {
  int m = 0;
  for (int d = 0; d < 3; d++) x[i][d] = buf[m++];
  for (int d = 0; d < 3; d++) v[i][d] = buf[m++];
  image[i] = (tagint)ubuf(buf[m++]).i;
  return m + unpack_ghost(i, &buf[m]);
}

// A bead made by create_atoms or an insertion fix: unlinked, the paper's wire radius,
// the mass of one Table 1 segment (ρ_w π r_w² l_w = 0.5·π·0.01·0.2). create_wire sets
// the real values.
void AtomVecWire::create_atom(int itype, double *coord) {
  const int nlocal = atom->nlocal;
  if (nlocal == nmax) grow(0);
  tag[nlocal] = 0;
  type[nlocal] = itype;
  for (int d = 0; d < 3; d++) {
    x[nlocal][d] = coord[d];
    v[nlocal][d] = 0.0;
  }
  mask[nlocal] = 1;
  image[nlocal] = ((tagint)IMGMAX << IMG2BITS) | ((tagint)IMGMAX << IMGBITS) | IMGMAX;
  radius[nlocal] = 0.1;
  rmass[nlocal] = 0.5 * 3.14159265358979323846 * 0.01 * 0.2;
  wire_prev[nlocal] = 0;
  wire_next[nlocal] = 0;
  wire_rest[nlocal] = 0.0;
  wiregrain_lmp::clear_restart_record(lmp, nlocal);
  atom->nlocal++;
}

namespace {
[[noreturn]] void data_error(Error *error, const std::string &what) {
  error->one(FLERR, ("atom_style wire: Atoms section of data file: " + what).c_str());
  std::abort();
}
int data_tag(Error *error, const char *word, const char *name) {
  char *end = NULL;
  const long value = std::strtol(word, &end, 10);
  if (end == word || *end != '\0' || value < 0)
    data_error(error, std::string(name) + " must be a bead ID >= 0 (0: free end), got '" + word + "'");
  return (int)value;
}
double data_value(Error *error, const char *word, const char *name, bool positive) {
  double value = 0.0;
  if (!wiregrain_lmp::parse_finite_number(word, value) || !(positive ? value > 0.0 : value >= 0.0))
    data_error(error, std::string(name) + (positive ? " must be a finite number > 0" : " must be a finite number >= 0") +
                          ", got '" + word + "'");
  return value;
}
}  // namespace

void AtomVecWire::data_atom(double *coord, tagint imagetmp, char **values) {
  const int nlocal = atom->nlocal;
  if (nlocal == nmax) grow(0);
  tag[nlocal] = atoi(values[0]);
  if (tag[nlocal] <= 0) data_error(error, std::string("invalid atom ID '") + values[0] + "'");
  type[nlocal] = atoi(values[1]);
  if (type[nlocal] <= 0 || type[nlocal] > atom->ntypes)
    data_error(error, std::string("invalid atom type '") + values[1] + "'");
  data_atom_hybrid(nlocal, &values[2]);
  for (int d = 0; d < 3; d++) {
    x[nlocal][d] = coord[d];
    v[nlocal][d] = 0.0;
  }
  image[nlocal] = imagetmp;
  mask[nlocal] = 1;
  atom->nlocal++;
}

// Velocities section: id vx vy vz, each a finite number (LIGGGHTS' own reader takes "1.0x"
// as 1 and "abc" as 0)
void AtomVecWire::data_vel(int m, char **values) {
  for (int d = 0; d < 3; d++) {
    double value = 0.0;
    if (!wiregrain_lmp::parse_finite_number(values[d], value))
      error->one(FLERR, ("atom_style wire: Velocities section of data file: v" + std::string(1, "xyz"[d]) +
                         " of atom " + std::to_string(atom->tag[m]) + " must be a finite number, got '" + values[d] +
                         "'")
                            .c_str());
    atom->v[m][d] = value;
  }
}

int AtomVecWire::data_atom_hybrid(int nlocal, char **values) {
  wire_prev[nlocal] = data_tag(error, values[0], "wire-prev");
  wire_next[nlocal] = data_tag(error, values[1], "wire-next");
  wire_rest[nlocal] = data_value(error, values[2], "rest-length", false);
  if (wire_next[nlocal] != 0 && wire_rest[nlocal] <= 0.0)
    data_error(error, std::string("rest-length must be > 0 for a bead with a next bead, got '") +
                          values[2] + "'");
  radius[nlocal] = data_value(error, values[3], "radius", true);
  rmass[nlocal] = data_value(error, values[4], "mass", true);
  return 5;
}

void AtomVecWire::pack_data(double **buf) {
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++) {
    buf[i][0] = ubuf(tag[i]).d;
    buf[i][1] = ubuf(type[i]).d;
    pack_data_hybrid(i, &buf[i][2]);
    buf[i][7] = x[i][0];
    buf[i][8] = x[i][1];
    buf[i][9] = x[i][2];
    buf[i][10] = ubuf((image[i] & IMGMASK) - IMGMAX).d;
    buf[i][11] = ubuf((image[i] >> IMGBITS & IMGMASK) - IMGMAX).d;
    buf[i][12] = ubuf((image[i] >> IMG2BITS) - IMGMAX).d;
  }
}

int AtomVecWire::pack_data_hybrid(int i, double *buf) {
  buf[0] = ubuf(wire_prev[i]).d;
  buf[1] = ubuf(wire_next[i]).d;
  buf[2] = wire_rest[i];
  buf[3] = radius[i];
  buf[4] = rmass[i];
  return 5;
}

void AtomVecWire::write_data(FILE *fp, int n, double **buf) {
  for (int i = 0; i < n; i++) {
    fprintf(fp, "%d %d", (int)ubuf(buf[i][0]).i, (int)ubuf(buf[i][1]).i);
    write_data_hybrid(fp, &buf[i][2]);
    fprintf(fp, " %-1.16e %-1.16e %-1.16e %d %d %d\n", buf[i][7], buf[i][8], buf[i][9],
            (int)ubuf(buf[i][10]).i, (int)ubuf(buf[i][11]).i, (int)ubuf(buf[i][12]).i);
  }
}

int AtomVecWire::write_data_hybrid(FILE *fp, double *buf) {
  fprintf(fp, " %d %d %-1.16e %-1.16e %-1.16e", (int)ubuf(buf[0]).i, (int)ubuf(buf[1]).i,
          buf[2], buf[3], buf[4]);
  return 5;
}

bigint AtomVecWire::memory_usage() {
  bigint bytes = 0;
  if (atom->memcheck("tag")) bytes += memory->usage(tag, nmax);
  if (atom->memcheck("type")) bytes += memory->usage(type, nmax);
  if (atom->memcheck("mask")) bytes += memory->usage(mask, nmax);
  if (atom->memcheck("image")) bytes += memory->usage(image, nmax);
  if (atom->memcheck("x")) bytes += memory->usage(x, nmax, 3);
  if (atom->memcheck("v")) bytes += memory->usage(v, nmax, 3);
  if (atom->memcheck("f")) bytes += memory->usage(f, nmax * comm->nthreads, 3);
  if (atom->memcheck("radius")) bytes += memory->usage(radius, nmax);
  if (atom->memcheck("rmass")) bytes += memory->usage(rmass, nmax);
  bytes += memory->usage(wire_prev, nmax);
  bytes += memory->usage(wire_next, nmax);
  bytes += memory->usage(wire_rest, nmax);
  bytes += memory->usage(contact_load, nmax, wiregrain_lmp::kBeadContactLoadSize);
  return bytes;
}
