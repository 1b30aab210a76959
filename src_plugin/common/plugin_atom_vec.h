// The part the plugin's atom styles (wire, polyhedron) share: every operation on the
// per-atom arrays (grow, copy, forward and reverse communication, ghosts, migration and
// restart records, data-file lines, memory), written once over the fields each style
// declares, as LAMMPS' AtomVec does with its field lists. Not a style of its own.
//
// Every style has tag, type, mask, image, x, v and f; this class handles them. A style
// declares its other arrays in its constructor (add_field) and names them, in buffer
// order, in the lists of FieldLists; then calls fields_declared(), which sets the
// AtomVec sizes. The buffers, per atom:
//   forward (pack_comm)          x+shift, comm
//   forward with velocities      x+shift, comm, v(+dv), comm_vel
//   reverse (pack_reverse)       f, reverse
//   ghost (pack_border)          x+shift, tag, type, mask, border
//   ghost with velocities        x+shift, tag, type, mask, border, v(+dv), border_vel
//   exchange and restart record  length, x, v, image, record, tag, type, mask, border,
//                                then the fixes' values (read_restart tests x, y, z
//                                right after the length to decide which rank keeps it)
//   data file Atoms line         atom-ID atom-type data_atom x y z (+ image flags)
//   data file Velocities line    atom-ID vx vy vz data_vel
// In atom_style hybrid the hybrid style sends x, tag, type, mask, v, f and the sub-style
// only its list (the *_hybrid methods). copy() copies the record and border fields, what
// travels with an atom. Reading a data line (data_atom_hybrid, data_vel_hybrid) is the
// style's: it checks each value.
#ifndef WIREGRAIN_PLUGIN_ATOM_VEC_H
#define WIREGRAIN_PLUGIN_ATOM_VEC_H

#include <initializer_list>
#include <string>
#include <vector>

#include "atom_vec.h"

namespace LAMMPS_NS {

class Fix;

// One per-atom array: the address of its pointer (in Atom or in the style), optionally
// the address of the style's copy of that pointer (set again after every grow), and its
// shape.
struct PerAtomField {
  std::string name;           // as LIGGGHTS names it ("radius"); memory label "atom:<name>"
  int **ints = nullptr;       // exactly one of these three is set
  double **values = nullptr;
  double ***rows = nullptr;
  int **int_copy = nullptr;   // the style's copy of the pointer, if any
  double **values_copy = nullptr;
  double ***rows_copy = nullptr;
  int columns = 1;            // values per atom
  bool per_thread = false;    // nmax rows per thread (forces, torques)
};

class PluginAtomVec : public AtomVec {
 public:
  // style: the name in messages ("atom_style <style>: ...")
  PluginAtomVec(class LAMMPS *lmp, const char *style);

  void grow(int);
  // the copies of the array pointers: the ones every style has and the fields'
  void grow_reset();
  void copy(int, int, int);
  int pack_comm(int, int *, double *, int, int *);
  int pack_comm_vel(int, int *, double *, int, int *);
  int pack_comm_hybrid(int, int *, double *);
  void unpack_comm(int, int, double *);
  void unpack_comm_vel(int, int, double *);
  int unpack_comm_hybrid(int, int, double *);
  int pack_reverse(int, int, double *);
  int pack_reverse_hybrid(int, int, double *);
  void unpack_reverse(int, int *, double *);
  int unpack_reverse_hybrid(int, int *, double *);
  int pack_border(int, int *, double *, int, int *);
  int pack_border_vel(int, int *, double *, int, int *);
  int pack_border_hybrid(int, int *, double *);
  void unpack_border(int, int, double *);
  void unpack_border_vel(int, int, double *);
  int unpack_border_hybrid(int, int, double *);
  int pack_exchange(int, double *);
  int unpack_exchange(double *);
  int size_restart();
  int pack_restart(int, double *);
  int unpack_restart(double *);
  void create_atom(int, double *);
  void data_atom(double *, tagint, char **);
  void data_vel(int, char **);
  void pack_data(double **);
  int pack_data_hybrid(int, double *);
  void write_data(FILE *, int, double **);
  int write_data_hybrid(FILE *, double *);
  void pack_vel(double **);
  int pack_vel_hybrid(int, double *);
  void write_vel(FILE *, int, double **);
  int write_vel_hybrid(FILE *, double *);
  bigint memory_usage();

 protected:
  // the fields of each buffer (indices into fields_), in buffer order; see the top
  struct FieldLists {
    std::vector<int> comm, comm_vel, reverse, border, border_vel, record, data_atom, data_vel;
  };

  // array: where the pointer lives; copy: the style's copy of it, or nullptr
  void add_field(const char *name, int **array, int **copy);
  void add_field(const char *name, double **array, double **copy);
  void add_field(const char *name, double ***array, int columns, double ***copy);
  // rows for every thread: forces, torques
  void add_per_thread_field(const char *name, double ***array, int columns, double ***copy);
  // the indices of declared fields, by name
  std::vector<int> fields(std::initializer_list<const char *> names) const;
  // sets size_forward, size_reverse, size_border, size_velocity, size_data_atom,
  // size_data_vel, xcol_data, comm_x_only and comm_f_only from the lists
  void fields_declared();

  // A new atom (create_atom) starts with its record and border fields zero, then this
  // sets the style's defaults for atom i.
  virtual void create_atom_defaults(int i) = 0;

  // "atom_style <style>: <section> section of data file: <what>" on this rank
  [[noreturn]] void data_error(const char *section, const std::string &what) const;
  // a finite number, else "<name> must be a finite number, got '<word>'"
  double data_number(const char *word, const std::string &name, const char *section) const;

  std::string style_;
  std::vector<PerAtomField> fields_;
  FieldLists lists_;

  // the arrays every style has, as of the last grow
  int *tag, *type, *mask;
  tagint *image;
  double **x, **v, **f;

 private:
  int count(const std::vector<int> &list) const;
  void copy_fields(const std::vector<int> &list, int i, int j);
  void zero_fields(const std::vector<int> &list, int i);
  int pack_fields(const std::vector<int> &list, int i, double *buf) const;
  int unpack_fields(const std::vector<int> &list, int i, const double *buf);
  // tag, type, mask, the border fields
  int pack_ghost(int j, double *buf) const;
  int unpack_ghost(int i, const double *buf);
  int pack_atoms(int n, const int *list, double *buf, int pbc_flag, const int *pbc, bool border,
                 bool velocities) const;
  int unpack_atoms(int n, int first, const double *buf, bool border, bool velocities);
  int pack_border_fixes(int n, int *list, double *buf);
  void unpack_border_fixes(int n, int first, double *buf);
  // x, v, image, the record fields, then the ghost values
  int pack_record(int i, double *buf) const;
  int unpack_record(int i, const double *buf);
  // the length, the record, then the values of the fixes in `extra` (Fix::pack_exchange
  // or Fix::pack_restart)
  int pack_record_and_fixes(int i, double *buf, int nextra, const int *extra, int (Fix::*pack)(int, double *));
  void write_columns(FILE *fp, const std::vector<int> &list, const double *buf) const;
};

}  // namespace LAMMPS_NS

#endif
