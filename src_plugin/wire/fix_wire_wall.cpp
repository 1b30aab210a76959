#include "fix_wire_wall.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "atom.h"
#include "atom_vec_wire.h"
#include "comm.h"
#include "error.h"
#include "fix_wire_contact_history.h"
#include "modify.h"
#include "update.h"

#include "core/contact/contact_laws.h"
#include "core/contact/contact_list.h"
#include "core/contact/contact_time_step.h"
#include "core/contact/soft_contact.h"
#include "atom_kinds.h"
#include "bead_contact_load.h"
#include "companion_fix.h"
#include "plugin_args.h"
#include "plugin_material.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixWireWall::FixWireWall(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg),
      reference_step_(0),
      reference_dt_(0.0),
      wire_(NULL),
      history_(NULL),
      contacts_(new wiregrain::ContactList),
      stats_step_(-1) {
  friction_ = wiregrain_lmp::table1_friction();
  wiregrain_lmp::StyleArgs args(error, "fix", "wire/wall", id, narg, arg, 3,
                                wiregrain_lmp::concat({"velocity", "E", "nu"}, wiregrain_lmp::friction_keywords()));
  wire_ = AtomVecWire::of(atom);
  if (!wire_)
    args.fail("needs atom_style wire (or hybrid with wire), not '" + std::string(atom->atom_style) + "'");
  if (args.done() || args.next_word() != "plane") args.fail("expected 'plane px py pz nx ny nz'");
  for (int d = 0; d < 3; d++) point_[d] = args.value_double("plane");
  for (int d = 0; d < 3; d++) normal_[d] = args.value_double("plane");
  const double length = std::sqrt(normal_[0] * normal_[0] + normal_[1] * normal_[1] + normal_[2] * normal_[2]);
  if (!(length > 0.0)) args.fail("the plane normal (nx ny nz) must not be zero");
  for (int d = 0; d < 3; d++) {
    normal_[d] /= length;
    velocity_[d] = 0.0;
  }
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (wiregrain_lmp::parse_material_keyword(args, key, "E", "nu", material_keywords_)) continue;
    if (wiregrain_lmp::parse_friction_keyword(args, key, friction_)) continue;
    if (key == "velocity") {
      for (int d = 0; d < 3; d++) velocity_[d] = args.value_double(key);
    } else {
      args.unknown_keyword(key);
    }
  }
  wiregrain_lmp::check_friction(args, friction_);

  reference_step_ = update->ntimestep;
  reference_dt_ = update->dt;
  restart_global = 1;
  vector_flag = 1;
  size_vector = 5;
  global_freq = 1;
  extvector = 0;
  for (int k = 0; k < 5; k++) local_stats_[k] = global_stats_[k] = 0.0;

  history_id_ = std::string("WIRE_WALL_HISTORY_") + id;
}

// after Modify::add_fix has finished with this fix, which a nested add_fix would upset
void FixWireWall::post_create() {
  wiregrain_lmp::ensure_companion_fix(lmp, history_id_, "wire/contact/history");
}

FixWireWall::~FixWireWall() {
  wiregrain_lmp::delete_companion_fix(lmp, history_id_);
  delete contacts_;
}

const wiregrain::ContactList &FixWireWall::published_contacts() const { return *contacts_; }

int FixWireWall::setmask() { return POST_FORCE; }

void FixWireWall::init() {
  // a grain in the group would be pushed as a bead of its bounding radius
  wiregrain_lmp::require_no_grains(lmp, igroup, "fix", "wire/wall", id);
  // re-reference at every run start, so a `timestep` command between runs is honoured
  rereference();
  history_ = dynamic_cast<FixWireContactHistory *>(wiregrain_lmp::find_companion_fix(lmp, history_id_));
  // the rigid-wall modulus of each atom type's wire material (plugin_material.h)
  wall_modulus_of_type_.assign(atom->ntypes + 1, 0.0);
  for (int type = 1; type <= atom->ntypes; type++)
    wall_modulus_of_type_[type] = wiregrain::wire_wall_modulus(
        wiregrain_lmp::wire_material_of_type(lmp, type, material_keywords_, "fix", "wire/wall", id));
}

