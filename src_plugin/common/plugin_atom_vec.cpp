#include "plugin_atom_vec.h"

#include "atom.h"
#include "fix.h"
#include "memory.h"
#include "modify.h"

#include "plugin_comm.h"

using namespace LAMMPS_NS;

int PluginAtomVec::pack_border(int n, int *list, double *buf, int pbc_flag, int *pbc) {
  double s[3];
  wiregrain_lmp::periodic_image_shift(domain, pbc_flag, pbc, true, s);
  double **x = atom->x;
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    for (int d = 0; d < 3; d++) buf[m++] = x[j][d] + s[d];
    m += pack_ghost(j, &buf[m]);
  }
  if (atom->nextra_border)
    for (int iextra = 0; iextra < atom->nextra_border; iextra++)
      m += modify->fix[atom->extra_border[iextra]]->pack_border(n, list, &buf[m]);
  return m;
}

int PluginAtomVec::pack_border_vel(int n, int *list, double *buf, int pbc_flag, int *pbc) {
  double s[3], dv[3];
  const double zero[3] = {0.0, 0.0, 0.0};
  wiregrain_lmp::periodic_image_shift(domain, pbc_flag, pbc, true, s);
  wiregrain_lmp::deforming_image_velocity(pbc_flag, pbc, deform_vremap, h_rate, dv);
  double **x = atom->x;
  const int *mask = atom->mask;
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    const bool remap = pbc_flag && deform_vremap && (mask[j] & deform_groupbit);
    for (int d = 0; d < 3; d++) buf[m++] = x[j][d] + s[d];
    m += pack_ghost(j, &buf[m]);
    m += pack_ghost_velocity(j, &buf[m], remap ? dv : zero);
  }
  if (atom->nextra_border)
    for (int iextra = 0; iextra < atom->nextra_border; iextra++)
      m += modify->fix[atom->extra_border[iextra]]->pack_border(n, list, &buf[m]);
  return m;
}

void PluginAtomVec::unpack_border(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++) {
    if (i == nmax) grow(0);
    for (int d = 0; d < 3; d++) atom->x[i][d] = buf[m++];
    m += unpack_ghost(i, &buf[m]);
  }
  if (atom->nextra_border)
    for (int iextra = 0; iextra < atom->nextra_border; iextra++)
      m += modify->fix[atom->extra_border[iextra]]->unpack_border(n, first, &buf[m]);
}

void PluginAtomVec::unpack_border_vel(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++) {
    if (i == nmax) grow(0);
    for (int d = 0; d < 3; d++) atom->x[i][d] = buf[m++];
    m += unpack_ghost(i, &buf[m]);
    m += unpack_ghost_velocity(i, &buf[m]);
  }
  if (atom->nextra_border)
    for (int iextra = 0; iextra < atom->nextra_border; iextra++)
      m += modify->fix[atom->extra_border[iextra]]->unpack_border(n, first, &buf[m]);
}

int PluginAtomVec::pack_exchange(int i, double *buf) {
  int m = 1 + pack_record(i, &buf[1]);
  if (atom->nextra_grow)
    for (int iextra = 0; iextra < atom->nextra_grow; iextra++)
      m += modify->fix[atom->extra_grow[iextra]]->pack_exchange(i, &buf[m]);
  buf[0] = m;
  return m;
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
  int n = (record_size() + 1) * nlocal;
  if (atom->nextra_restart)
    for (int iextra = 0; iextra < atom->nextra_restart; iextra++)
      for (int i = 0; i < nlocal; i++) n += modify->fix[atom->extra_restart[iextra]]->size_restart(i);
  return n;
}

int PluginAtomVec::pack_restart(int i, double *buf) {
  int m = 1 + pack_record(i, &buf[1]);
  if (atom->nextra_restart)
    for (int iextra = 0; iextra < atom->nextra_restart; iextra++)
      m += modify->fix[atom->extra_restart[iextra]]->pack_restart(i, &buf[m]);
  buf[0] = m;
  return m;
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
