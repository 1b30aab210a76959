/* fix nve/polyhedron: rigid-body motion of grains (atom_style polyhedron) under forces and
   torques, without contacts (contacts are the NSCD fix's business).

   fix ID group nve/polyhedron [rotation splitting2|splitting4]

   Translation: velocity Verlet. Rotation: angular momentum L (space frame) kicked by the
   torque over half steps, the torque-free rotation in between by the splitting of
   core/nscd/rigid_body.h (second order, or fourth with splitting4); L is conserved exactly
   without torque, the energy error stays bounded. The quaternion is renormalised every
   step; angular velocity ω = R I⁻¹ Rᵀ L. */

#ifdef FIX_CLASS

FixStyle(nve/polyhedron,FixNVEPolyhedron)

#else

#ifndef LMP_FIX_NVE_POLYHEDRON_H
#define LMP_FIX_NVE_POLYHEDRON_H

#include "fix.h"

namespace LAMMPS_NS {

class FixNVEPolyhedron : public Fix {
 public:
  FixNVEPolyhedron(class LAMMPS *, int, char **);
  int setmask();
  void init();
  void setup(int);
  void initial_integrate(int);
  void final_integrate();

 private:
  bool fourth_order_;
  class AtomVecPolyhedron *grains_;
};

}  // namespace LAMMPS_NS

#endif
#endif