void FixWireWall::setup(int vflag) {
  check_time_step();
  post_force(vflag);
}

double FixWireWall::bead_length(int i) const {
  const double *rest = wire_->wire_rest;
  double previous_rest = 0.0;
  if (rest[i] <= 0.0 && wire_->wire_prev[i]) {
    const int j = wire_->linked_bead(wire_->wire_prev[i]);
    if (j >= 0) previous_rest = rest[j];
  }
  return wiregrain::bead_segment_length(rest[i], previous_rest, atom->radius[i]);
}

// At the setup of each run (all ranks): the stiffest contact of each wire type of the
// group (the longest segment a bead stands for, the thickest bead) on the lightest bead
// (the wall is rigid: the spring acts on the bead alone).
void FixWireWall::check_time_step() {
  const int ntypes = atom->ntypes, *type = atom->type, *mask = atom->mask;
  // per type: present; then the longest length, the largest radius, −the lightest mass
  std::vector<double> local(ntypes + 4, 0.0), global(ntypes + 4);
  local[ntypes + 3] = -INFINITY;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    local[type[i]] = 1.0;
    local[ntypes + 1] = std::max(local[ntypes + 1], bead_length(i));
    local[ntypes + 2] = std::max(local[ntypes + 2], atom->radius[i]);
    local[ntypes + 3] = std::max(local[ntypes + 3], -atom->rmass[i]);
  }
  MPI_Allreduce(local.data(), global.data(), ntypes + 4, MPI_DOUBLE, MPI_MAX, world);
  std::vector<wiregrain_lmp::ContactSpring> springs;
  if (std::isfinite(global[ntypes + 3]))
    for (int t = 1; t <= ntypes; t++) {
      if (global[t] == 0.0) continue;
      wiregrain_lmp::ContactSpring s;
      s.effective_modulus = wall_modulus_of_type_[t];
      s.segment_length = global[ntypes + 1];
      s.radius = global[ntypes + 2];
      s.friction = friction_;
      s.mass = -global[ntypes + 3];
      s.mass_name = "the lightest bead";
      springs.push_back(s);
    }
  time_step_check_.check(lmp, "fix", "wire/wall", id, springs);
}

void FixWireWall::current_point(double p[3]) const {
  const double t = reference_dt_ * double(update->ntimestep - reference_step_);
  for (int d = 0; d < 3; d++) p[d] = point_[d] + velocity_[d] * t;
}

// the wall continues from where it is (a changed time step or velocity)
void FixWireWall::rereference() {
  current_point(point_);
  reference_step_ = update->ntimestep;
  reference_dt_ = update->dt;
}

void FixWireWall::reset_dt() { rereference(); }

// fix_modify ID velocity vx vy vz
int FixWireWall::modify_param(int narg, char **arg) {
  if (narg < 1 || std::string(arg[0]) != "velocity") return 0;
  wiregrain_lmp::StyleArgs args(error, "fix_modify", "wire/wall", id, std::min(narg, 4), arg, 0);
  args.next_word();
  rereference();
  for (int d = 0; d < 3; d++) velocity_[d] = args.value_double("velocity");
  return 4;
}

