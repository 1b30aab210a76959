#include "plugin_atom_vec.h"

#include <cstdlib>

#include "atom.h"
#include "atom_vec_hybrid.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "memory.h"
#include "modify.h"

#include "atom_style_part.h"
#include "core/common/validation.h"
#include "plugin_args.h"
#include "plugin_comm.h"

using namespace LAMMPS_NS;

namespace {
constexpr int kDelta = 10000;
}  // namespace

PluginAtomVec::PluginAtomVec(LAMMPS *lmp, const char *style)
    : AtomVec(lmp), style_(style), tag(NULL), type(NULL), mask(NULL), image(NULL), x(NULL), v(NULL), f(NULL) {
  molecular = 0;
}

// ---------------------------------------------------------------------------------------
// declaring the fields

void PluginAtomVec::add_field(const char *name, int **array, int **copy) {
  PerAtomField field;
  field.name = name;
  field.ints = array;
  field.int_copy = copy;
  fields_.push_back(field);
}

void PluginAtomVec::add_field(const char *name, double **array, double **copy) {
  PerAtomField field;
  field.name = name;
  field.values = array;
  field.values_copy = copy;
  fields_.push_back(field);
}

void PluginAtomVec::add_field(const char *name, double ***array, int columns, double ***copy) {
  PerAtomField field;
  field.name = name;
  field.rows = array;
  field.rows_copy = copy;
  field.columns = columns;
  fields_.push_back(field);
}

void PluginAtomVec::add_per_thread_field(const char *name, double ***array, int columns, double ***copy) {
  add_field(name, array, columns, copy);
  fields_.back().per_thread = true;
}

std::vector<int> PluginAtomVec::fields(std::initializer_list<const char *> names) const {
  std::vector<int> list;
  for (const char *name : names) {
    int k = 0;
    while (k < (int)fields_.size() && fields_[k].name != name) k++;
    if (k == (int)fields_.size())
      error->all(FLERR, ("atom_style " + style_ + ": no per-atom field '" + name + "'").c_str());
    list.push_back(k);
  }
  return list;
}

int PluginAtomVec::count(const std::vector<int> &list) const {
  int n = 0;
  for (int k : list) n += fields_[k].columns;
  return n;
}

void PluginAtomVec::fields_declared() {
  comm_x_only = lists_.comm.empty() ? 1 : 0;
  comm_f_only = lists_.reverse.empty() ? 1 : 0;
  size_forward = 3 + count(lists_.comm);
  size_reverse = 3 + count(lists_.reverse);
  size_border = 6 + count(lists_.border);
  size_velocity = 3 + count(lists_.comm_vel);
  size_data_atom = 5 + count(lists_.data_atom);
  size_data_vel = 4 + count(lists_.data_vel);
  xcol_data = 3 + count(lists_.data_atom);
}

// ---------------------------------------------------------------------------------------
// one atom's fields to and from a buffer

void PluginAtomVec::zero_fields(const std::vector<int> &list, int i) {
  for (int k : list) {
    const PerAtomField &field = fields_[k];
    if (field.ints) (*field.ints)[i] = 0;
    else if (field.values) (*field.values)[i] = 0.0;
    else
      for (int c = 0; c < field.columns; c++) (*field.rows)[i][c] = 0.0;
  }
}

void PluginAtomVec::copy_fields(const std::vector<int> &list, int i, int j) {
  for (int k : list) {
    const PerAtomField &field = fields_[k];
    if (field.ints) (*field.ints)[j] = (*field.ints)[i];
    else if (field.values) (*field.values)[j] = (*field.values)[i];
    else
      for (int c = 0; c < field.columns; c++) (*field.rows)[j][c] = (*field.rows)[i][c];
  }
}

int PluginAtomVec::pack_fields(const std::vector<int> &list, int i, double *buf) const {
  int m = 0;
  for (int k : list) {
    const PerAtomField &field = fields_[k];
    if (field.ints) buf[m++] = ubuf((*field.ints)[i]).d;
    else if (field.values) buf[m++] = (*field.values)[i];
    else
      for (int c = 0; c < field.columns; c++) buf[m++] = (*field.rows)[i][c];
  }
  return m;
}

int PluginAtomVec::unpack_fields(const std::vector<int> &list, int i, const double *buf) {
  int m = 0;
  for (int k : list) {
    const PerAtomField &field = fields_[k];
    if (field.ints) (*field.ints)[i] = (int)ubuf(buf[m++]).i;
    else if (field.values) (*field.values)[i] = buf[m++];
    else
      for (int c = 0; c < field.columns; c++) (*field.rows)[i][c] = buf[m++];
  }
  return m;
}

