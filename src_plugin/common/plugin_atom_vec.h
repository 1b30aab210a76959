// The part the plugin's atom styles (wire, polyhedron) share: ghost (border)
// communication, migration and restart records, written once in terms of what each
// style sends. Not a style of its own.
#ifndef WIREGRAIN_PLUGIN_ATOM_VEC_H
#define WIREGRAIN_PLUGIN_ATOM_VEC_H

#include "atom_vec.h"

namespace LAMMPS_NS {

class PluginAtomVec : public AtomVec {
 public:
  explicit PluginAtomVec(class LAMMPS *lmp) : AtomVec(lmp) {}
  int pack_border(int, int *, double *, int, int *);
  int pack_border_vel(int, int *, double *, int, int *);
  void unpack_border(int, int, double *);
  void unpack_border_vel(int, int, double *);
  int pack_exchange(int, double *);
  int unpack_exchange(double *);
  int size_restart();
  int pack_restart(int, double *);
  int unpack_restart(double *);

 protected:
  // what a ghost gets besides its position, and back
  virtual int pack_ghost(int j, double *buf) const = 0;
  virtual int unpack_ghost(int i, const double *buf) = 0;
  // what a ghost gets with `communicate vel yes`: the velocity plus dv (a deforming box)
  // and, for grains, the angular velocity
  virtual int pack_ghost_velocity(int j, double *buf, const double dv[3]) const = 0;
  virtual int unpack_ghost_velocity(int i, const double *buf) = 0;
  // one atom as exchange and restart records carry it, starting with x, y, z (read_restart
  // tests them to decide which rank keeps the atom); record_size() values
  virtual int pack_record(int i, double *buf) const = 0;
  virtual int unpack_record(int i, const double *buf) = 0;
  virtual int record_size() const = 0;
};

}  // namespace LAMMPS_NS

#endif