void FixWireWall::post_force(int /*vflag*/) {
  double **x = atom->x, **v = atom->v, **f = atom->f;
  const int *mask = atom->mask, *type = atom->type, *tag = atom->tag;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int nlocal = atom->nlocal;
  double p[3];
  current_point(p);
  const Eigen::Vector3d n(normal_[0], normal_[1], normal_[2]);
  const Eigen::Vector3d wall_velocity(velocity_[0], velocity_[1], velocity_[2]);

  const bool setup = update->setupflag != 0;
  history_->begin_step();
  for (int k = 0; k < 5; k++) local_stats_[k] = 0.0;
  contacts_->clear();
  int deepest = -1;  // this rank's bead of the largest overlap / r_w, and its gap
  double deepest_gap = 0.0;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double gap = (x[i][0] - p[0]) * n.x() + (x[i][1] - p[1]) * n.y() + (x[i][2] - p[2]) * n.z() - radius[i];
    if (gap >= 0.0) continue;
    if (deepest < 0 || -gap * radius[deepest] > -deepest_gap * radius[i]) {
      deepest = i;
      deepest_gap = gap;
    }
    const wiregrain::SoftContactLaw law =
        wiregrain::segment_contact_law(wall_modulus_of_type_[type[i]], bead_length(i), radius[i], friction_);
    wiregrain::TangentialHistory h;
    history_->lookup(i, 0, h);
    const Eigen::Vector3d u = Eigen::Vector3d(v[i][0], v[i][1], v[i][2]) - wall_velocity;
    // the setup force call of a run does not advance the spring (see pair wire/contact)
    wiregrain::TangentialHistory advanced = h;
    const wiregrain::SoftContactForce fc =
        wiregrain::soft_contact_force(law, -gap, n, u, setup ? 0.0 : update->dt, rmass[i], advanced);
    history_->store(i, 0, setup ? h : advanced);
    // the bead's time-step check (contact_time_step.h): the wall does not move with it
    if (wire_->contact_load_wanted)
      wiregrain_lmp::add_bead_contact_load(
          wire_->contact_load[i], 1.0, wiregrain::contact_load_entries(wiregrain::contact_spring_dashpot(law, rmass[i]), n));
    for (int d = 0; d < 3; d++) {
      f[i][d] += fc.force[d];
      local_stats_[2 + d] -= fc.force[d];
    }
    local_stats_[0] += 1.0;
    local_stats_[1] = std::max(local_stats_[1], -gap);
    wiregrain::ContactRecord record;
    record.kind = wiregrain::ContactKind::wire_wall;
    record.a = -1;  // the one wall of this fix
    record.b = tag[i];
    record.point = Eigen::Vector3d(x[i][0], x[i][1], x[i][2]) - (radius[i] + 0.5 * gap) * n;  // middle of the overlap
    record.normal = n;
    record.force = fc.force;
    record.overlap = -gap;
    record.status = advanced.sliding ? wiregrain::ContactStatus::slide : wiregrain::ContactStatus::stick;
    contacts_->add(record);
  }
  history_->end_step();
  stats_step_ = -1;
  if (overlap_warnings_.due(deepest >= 0 ? -deepest_gap / radius[deepest] : 0.0))
    overlap_warnings_.warn(lmp, "fix", "wire/wall", id, -deepest_gap, radius[deepest],
                            "bead " + std::to_string(tag[deepest]) + " and the wall",
                            "a stiffer material (E)");
}

double FixWireWall::compute_vector(int k) {
  if (stats_step_ != update->ntimestep) {
    double sums[4] = {local_stats_[0], local_stats_[2], local_stats_[3], local_stats_[4]}, total[4];
    MPI_Allreduce(sums, total, 4, MPI_DOUBLE, MPI_SUM, world);
    MPI_Allreduce(&local_stats_[1], &global_stats_[1], 1, MPI_DOUBLE, MPI_MAX, world);
    global_stats_[0] = total[0];
    for (int d = 0; d < 3; d++) global_stats_[2 + d] = total[1 + d];
    stats_step_ = update->ntimestep;
  }
  return global_stats_[k];
}

void FixWireWall::force_on_plane(double f[3]) {
  for (int d = 0; d < 3; d++) f[d] = compute_vector(2 + d);
}

void FixWireWall::move_plane(const double point[3], const double velocity[3]) {
  for (int d = 0; d < 3; d++) {
    point_[d] = point[d];
    velocity_[d] = velocity[d];
  }
  reference_step_ = update->ntimestep;
  reference_dt_ = update->dt;
}

// The wall's current position, so a restarted run continues from it.
void FixWireWall::write_restart(FILE *fp) {
  double p[3];
  current_point(p);
  if (comm->me == 0) {
    const int size = 3 * sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(p, sizeof(double), 3, fp);
  }
}

void FixWireWall::restart(char *buf) {
  const double *p = reinterpret_cast<const double *>(buf);
  for (int d = 0; d < 3; d++) point_[d] = p[d];
  reference_step_ = update->ntimestep;
  reference_dt_ = update->dt;
}