// ---------------------------------------------------------------------------------------
// the local arrays

void PluginAtomVec::grow(int n) {
  if (n == 0) nmax += kDelta;
  else nmax = n;
  atom->nmax = nmax;
  if (nmax < 0 || nmax > MAXSMALLINT)
    error->one(FLERR, ("atom_style " + style_ + ": per-processor system is too big").c_str());

  memory->grow(atom->tag, nmax, "atom:tag");
  memory->grow(atom->type, nmax, "atom:type");
  memory->grow(atom->mask, nmax, "atom:mask");
  memory->grow(atom->image, nmax, "atom:image");
  memory->grow(atom->x, nmax, 3, "atom:x");
  memory->grow(atom->v, nmax, 3, "atom:v");
  memory->grow(atom->f, nmax * comm->nthreads, 3, "atom:f");
  for (const PerAtomField &field : fields_) {
    const std::string label = "atom:" + field.name;
    if (field.ints) memory->grow(*field.ints, nmax, label.c_str());
    else if (field.values) memory->grow(*field.values, nmax, label.c_str());
    else memory->grow(*field.rows, field.per_thread ? nmax * comm->nthreads : nmax, field.columns, label.c_str());
  }
  grow_reset();

  if (atom->nextra_grow)
    for (int iextra = 0; iextra < atom->nextra_grow; iextra++)
      modify->fix[atom->extra_grow[iextra]]->grow_arrays(nmax);
}

void PluginAtomVec::grow_reset() {
  tag = atom->tag;
  type = atom->type;
  mask = atom->mask;
  image = atom->image;
  x = atom->x;
  v = atom->v;
  f = atom->f;
  for (const PerAtomField &field : fields_) {
    if (field.int_copy) *field.int_copy = *field.ints;
    if (field.values_copy) *field.values_copy = *field.values;
    if (field.rows_copy) *field.rows_copy = *field.rows;
  }
}

void PluginAtomVec::copy(int i, int j, int delflag) {
  tag[j] = tag[i];
  type[j] = type[i];
  mask[j] = mask[i];
  image[j] = image[i];
  for (int d = 0; d < 3; d++) {
    x[j][d] = x[i][d];
    v[j][d] = v[i][d];
  }
  copy_fields(lists_.record, i, j);
  copy_fields(lists_.border, i, j);

  if (atom->nextra_grow)
    for (int iextra = 0; iextra < atom->nextra_grow; iextra++)
      modify->fix[atom->extra_grow[iextra]]->copy_arrays(i, j, delflag);
}

bigint PluginAtomVec::memory_usage() {
  bigint bytes = 0;
  if (atom->memcheck("tag")) bytes += memory->usage(tag, nmax);
  if (atom->memcheck("type")) bytes += memory->usage(type, nmax);
  if (atom->memcheck("mask")) bytes += memory->usage(mask, nmax);
  if (atom->memcheck("image")) bytes += memory->usage(image, nmax);
  if (atom->memcheck("x")) bytes += memory->usage(x, nmax, 3);
  if (atom->memcheck("v")) bytes += memory->usage(v, nmax, 3);
  if (atom->memcheck("f")) bytes += memory->usage(f, nmax * comm->nthreads, 3);
  for (const PerAtomField &field : fields_) {
    if (!atom->memcheck(field.name.c_str())) continue;
    if (field.ints) bytes += memory->usage(*field.ints, nmax);
    else if (field.values) bytes += memory->usage(*field.values, nmax);
    else bytes += memory->usage(*field.rows, field.per_thread ? nmax * comm->nthreads : nmax, field.columns);
  }
  return bytes;
}

// ---------------------------------------------------------------------------------------
// forward and reverse communication

