/* atom_style polyhedron: rigid convex spheropolyhedral grains (docs/design.md, "Grains: rigid
   spheropolyhedra, NSCD" and "Shapes and mass properties").

   atom_style polyhedron [mass dilated|sharp]

   Per grain: position (the centre of mass), velocity, force, orientation (unit quaternion
   body frame → space, atom->quaternion, w first), angular velocity and angular momentum
   (space frame), torque, principal moments of inertia (body frame, atom->inertia), shape
   index (atom->shapetype) into the shape library, density, mass and bounding radius (the
   farthest surface point, sweep radius included: neighbour lists and ghosts use it).
   `mass`: the body that carries the mass and inertia, the swept spheropolyhedron
   (dilated, default) or the sharp polyhedron.

   The shape library (wiregrain::ShapeLibrary) is held here, its records identical on every
   rank, and written to restart files; a rank builds the shapes it uses (with `solve
   distributed`, those of its own and ghost grains). Grains are made by create_grains (or
   read_data, given a library from a restart).

   Data file Atoms line: atom-ID atom-type shape density qw qi qj qk x y z
   Velocities line:      atom-ID vx vy vz wx wy wz */

#ifdef ATOM_CLASS

AtomStyle(polyhedron,AtomVecPolyhedron)

#else

#ifndef LMP_ATOM_VEC_POLYHEDRON_H
#define LMP_ATOM_VEC_POLYHEDRON_H

#include <memory>

#include "common/grain_shape_source.h"
#include "common/plugin_atom_vec.h"

namespace wiregrain {
class ShapeLibrary;
class ConvexShape;
}

namespace LAMMPS_NS {

class AtomVecPolyhedron : public PluginAtomVec, public wiregrain_lmp::GrainShapeSource {
 public:
  AtomVecPolyhedron(class LAMMPS *);
  ~AtomVecPolyhedron();
  void settings(int, char **);
  void write_restart_settings(FILE *);
  void read_restart_settings(FILE *);
  int data_atom_hybrid(int, char **);
  int data_vel_hybrid(int, char **);

  // The shape library (GrainShapeSource). add_shape must be called with the same shape on every rank.
  const wiregrain::ShapeLibrary &shapes() const { return *library_; }
  int add_shape(const wiregrain::ConvexShape &shape, double body_to_input[4], double centroid[3]);
  // Replace the library (grain_shapes read); grains already defined keep their indices.
  void replace_shapes(wiregrain::ShapeLibrary library);
  // Drop the built shapes (core/geometry/shape_library.h) of the grains this rank neither
  // owns nor holds as ghosts; the records stay and a shape asked for again is built again.
  // For a rank that works only on its own and ghost grains (fix nscd/polyhedra `solve
  // distributed`), at a step where no posed shape of the library is held.
  void release_shapes_of_absent_grains();
  // Give grain i shape `shape` at `density`: mass, principal inertia, bounding radius.
  void assign_shape(int i, int shape, double density);
  // grains of the group (all ranks) that have no shape (made by create_atoms)
  int count_without_shape(int groupbit);
  // angular momentum from angular velocity (L = R I Rᵀ ω) and back, for grain i
  void angmom_from_omega(int i);
  void omega_from_angmom(int i);

  // The polyhedron style of this system (plain or inside atom_style hybrid), or NULL.
  static AtomVecPolyhedron *of(class Atom *);

 private:
  std::unique_ptr<wiregrain::ShapeLibrary> library_;
  double *radius, *rmass, *density;
  double **omega, **angmom, **torque, **quat, **inertia;
  int *shape;

  void create_atom_defaults(int i);
};

}  // namespace LAMMPS_NS

#endif
#endif
