/* fix wire/wall: a frictional plane wall for wire beads, optionally moving.

   fix ID group wire/wall plane px py pz nx ny nz [E 100] [nu 0] [mu_s 0.5] [mu_d 0.5]
       [restitution 0.5 | damping_ratio z] [limit_force no|yes] [velocity vx vy vz]

   The wall is the plane through (px,py,pz) with unit normal (nx,ny,nz) pointing into the
   space of the beads, moving at the given velocity. A bead (sphere of its radius: the
   end of its spherocylinder segments) touching it feels the soft contact of
   core/soft_contact.h with a rigid wall, E* = E/(1−ν²), k_n = E* l π/4, k_t = E* r, where
   l is the bead's segment rest length (core/contact/contact_laws.h); E and ν: the
   keywords, else fix property/global youngsModulus / poissonsRatio of the bead's atom
   type, else Table 1 (common/plugin_material.h); tangential springs persist (fix
   WIRE_WALL_HISTORY_<ID>). Several walls: several fixes.

   fix_modify ID velocity vx vy vz: the wall goes on from where it is at the new velocity
   (e.g. the column's side walls taken away).

   fix nscd/polyhedra ... wall_fix ID makes the same plane a wall of the grains: one
   definition per container wall (read through common/moving_plane_wall.h). With its
   `plate` keyword the plane is a body of the grains' contact problem: fix nscd/polyhedra
   moves it (position and velocity) at every solve, and the beads' force on it is part of
   the plate's load.

   Checks (common/contact_checks.h): at each run start the timestep against the stability
   limit of the stiffest bead of the group (longest segment, thickest bead, stiffest
   material) on the lightest bead; every step, a bead overlapping the wall by more than
   0.5 r_w is named in a warning, the first 10 times per rank.

   Outputs: vector = [contacts, largest overlap, force on the wall x, y, z] (all ranks).
   Publishes its contacts (kind wire_wall, a = −1, b = the bead's tag) as a
   ContactPublisher. */

#ifdef FIX_CLASS

FixStyle(wire/wall,FixWireWall)

#else

#ifndef LMP_FIX_WIRE_WALL_H
#define LMP_FIX_WIRE_WALL_H

#include <string>
#include <vector>

#include "common/contact_checks.h"
#include "common/contact_publisher.h"
#include "common/moving_plane_wall.h"
#include "core/contact/contact_materials.h"
#include "fix.h"
#include "common/plugin_material.h"

namespace LAMMPS_NS {

class FixWireWall : public Fix, public wiregrain_lmp::ContactPublisher, public wiregrain_lmp::MovingPlaneWall {
 public:
  FixWireWall(class LAMMPS *, int, char **);
  ~FixWireWall();
  int setmask();
  void post_create();
  void init();
  void setup(int);
  void post_force(int);
  void reset_dt();
  double compute_vector(int);
  void write_restart(FILE *);
  void restart(char *);
  int modify_param(int, char **);
  // this rank's bead–wall contacts of the last force call
  const wiregrain::ContactList &published_contacts() const;
  // MovingPlaneWall: the plane now (fix nscd/polyhedra's wall_fix uses it for the grains)
  void current_point(double p[3]) const;
  const double *normal() const { return normal_; }
  const double *velocity() const { return velocity_; }
  void force_on_plane(double f[3]);
  void move_plane(const double point[3], const double velocity[3]);

 private:
  double point_[3], normal_[3], velocity_[3];
  wiregrain_lmp::MaterialKeywords material_keywords_;  // E, nu when given
  wiregrain::ContactFriction friction_;
  std::vector<double> wall_modulus_of_type_;            // E* = E/(1−ν²) per atom type, from init()
  // the wall passes through point_ + velocity_ reference_dt_ (step − reference_step_)
  bigint reference_step_;
  double reference_dt_;
  class AtomVecWire *wire_;
  class FixWireContactHistory *history_;
  std::string history_id_;
  wiregrain::ContactList *contacts_;
  double local_stats_[5], global_stats_[5];
  bigint stats_step_;
  wiregrain_lmp::ContactTimeStepCheck time_step_check_;
  wiregrain_lmp::OverlapWarnings overlap_warnings_;
  void rereference();
  void check_time_step();
  // the segment length bead i stands for (its own, its previous bead's, or 2 r)
  double bead_length(int i) const;
};

}  // namespace LAMMPS_NS

#endif
#endif