// x + the periodic shift, then the comm fields (border: the ghost values); with
// velocities, then v (+ dv for a deforming box) and the comm_vel (border_vel) fields
int PluginAtomVec::pack_atoms(int n, const int *list, double *buf, int pbc_flag, const int *pbc, bool border,
                              bool velocities) const {
  double s[3], dv[3];
  wiregrain_lmp::periodic_image_shift(domain, pbc_flag, pbc, border, s);
  if (velocities) wiregrain_lmp::deforming_image_velocity(pbc_flag, pbc, deform_vremap, h_rate, dv);
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    for (int d = 0; d < 3; d++) buf[m++] = x[j][d] + s[d];
    m += border ? pack_ghost(j, &buf[m]) : pack_fields(lists_.comm, j, &buf[m]);
    if (!velocities) continue;
    const bool remap = pbc_flag && deform_vremap && (mask[j] & deform_groupbit);
    for (int d = 0; d < 3; d++) buf[m++] = v[j][d] + (remap ? dv[d] : 0.0);
    m += pack_fields(border ? lists_.border_vel : lists_.comm_vel, j, &buf[m]);
  }
  return m;
}

// the atoms first..first+n-1 from a buffer of pack_atoms
int PluginAtomVec::unpack_atoms(int n, int first, const double *buf, bool border, bool velocities) {
  int m = 0;
  for (int i = first; i < first + n; i++) {
    if (border && i == nmax) grow(0);
    for (int d = 0; d < 3; d++) x[i][d] = buf[m++];
    m += border ? unpack_ghost(i, &buf[m]) : unpack_fields(lists_.comm, i, &buf[m]);
    if (!velocities) continue;
    for (int d = 0; d < 3; d++) v[i][d] = buf[m++];
    m += unpack_fields(border ? lists_.border_vel : lists_.comm_vel, i, &buf[m]);
  }
  return m;
}

int PluginAtomVec::pack_comm(int n, int *list, double *buf, int pbc_flag, int *pbc) {
  return pack_atoms(n, list, buf, pbc_flag, pbc, false, false);
}

int PluginAtomVec::pack_comm_vel(int n, int *list, double *buf, int pbc_flag, int *pbc) {
  return pack_atoms(n, list, buf, pbc_flag, pbc, false, true);
}

int PluginAtomVec::pack_comm_hybrid(int n, int *list, double *buf) {
  int m = 0;
  for (int i = 0; i < n; i++) m += pack_fields(lists_.comm, list[i], &buf[m]);
  return m;
}

void PluginAtomVec::unpack_comm(int n, int first, double *buf) { unpack_atoms(n, first, buf, false, false); }

void PluginAtomVec::unpack_comm_vel(int n, int first, double *buf) { unpack_atoms(n, first, buf, false, true); }

int PluginAtomVec::unpack_comm_hybrid(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++) m += unpack_fields(lists_.comm, i, &buf[m]);
  return m;
}

int PluginAtomVec::pack_reverse(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++) {
    for (int d = 0; d < 3; d++) buf[m++] = f[i][d];
    m += pack_fields(lists_.reverse, i, &buf[m]);
  }
  return m;
}

int PluginAtomVec::pack_reverse_hybrid(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++) m += pack_fields(lists_.reverse, i, &buf[m]);
  return m;
}

// Reverse communication sums a ghost's values into its owner: the reverse fields are
// per-atom doubles (forces, torques).
void PluginAtomVec::unpack_reverse(int n, int *list, double *buf) {
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    for (int d = 0; d < 3; d++) f[j][d] += buf[m++];
    for (int k : lists_.reverse)
      for (int c = 0; c < fields_[k].columns; c++) (*fields_[k].rows)[j][c] += buf[m++];
  }
}

int PluginAtomVec::unpack_reverse_hybrid(int n, int *list, double *buf) {
  int m = 0;
  for (int i = 0; i < n; i++)
    for (int k : lists_.reverse)
      for (int c = 0; c < fields_[k].columns; c++) (*fields_[k].rows)[list[i]][c] += buf[m++];
  return m;
}

// ---------------------------------------------------------------------------------------
// ghosts

// what a ghost gets besides its position
int PluginAtomVec::pack_ghost(int j, double *buf) const {
  buf[0] = ubuf(tag[j]).d;
  buf[1] = ubuf(type[j]).d;
  buf[2] = ubuf(mask[j]).d;
  return 3 + pack_fields(lists_.border, j, &buf[3]);
}

int PluginAtomVec::unpack_ghost(int i, const double *buf) {
  tag[i] = (int)ubuf(buf[0]).i;
  type[i] = (int)ubuf(buf[1]).i;
  mask[i] = (int)ubuf(buf[2]).i;
  return 3 + unpack_fields(lists_.border, i, &buf[3]);
}

