/* fix nscd/polyhedra's plates: keyword `plate`, after a `wall_fix ID`, makes the plane of
   that fix wire/wall a plate, a body of the grains' contact problem of mass m_p that
   translates along its normal n (core/nscd/grain_step.h, PlaneWall):

       plate m_p load F            F: a number or v_name (equal-style variable)
       plate m_p spring k v_drive  v_drive: a number or v_name

   Signs: n points into the grains; F > 0 presses the plate onto them (along n), v_drive >
   0 moves the drive point towards them. The plate has no weight of its own (give it in F).

   At every solve (h the NSCD step) the plate's external force along n is
     load:   F (evaluated at the solve) + the beads' force on the plane,
     spring: k (d_{k+1} − s_k − h v_k) + the beads' force on the plane, with mass m_p + h² k,
   where s is the plate's travel along n since its first solve, v its velocity along n, d
   the drive point's travel (d_{k+1} = d_k + h v_drive; the spring is unstretched at the
   first solve). The spring is implicit (backward Euler): m_p (v_{k+1} − v_k) = h k (d_{k+1}
   − s_k − h v_{k+1}) + impulses, stable for any k h² / m_p. The beads' force is the fix
   wire/wall's force on its plane averaged over the steps since the last solve (the setup
   solve: the current one). After the solve the plate's plane is moved: from its current
   point at the θ-method velocity ((1 − θ) v_k + θ v_{k+1}) n over the next h (fix
   wire/wall's motion, so the beads see it where the grains push it).

   Outputs, per plate (4 values after the fix's other global values): its travel s, its
   velocity v (both along n), the grains' force on it along −n (positive: pushing it
   back) and the drive force along n (F, or the spring's k (d − s)).

   Restart: the fix's restart data hold each plate's state (v, s, d, the beads' force summed
   since the last solve, the outputs and the plane's velocity), keyed by its wall's index:
   a run continued from a restart file moves the plate as the straight run does (to the
   bit when the fix solves every step). A plate on a wall that had none when the file was
   written starts afresh, at the plane's velocity with an unstretched spring. */

#ifndef WIREGRAIN_NSCD_PLATE_H
#define WIREGRAIN_NSCD_PLATE_H

#include <string>
#include <vector>

#include "core/nscd/grain_step.h"
#include "common/plugin_args.h"

namespace LAMMPS_NS {
class LAMMPS;
}

namespace wiregrain_lmp {

class MovingPlaneWall;

class NscdPlates {
 public:
  // keyword `plate` of the wall `wall` (0-based; its wall_fix ID `wall_fix`, "" for a `wall`)
  void parse(StyleArgs& args, size_t wall, const std::string& wall_fix);
  bool empty() const { return plates_.empty(); }
  int output_size() const { return 4 * static_cast<int>(plates_.size()); }
  double output(int k) const;
  // at init: the planes' fixes (wall_fix of the fix nscd/polyhedra `id`: they are wire/wall
  // fixes by then) and the variables
  void init(LAMMPS_NS::LAMMPS* lmp, const std::string& id, const std::vector<std::string>& wall_fix_ids);
  // every step (all ranks): add the beads' force on each plate's plane
  void sum_wire_forces();
  // at a solve of step h: the plates' mass, velocity and force in `walls`
  void prepare(LAMMPS_NS::LAMMPS* lmp, std::vector<wiregrain::PlaneWall>& walls, double h);
  // after it: the plates' new state, their planes moved
  void advance(const std::vector<wiregrain::PlaneWall>& walls, const wiregrain::GrainStepResult& result, double h,
               double theta);
  // restart data: the plate count, then kStateNumbers per plate (its wall index first);
  // restore reads them onto the plates of the same walls (their planes set moving at init)
  // and returns how many numbers it read
  std::vector<double> state() const;
  size_t restore(const double* data);
  static constexpr int kStateNumbers = 14;

 private:
  // a number, or an equal-style variable (v_name)
  struct Value {
    double number = 0.0;
    std::string variable;
    int index = -1;
  };
  struct Plate {
    size_t wall = 0;
    std::string wall_fix;
    double mass = 0.0;
    bool spring = false;
    Value load;       // load: F
    double k = 0.0;   // spring: stiffness
    Value drive;      // spring: v_drive
    MovingPlaneWall* plane = nullptr;
    // state
    bool started = false;
    double velocity = 0.0, travel = 0.0, drive_travel = 0.0;
    double wire_sum[3] = {0.0, 0.0, 0.0};
    int wire_steps = 0;
    double next_drive = 0.0;  // d_{k+1} of the solve under way
    double grains_force = 0.0, drive_force = 0.0;
    bool restored = false;                            // from a restart: its plane set at init
    double plane_velocity[3] = {0.0, 0.0, 0.0};       // the restart's plane velocity
  };
  std::vector<Plate> plates_;
  std::string id_;

  static Value parse_value(StyleArgs& args, const std::string& keyword);
  double evaluate(LAMMPS_NS::LAMMPS* lmp, const Value& value) const;
  void resolve(LAMMPS_NS::LAMMPS* lmp, Value& value, const std::string& what) const;
};

}  // namespace wiregrain_lmp

#endif
