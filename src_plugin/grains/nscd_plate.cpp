// fix nscd/polyhedra's plates (nscd_plate.h): the keyword, the force on each plate at a
// solve and its motion after it.
#include "nscd_plate.h"

#include <cmath>
#include <cstdlib>

#include "error.h"
#include "fix.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

#include "common/moving_plane_wall.h"
#include "core/common/validation.h"

namespace wiregrain_lmp {

NscdPlates::Value NscdPlates::parse_value(StyleArgs& args, const std::string& keyword) {
  Value value;
  const std::string word = args.value_word(keyword);
  if (word.compare(0, 2, "v_") == 0 && word.size() > 2) {
    value.variable = word.substr(2);
    return value;
  }
  char* end = nullptr;
  value.number = std::strtod(word.c_str(), &end);
  if (end == word.c_str() || *end != '\0' || !std::isfinite(value.number))
    args.fail("value of '" + keyword + "' must be a finite number or v_name (an equal-style variable), got '" + word + "'");
  return value;
}

void NscdPlates::parse(StyleArgs& args, size_t wall, const std::string& wall_fix) {
  if (wall_fix.empty()) args.fail("'plate' must follow a 'wall_fix' (a plate moves the plane of a fix wire/wall)");
  for (const Plate& p : plates_)
    if (p.wall == wall) args.fail("wall_fix " + wall_fix + " has a 'plate' already");
  Plate plate;
  plate.wall = wall;
  plate.wall_fix = wall_fix;
  plate.mass = args.value_positive("plate m_p");
  const std::string mode = args.value_word("plate m_p");
  if (mode == "load") {
    plate.load = parse_value(args, "plate load");
  } else if (mode == "spring") {
    plate.spring = true;
    plate.k = args.value_positive("plate spring k");
    plate.drive = parse_value(args, "plate spring v_drive");
  } else {
    args.fail("value of 'plate' mode must be load or spring, got '" + mode + "'");
  }
  plates_.push_back(plate);
}

void NscdPlates::resolve(LAMMPS_NS::LAMMPS* lmp, Value& value, const std::string& what) const {
  if (value.variable.empty()) return;
  std::string name = value.variable;
  value.index = lmp->input->variable->find(&name[0]);
  if (value.index < 0)
    style_error(lmp->error, "fix", "nscd/polyhedra", id_, "plate " + what + ": variable '" + value.variable + "' does not exist");
  if (!lmp->input->variable->equalstyle(value.index))
    style_error(lmp->error, "fix", "nscd/polyhedra", id_, "plate " + what + ": variable '" + value.variable + "' is not equal-style");
}

void NscdPlates::init(LAMMPS_NS::LAMMPS* lmp, const std::string& id, const std::vector<std::string>& wall_fix_ids) {
  id_ = id;
  for (Plate& p : plates_) {
    const int ifix = lmp->modify->find_fix(&wall_fix_ids[p.wall][0]);
    p.plane = ifix < 0 ? nullptr : dynamic_cast<MovingPlaneWall*>(lmp->modify->fix[ifix]);
    if (!p.plane)  // the wall_fix check before names a missing or wrong fix
      style_error(lmp->error, "fix", "nscd/polyhedra", id_, "plate: wall_fix " + p.wall_fix + " is not a fix wire/wall");
    resolve(lmp, p.load, "load");
    resolve(lmp, p.drive, "spring v_drive");
    if (p.restored) {  // the plane where its fix's restart put it, moving as it was
      double point[3];
      p.plane->current_point(point);
      p.plane->move_plane(point, p.plane_velocity);
      p.restored = false;
    }
  }
}

std::vector<double> NscdPlates::state() const {
  std::vector<double> data = {double(plates_.size())};
  for (const Plate& p : plates_) {
    const double* v = p.plane ? p.plane->velocity() : p.plane_velocity;
    const double record[kStateNumbers] = {double(p.wall), p.started ? 1.0 : 0.0, p.velocity, p.travel,
                                          p.drive_travel, p.wire_sum[0], p.wire_sum[1], p.wire_sum[2],
                                          double(p.wire_steps), p.grains_force, p.drive_force, v[0], v[1], v[2]};
    data.insert(data.end(), record, record + kStateNumbers);
  }
  return data;
}

size_t NscdPlates::restore(const double* data) {
  const size_t plates = (size_t)data[0];
  for (size_t k = 0; k < plates; k++) {
    const double* r = data + 1 + k * kStateNumbers;
    for (Plate& p : plates_) {
      if (p.wall != (size_t)r[0]) continue;
      p.started = r[1] != 0.0;
      p.velocity = r[2];
      p.travel = r[3];
      p.drive_travel = r[4];
      for (int d = 0; d < 3; d++) p.wire_sum[d] = r[5 + d];
      p.wire_steps = (int)r[8];
      p.grains_force = r[9];
      p.drive_force = r[10];
      for (int d = 0; d < 3; d++) p.plane_velocity[d] = r[11 + d];
      p.restored = true;
    }
  }
  return 1 + plates * kStateNumbers;
}

double NscdPlates::evaluate(LAMMPS_NS::LAMMPS* lmp, const Value& value) const {
  if (value.index < 0) return value.number;
  lmp->modify->clearstep_compute();
  const double v = lmp->input->variable->compute_equal(value.index);
  lmp->modify->addstep_compute(lmp->update->ntimestep + 1);
  if (!std::isfinite(v))
    style_error(lmp->error, "fix", "nscd/polyhedra", id_,
                "plate: variable '" + value.variable + "' is " + wiregrain::format_number(v) + " at step " +
                    std::to_string(lmp->update->ntimestep));
  return v;
}

void NscdPlates::sum_wire_forces() {
  for (Plate& p : plates_) {
    double f[3];
    p.plane->force_on_plane(f);
    for (int d = 0; d < 3; d++) p.wire_sum[d] += f[d];
    p.wire_steps++;
  }
}

void NscdPlates::prepare(LAMMPS_NS::LAMMPS* lmp, std::vector<wiregrain::PlaneWall>& walls, double h) {
  for (Plate& p : plates_) {
    wiregrain::PlaneWall& wall = walls[p.wall];
    const Eigen::Vector3d& n = wall.normal;
    if (!p.started) {  // the first solve: from the plane's own velocity, the spring unstretched
      p.velocity = n.dot(Eigen::Vector3d(p.plane->velocity()[0], p.plane->velocity()[1], p.plane->velocity()[2]));
      p.started = true;
    }
    double wire[3];
    if (p.wire_steps > 0)
      for (int d = 0; d < 3; d++) wire[d] = p.wire_sum[d] / p.wire_steps;
    else
      p.plane->force_on_plane(wire);  // the setup solve: the setup force call's
    const double on_plane = n.dot(Eigen::Vector3d(wire[0], wire[1], wire[2]));
    double drive, mass = p.mass;
    if (p.spring) {  // backward Euler: k (d_{k+1} − s_k − h v_{k+1}) = k (d_{k+1} − s_k − h v_k) − h k (v_{k+1} − v_k)
      p.next_drive = p.drive_travel + h * evaluate(lmp, p.drive);
      drive = p.k * (p.next_drive - p.travel - h * p.velocity);
      mass += h * h * p.k;
    } else {
      drive = evaluate(lmp, p.load);
      p.drive_force = drive;
    }
    wall.mass = mass;
    wall.velocity = p.velocity * n;
    wall.force = (drive + on_plane) * n;
  }
}

void NscdPlates::advance(const std::vector<wiregrain::PlaneWall>& walls, const wiregrain::GrainStepResult& result,
                         double h, double theta) {
  for (Plate& p : plates_) {
    const wiregrain::PlaneWall& wall = walls[p.wall];
    const Eigen::Vector3d& n = wall.normal;
    const Eigen::Vector3d step = wiregrain::wall_step_displacement(wall, result.wall_velocities[p.wall], h, theta);
    p.velocity = n.dot(result.wall_velocities[p.wall]);
    p.travel += n.dot(step);
    p.grains_force = -n.dot(result.wall_forces[p.wall]);
    if (p.spring) {
      p.drive_travel = p.next_drive;
      p.drive_force = p.k * (p.drive_travel - p.travel);
    }
    for (double& f : p.wire_sum) f = 0.0;
    p.wire_steps = 0;
    // the plane from where it is now, over the next h at the θ-method velocity
    double point[3];
    p.plane->current_point(point);
    const Eigen::Vector3d velocity = step / h;
    p.plane->move_plane(point, velocity.data());
  }
}

double NscdPlates::output(int k) const {
  const Plate& p = plates_[k / 4];
  switch (k % 4) {
    case 0: return p.travel;
    case 1: return p.velocity;
    case 2: return p.grains_force;
    default: return p.drive_force;
  }
}

}  // namespace wiregrain_lmp