// the fixes' ghost values after the atoms' (atom->extra_border)
int PluginAtomVec::pack_border_fixes(int n, int *list, double *buf) {
  int m = 0;
  for (int iextra = 0; iextra < atom->nextra_border; iextra++)
    m += modify->fix[atom->extra_border[iextra]]->pack_border(n, list, &buf[m]);
  return m;
}

void PluginAtomVec::unpack_border_fixes(int n, int first, double *buf) {
  int m = 0;
  for (int iextra = 0; iextra < atom->nextra_border; iextra++)
    m += modify->fix[atom->extra_border[iextra]]->unpack_border(n, first, &buf[m]);
}

int PluginAtomVec::pack_border(int n, int *list, double *buf, int pbc_flag, int *pbc) {
  const int m = pack_atoms(n, list, buf, pbc_flag, pbc, true, false);
  return m + pack_border_fixes(n, list, &buf[m]);
}

int PluginAtomVec::pack_border_vel(int n, int *list, double *buf, int pbc_flag, int *pbc) {
  const int m = pack_atoms(n, list, buf, pbc_flag, pbc, true, true);
  return m + pack_border_fixes(n, list, &buf[m]);
}

int PluginAtomVec::pack_border_hybrid(int n, int *list, double *buf) {
  int m = 0;
  for (int i = 0; i < n; i++) m += pack_fields(lists_.border, list[i], &buf[m]);
  return m;
}

void PluginAtomVec::unpack_border(int n, int first, double *buf) {
  const int m = unpack_atoms(n, first, buf, true, false);
  unpack_border_fixes(n, first, &buf[m]);
}

void PluginAtomVec::unpack_border_vel(int n, int first, double *buf) {
  const int m = unpack_atoms(n, first, buf, true, true);
  unpack_border_fixes(n, first, &buf[m]);
}

int PluginAtomVec::unpack_border_hybrid(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++) m += unpack_fields(lists_.border, i, &buf[m]);
  return m;
}

// ---------------------------------------------------------------------------------------
// exchange and restart records

int PluginAtomVec::pack_record(int i, double *buf) const {
  int m = 0;
  for (int d = 0; d < 3; d++) buf[m++] = x[i][d];
  for (int d = 0; d < 3; d++) buf[m++] = v[i][d];
  buf[m++] = ubuf(image[i]).d;
  m += pack_fields(lists_.record, i, &buf[m]);
  return m + pack_ghost(i, &buf[m]);
}

int PluginAtomVec::unpack_record(int i, const double *buf) {
  int m = 0;
  for (int d = 0; d < 3; d++) x[i][d] = buf[m++];
  for (int d = 0; d < 3; d++) v[i][d] = buf[m++];
  image[i] = (tagint)ubuf(buf[m++]).i;
  m += unpack_fields(lists_.record, i, &buf[m]);
  return m + unpack_ghost(i, &buf[m]);
}

int PluginAtomVec::pack_record_and_fixes(int i, double *buf, int nextra, const int *extra,
                                         int (Fix::*pack)(int, double *)) {
  int m = 1 + pack_record(i, &buf[1]);
  for (int iextra = 0; iextra < nextra; iextra++) m += (modify->fix[extra[iextra]]->*pack)(i, &buf[m]);
  buf[0] = m;
  return m;
}

int PluginAtomVec::pack_exchange(int i, double *buf) {
  return pack_record_and_fixes(i, buf, atom->nextra_grow, atom->extra_grow, &Fix::pack_exchange);
}

int PluginAtomVec::unpack_exchange(double *buf) {
  const int nlocal = atom->nlocal;
  if (nlocal == nmax) grow(0);
  int m = 1 + unpack_record(nlocal, &buf[1]);
  if (atom->nextra_grow)
    for (int iextra = 0; iextra < atom->nextra_grow; iextra++)
      m += modify->fix[atom->extra_grow[iextra]]->unpack_exchange(nlocal, &buf[m]);
  atom->nlocal++;
  return m;
}

int PluginAtomVec::size_restart() {
  const int nlocal = atom->nlocal;
  const int record = 7 + count(lists_.record) + 3 + count(lists_.border);  // pack_record
  int n = (record + 1) * nlocal;
  if (atom->nextra_restart)
    for (int iextra = 0; iextra < atom->nextra_restart; iextra++)
      for (int i = 0; i < nlocal; i++) n += modify->fix[atom->extra_restart[iextra]]->size_restart(i);
  return n;
}

int PluginAtomVec::pack_restart(int i, double *buf) {
  return pack_record_and_fixes(i, buf, atom->nextra_restart, atom->extra_restart, &Fix::pack_restart);
}

