/* dump polyhedron/vtk: the grains of atom_style polyhedron as VTK XML PolyData polygons,
   one file per snapshot, plus a ParaView ".vtp.series" file listing the snapshots with
   their times (the same times as dump wire/vtk, so both series open together).

   dump ID group polyhedron/vtk N file [format binary|ascii] [sweep yes|no]

   file must contain one '*' (replaced by the time step) in its name and end in ".vtp".
   The wire beads of the group are left out. Every grain of the group with a shape becomes the polygon faces of its polyhedron
   (shape library, body frame) placed at x + R·v; each face has its own points (the
   points of a file are Σ over grains and faces of the face's vertex count), so faces
   render flat. Cell data per face: id, type, shape; point data: velocity and
   angular_velocity of the grain. `sweep yes` moves each face outward by the sweep radius
   (an approximation of the spheropolyhedron: edges and corners are not rounded). A
   sphere (one-vertex shape) is always drawn as its ball, tessellated along latitudes and
   longitudes (core surface_polygons: 8 bands x 16 sectors, 128 cells, 480 points).

   Every rank packs its grains through the Dump base class (pack() into buf); rank 0
   receives all buffers and builds the meshes from the shape library, which is the same
   on every rank. */

#ifdef DUMP_CLASS

DumpStyle(polyhedron/vtk,DumpPolyhedronVTK)

#else

#ifndef LMP_DUMP_POLYHEDRON_VTK_H
#define LMP_DUMP_POLYHEDRON_VTK_H

#include <string>
#include <vector>

#include "common/atom_kinds.h"
#include "output/dump_vtp.h"
#include "output/plugin_vtk.h"

namespace LAMMPS_NS {

class DumpPolyhedronVTK : public DumpVtp {
 public:
  DumpPolyhedronVTK(class LAMMPS *, int, char **);
  ~DumpPolyhedronVTK();

 protected:
  void init_style();
  void pack(int *);

 private:
  bool sweep_;            // offset each face outward by the sweep radius
  class AtomVecPolyhedron *grains_;
  wiregrain_lmp::AtomKinds kinds_;

  bool warned_shapeless_;              // rank 0: warned once about grains without a shape

  bool writes(int i) const { return kinds_.of(i) != wiregrain_lmp::AtomKind::bead; }
  void write_snapshot(const std::string &path);
};

}  // namespace LAMMPS_NS

#endif
#endif
