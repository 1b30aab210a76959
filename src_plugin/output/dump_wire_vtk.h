/* dump wire/vtk: the wires of atom_style wire as VTK XML PolyData polylines, one file per
   snapshot, plus a ParaView ".vtp.series" file listing the snapshots with their times.

   dump ID group wire/vtk N file [energy fix-ID] [grains fix-ID] [format binary|ascii]

   file must contain one '*' (replaced by the time step) in its name and end in ".vtp".
   Each wire (chain of beads linked by wire_prev/wire_next) becomes one polyline; only
   beads of the group are written (its grains are left out) and a chain is cut where a
   link leaves the group. Point
   data per bead: id, type, velocity and, with `energy fix-ID` (a fix wire/elastic),
   stretching_energy, bending_energy, elastic_energy; with `grains fix-ID` (a fix
   wire/grain) grain_force and grain_contacts. Cell data: wire (index of the chain
   in the file, chains ordered by their first bead's id).

   Every rank packs its beads through the Dump base class (pack() into buf); rank 0
   receives all buffers, assembles the chains from the tags and writes the files. */

#ifdef DUMP_CLASS

DumpStyle(wire/vtk,DumpWireVTK)

#else

#ifndef LMP_DUMP_WIRE_VTK_H
#define LMP_DUMP_WIRE_VTK_H

#include <string>
#include <utility>
#include <vector>

#include "common/atom_kinds.h"
#include "output/dump_vtp.h"
#include "output/plugin_vtk.h"

namespace LAMMPS_NS {

class DumpWireVTK : public DumpVtp {
 public:
  DumpWireVTK(class LAMMPS *, int, char **);
  ~DumpWireVTK();

 protected:
  void init_style();
  void pack(int *);

 private:
  std::string energy_fix_id_;    // empty: no energy columns
  int energy_fix_;               // index of that fix in modify->fix, -1 if none
  std::string grain_fix_id_;     // empty: no grain columns
  int grain_fix_;                // index of that fix wire/grain, -1 if none
  int energy_column_, grain_column_;  // first buffer column of each, -1 if absent
  class AtomVecWire *wire_;
  wiregrain_lmp::AtomKinds kinds_;

  bool writes(int i) const { return !kinds_.is_grain(i); }
  int find_fix(const std::string &fix_id, const char *keyword, bool at_init);
  int find_energy_fix(bool at_init);
  int find_grain_fix(bool at_init);
  void write_snapshot(const std::string &path);
};

}  // namespace LAMMPS_NS

#endif
#endif