int PluginAtomVec::unpack_restart(double *buf) {
  const int nlocal = atom->nlocal;
  if (nlocal == nmax) {
    grow(0);
    if (atom->nextra_store) memory->grow(atom->extra, nmax, atom->nextra_store, "atom:extra");
  }
  int m = 1 + unpack_record(nlocal, &buf[1]);
  if (atom->nextra_store) {
    const int size = static_cast<int>(buf[0]) - m;
    for (int k = 0; k < size; k++) atom->extra[nlocal][k] = buf[m++];
  }
  atom->nlocal++;
  return m;
}

// ---------------------------------------------------------------------------------------
// new atoms and data files

// create_atoms or an insertion fix; create_atom_defaults gives the style's values
void PluginAtomVec::create_atom(int itype, double *coord) {
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
  zero_fields(lists_.record, nlocal);
  zero_fields(lists_.border, nlocal);
  create_atom_defaults(nlocal);
  wiregrain_lmp::clear_restart_record(lmp, nlocal);
  atom->nlocal++;
}

void PluginAtomVec::data_error(const char *section, const std::string &what) const {
  error->one(FLERR, ("atom_style " + style_ + ": " + section + " section of data file: " + what).c_str());
  std::abort();
}

double PluginAtomVec::data_number(const char *word, const std::string &name, const char *section) const {
  double value = 0.0;
  if (!wiregrain_lmp::parse_finite_number(word, value))
    data_error(section, name + " must be a finite number, got '" + word + "'");
  return value;
}

// Atoms line: atom-ID atom-type, the style's columns (data_atom_hybrid), x y z. The
// velocities and the fields the style's columns leave out start at zero.
void PluginAtomVec::data_atom(double *coord, tagint imagetmp, char **values) {
  const int nlocal = atom->nlocal;
  if (nlocal == nmax) grow(0);
  tag[nlocal] = atoi(values[0]);
  if (tag[nlocal] <= 0) data_error("Atoms", std::string("invalid atom ID '") + values[0] + "'");
  type[nlocal] = atoi(values[1]);
  if (type[nlocal] <= 0 || type[nlocal] > atom->ntypes)
    data_error("Atoms", std::string("invalid atom type '") + values[1] + "'");
  for (int d = 0; d < 3; d++) {
    x[nlocal][d] = coord[d];
    v[nlocal][d] = 0.0;
  }
  zero_fields(lists_.record, nlocal);
  zero_fields(lists_.border, nlocal);
  image[nlocal] = imagetmp;
  mask[nlocal] = 1;
  data_atom_hybrid(nlocal, &values[2]);
  atom->nlocal++;
}

// Velocities line: atom-ID vx vy vz, each a finite number (LIGGGHTS' own reader takes
// "1.0x" as 1 and "abc" as 0), then the style's columns (data_vel_hybrid)
void PluginAtomVec::data_vel(int m, char **values) {
  for (int d = 0; d < 3; d++)
    v[m][d] = data_number(values[d], "v" + std::string(1, "xyz"[d]) + " of atom " + std::to_string(tag[m]),
                          "Velocities");
  data_vel_hybrid(m, &values[3]);
}

void PluginAtomVec::pack_data(double **buf) {
  const int columns = count(lists_.data_atom);
  for (int i = 0; i < atom->nlocal; i++) {
    buf[i][0] = ubuf(tag[i]).d;
    buf[i][1] = ubuf(type[i]).d;
    pack_data_hybrid(i, &buf[i][2]);
    for (int d = 0; d < 3; d++) buf[i][2 + columns + d] = x[i][d];
    buf[i][5 + columns] = ubuf((image[i] & IMGMASK) - IMGMAX).d;
    buf[i][6 + columns] = ubuf((image[i] >> IMGBITS & IMGMASK) - IMGMAX).d;
    buf[i][7 + columns] = ubuf((image[i] >> IMG2BITS) - IMGMAX).d;
  }
}

int PluginAtomVec::pack_data_hybrid(int i, double *buf) { return pack_fields(lists_.data_atom, i, buf); }

