/* grain_shapes: save or load the grain shape library (atom_style polyhedron) as a text
   file, so grains can go through write_data / read_data.

   grain_shapes write FILE     (rank 0 writes)
   grain_shapes read FILE      (before read_data; replaces an empty library)

   File: a header line "wiregrain shapes N mass dilated|sharp", then per shape a line
   "shape K sweep R vertices V" followed by V lines "x y z" of body-frame vertices
   (V = 1: a sphere of radius R; otherwise V >= 4, the hull's vertices). */

#ifdef COMMAND_CLASS

CommandStyle(grain_shapes,GrainShapes)

#else

#ifndef LMP_GRAIN_SHAPES_H
#define LMP_GRAIN_SHAPES_H

#include "pointers.h"

namespace LAMMPS_NS {

class GrainShapes : protected Pointers {
 public:
  GrainShapes(class LAMMPS *);
  void command(int, char **);
};

}  // namespace LAMMPS_NS

#endif
#endif
