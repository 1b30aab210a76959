/* fix wire/contact/history: the tangential springs of the soft contacts of wire beads,
   kept per contact and per bead so they migrate with the bead and go to restart files.
   Created by pair wire/contact (id WIRE_CONTACT_HISTORY), fix wire/wall (id
   WIRE_WALL_HISTORY_<fix ID>) and fix wire/grain (id WIRE_GRAIN_HISTORY_<fix ID>); not
   meant to be defined by hand (docs/commands/fix_wire_contact_history.md).

   Each bead keeps up to kMaxPartners contacts: the partner key (for a segment pair the
   other segment's first bead's tag, for a grain the grain's tag, for a wall 0: each fix
   wire/wall has its own history fix) and the spring ξ_t and sliding state.
   A force computation reads last step's list and writes this step's; contacts that
   were not written again (the pair separated) are gone. */

#ifdef FIX_CLASS

FixStyle(wire/contact/history,FixWireContactHistory)

#else

#ifndef LMP_FIX_WIRE_CONTACT_HISTORY_H
#define LMP_FIX_WIRE_CONTACT_HISTORY_H

#include "fix.h"

namespace wiregrain {
struct TangentialHistory;
}

namespace LAMMPS_NS {

class FixWireContactHistory : public Fix {
 public:
  static const int kMaxPartners = 16;

  FixWireContactHistory(class LAMMPS *, int, char **);
  ~FixWireContactHistory();
  int setmask();

  // Start a new force computation: this step's lists are empty.
  void begin_step();
  // Last step's spring of bead i (owned) with `partner` (zero if new).
  void lookup(int i, int partner, wiregrain::TangentialHistory &history) const;
  // Record this step's spring; errors when bead i has too many contacts.
  void store(int i, int partner, const wiregrain::TangentialHistory &history);
  // This step's lists become last step's.
  void end_step();
  // number of contacts stored this step on owned beads
  int stored_count() const;

  void grow_arrays(int);
  void copy_arrays(int, int, int);
  void set_arrays(int);
  int pack_exchange(int, double *);
  int unpack_exchange(int, double *);
  int pack_restart(int, double *);
  void unpack_restart(int, int);
  int size_restart(int);
  int maxsize_restart();
  double memory_usage();

 private:
  static const int kValues = 4;  // spring x, y, z and the sliding flag
  int *count_, *new_count_;
  int **partner_, **new_partner_;
  double **value_, **new_value_;
  int nmax_;
  int pack(int i, double *buf) const;
  int unpack(int i, const double *buf);
};

}  // namespace LAMMPS_NS

#endif
#endif