void PluginAtomVec::write_data(FILE *fp, int n, double **buf) {
  const int columns = count(lists_.data_atom);
  for (int i = 0; i < n; i++) {
    fprintf(fp, "%d %d", (int)ubuf(buf[i][0]).i, (int)ubuf(buf[i][1]).i);
    write_data_hybrid(fp, &buf[i][2]);
    const double *end = &buf[i][2 + columns];  // x y z and the image flags
    fprintf(fp, " %-1.16e %-1.16e %-1.16e %d %d %d\n", end[0], end[1], end[2], (int)ubuf(end[3]).i,
            (int)ubuf(end[4]).i, (int)ubuf(end[5]).i);
  }
}

// integers as %d, reals as %-1.16e, each after a space
void PluginAtomVec::write_columns(FILE *fp, const std::vector<int> &list, const double *buf) const {
  int m = 0;
  for (int k : list) {
    if (fields_[k].ints) fprintf(fp, " %d", (int)ubuf(buf[m++]).i);
    else
      for (int c = 0; c < fields_[k].columns; c++) fprintf(fp, " %-1.16e", buf[m++]);
  }
}

int PluginAtomVec::write_data_hybrid(FILE *fp, double *buf) {
  write_columns(fp, lists_.data_atom, buf);
  return count(lists_.data_atom);
}

void PluginAtomVec::pack_vel(double **buf) {
  for (int i = 0; i < atom->nlocal; i++) {
    buf[i][0] = ubuf(tag[i]).d;
    for (int d = 0; d < 3; d++) buf[i][1 + d] = v[i][d];
    pack_vel_hybrid(i, &buf[i][4]);
  }
}

int PluginAtomVec::pack_vel_hybrid(int i, double *buf) { return pack_fields(lists_.data_vel, i, buf); }

void PluginAtomVec::write_vel(FILE *fp, int n, double **buf) {
  for (int i = 0; i < n; i++) {
    fprintf(fp, "%d %-1.16e %-1.16e %-1.16e", (int)ubuf(buf[i][0]).i, buf[i][1], buf[i][2], buf[i][3]);
    write_vel_hybrid(fp, &buf[i][4]);
    fprintf(fp, "\n");
  }
}

int PluginAtomVec::write_vel_hybrid(FILE *fp, double *buf) {
  write_columns(fp, lists_.data_vel, buf);
  return count(lists_.data_vel);
}

// ---------------------------------------------------------------------------------------
// An Atoms line that no sub-domain takes (cmake/patches/0008: Atom::data_atoms calls this on
// every rank alike, for a coordinate that is not a finite number or a point outside the
// box): with a plugin atom style (plain or in a hybrid) the run stops naming the atom and
// the cause; other atom styles keep LIGGGHTS' "Did not assign all atoms correctly".
namespace LAMMPS_NS {

void wiregrain_data_atom_unassigned(LAMMPS *lmp, char **values, int xptr) {
  bool plugin = false;
  for (AtomVec *part : wiregrain_lmp::atom_style_parts(lmp->atom)) plugin = plugin || dynamic_cast<PluginAtomVec *>(part);
  if (!plugin) return;
  std::string style = lmp->atom->atom_style;
  if (AtomVecHybrid *hybrid = dynamic_cast<AtomVecHybrid *>(lmp->atom->avec))
    for (int k = 0; k < hybrid->nstyles; k++) style += std::string(" ") + hybrid->keywords[k];
  const std::string prefix = "atom_style " + style + ": Atoms section of data file: ";
  const std::string atom_id = values[0];
  Domain *domain = lmp->domain;
  double x[3];
  for (int d = 0; d < 3; d++)
    if (!wiregrain_lmp::parse_finite_number(values[xptr + d], x[d]))
      lmp->error->all(FLERR, (prefix + "xyz"[d] + " of atom " + atom_id + " must be a finite number, got '" +
                              values[xptr + d] + "'").c_str());
  std::string where;  // the non-periodic direction in which it is out (remap wraps the periodic ones)
  for (int d = 0; d < 3 && !domain->triclinic && where.empty(); d++)
    if (!domain->periodicity[d] && !(x[d] >= domain->boxlo[d] && x[d] < domain->boxhi[d]))
      where = std::string(": ") + "xyz"[d] + " = " + wiregrain::format_number(x[d]) + ", the box spans [" +
              wiregrain::format_number(domain->boxlo[d]) + ", " + wiregrain::format_number(domain->boxhi[d]) +
              ") in " + "xyz"[d] + " (a non-periodic boundary)";
  lmp->error->all(FLERR, (prefix + "atom " + atom_id + " lies outside the " +
                          (domain->triclinic ? "(triclinic) " : "") + "simulation box" + where).c_str());
}

}  // namespace LAMMPS_NS
