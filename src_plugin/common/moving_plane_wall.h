/* A plane wall that moves at a constant velocity, defined by one style and felt by the
   bodies of another: fix wire/wall implements it, fix nscd/polyhedra's `wall_fix ID` finds
   it by fix ID and reads the plane at every solve, so that one definition serves the
   wire and the grains; `plate` makes the plane a body of the grains' contact problem that
   fix nscd/polyhedra moves. The friction is not part of it: the grains take theirs from fix
   nscd/polyhedra ('wall_friction', else 'friction'). */

#ifndef WIREGRAIN_MOVING_PLANE_WALL_H
#define WIREGRAIN_MOVING_PLANE_WALL_H

namespace wiregrain_lmp {

class MovingPlaneWall {
 public:
  virtual ~MovingPlaneWall() = default;
  // a point of the plane at the current step
  virtual void current_point(double p[3]) const = 0;
  // the unit normal, pointing into the space of the bodies
  virtual const double *normal() const = 0;
  // the velocity of the plane
  virtual const double *velocity() const = 0;
  // the force of the fix's own bodies (the wire's beads) on the plane at the last force
  // call, summed over the ranks (every rank calls it: an all-reduce)
  virtual void force_on_plane(double f[3]) = 0;
  // from now on the plane passes through `point` and moves at `velocity` (fix
  // nscd/polyhedra's `plate` moves it by the solved velocity at every solve)
  virtual void move_plane(const double point[3], const double velocity[3]) = 0;
};

}  // namespace wiregrain_lmp

#endif
