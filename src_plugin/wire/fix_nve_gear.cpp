#include "fix_nve_gear.h"

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "update.h"

#include "atom_kinds.h"
#include "atom_vec_wire.h"
#include "core/common/validation.h"
#include "core/contact/contact_time_step.h"
#include "core/wire/gear_integrator.h"
#include "bead_contact_load.h"
#include "plugin_args.h"
#include "plugin_comm.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
// the per-bead check's largest timestep / limit is exact above this, the traces' bound below
constexpr double kExactRatioAbove = 0.5;
constexpr int kStartedFlag = wiregrain::kGearHistorySize;   // index of the flag
constexpr int kPerAtom = wiregrain::kGearHistorySize + 1;    // values stored per atom
}  // namespace

FixNVEGear::FixNVEGear(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg),
      scheme_(GEAR5),
      velocity_forces_(false),
      dt_(0.0),
      history_(NULL),
      wire_(NULL),
      check_every_(10),
      checking_this_step_(false),
      unstable_steps_(0),
      largest_ratio_(0.0),
      load_warnings_(0) {
  wiregrain_lmp::StyleArgs args(error, "fix", "nve/gear", id, narg, arg, 3, {"scheme", "forces", "check_every"});
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "scheme") {
      const std::string v = args.value_word(key);
      if (v == "gear5") scheme_ = GEAR5;
      else if (v == "verlet") scheme_ = VERLET;
      else args.fail("value of 'scheme' must be gear5 or verlet, got '" + v + "'");
    } else if (key == "forces") {
      const std::string v = args.value_word(key);
      if (v == "position") velocity_forces_ = false;
      else if (v == "velocity") velocity_forces_ = true;
      else args.fail("value of 'forces' must be position or velocity, got '" + v + "'");
    } else if (key == "check_every") {
      check_every_ = (int)args.value_int_in_range(key, 0);
    } else {
      args.unknown_keyword(key);
    }
  }

  time_integrate = 1;
  restart_peratom = 1;
  vector_flag = 1;
  size_vector = 2;
  global_freq = 1;
  extvector = 0;
  comm_reverse = wiregrain_lmp::kBeadContactLoadSize;
  create_attribute = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(0);
  atom->add_callback(1);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixNVEGear::~FixNVEGear() {
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  memory->destroy(history_);
}

int FixNVEGear::setmask() {
  int mask = 0;
  mask |= INITIAL_INTEGRATE;
  mask |= PRE_FORCE;
  mask |= FINAL_INTEGRATE;
  return mask;
}

void FixNVEGear::init() {
  if (!atom->rmass_flag && !atom->mass_setflag)
    wiregrain_lmp::style_error(error, "fix", "nve/gear", id,
                               "atoms need a mass (per-atom rmass or 'mass' per type)");
  if (atom->rmass_flag == 0) {
    for (int t = 1; t <= atom->ntypes; t++)
      if (!atom->mass_setflag[t])
        wiregrain_lmp::style_error(error, "fix", "nve/gear", id,
                                   "mass of atom type " + std::to_string(t) + " is not set");
  }
  // a = F/m needs a finite m > 0 (LIGGGHTS' set diameter 0 gives a sphere rmass 0, set mass 1e400 inf)
  if (atom->rmass) {
    // the lowest tag of a bad mass in the group over all ranks, and that mass
    const int none = std::numeric_limits<int>::max();
    int mine = none, lowest = none;
    double mine_mass = 0.0, mass = 0.0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & groupbit) && !(std::isfinite(atom->rmass[i]) && atom->rmass[i] > 0.0) &&
          atom->tag[i] < mine) {
        mine = atom->tag[i];
        mine_mass = atom->rmass[i];
      }
    MPI_Allreduce(&mine, &lowest, 1, MPI_INT, MPI_MIN, world);
    if (lowest != none) {
      const double owned = mine == lowest ? mine_mass : 0.0;  // only its owner adds a value
      MPI_Allreduce(&owned, &mass, 1, MPI_DOUBLE, MPI_SUM, world);
      wiregrain_lmp::style_error(error, "fix", "nve/gear", id,
                                 "atom " + std::to_string(lowest) + " has mass " + wiregrain::format_number(mass) +
                                     " (must be a finite number > 0)");
    }
  } else {
    for (int t = 1; t <= atom->ntypes; t++)
      if (!(std::isfinite(atom->mass[t]) && atom->mass[t] > 0.0))
        wiregrain_lmp::style_error(error, "fix", "nve/gear", id,
                                   "mass of atom type " + std::to_string(t) + " is " +
                                       wiregrain::format_number(atom->mass[t]) + " (must be a finite number > 0)");
  }
  // Point masses only: a grain of atom_style polyhedron is a rigid body whose rotation this
  // fix would drop; wire beads and stock grains (spheres integrated as point masses) are
  // given by separate groups
  const wiregrain_lmp::AtomKindCounts kinds = wiregrain_lmp::AtomKinds(lmp).count(groupbit);
  const std::string group_name = std::string("group '") + group->names[igroup] + "' holds ";
  if (kinds.polyhedra > 0)
    wiregrain_lmp::style_error(error, "fix", "nve/gear", id,
                               group_name + std::to_string(kinds.polyhedra) +
                                   " grains of atom_style polyhedron (rigid bodies: integrate them by fix "
                                   "nscd/polyhedra or fix nve/polyhedron)");
  if (kinds.beads > 0 && kinds.stock_grains > 0)
    wiregrain_lmp::style_error(error, "fix", "nve/gear", id,
                               group_name + std::to_string(kinds.beads) + " wire beads and " +
                                   std::to_string(kinds.stock_grains) +
                                   " grains (give the wire beads only, or the grains only)");
  dt_ = update->dt;
  wire_ = AtomVecWire::of(atom);
}

void FixNVEGear::reset_dt() { dt_ = update->dt; }

double FixNVEGear::mass_of(int i) const {
  return atom->rmass ? atom->rmass[i] : atom->mass[atom->type[i]];
}

void FixNVEGear::start_history(int i) {
  const double inv_m = force->ftm2v / mass_of(i);
  const double a[3] = {atom->f[i][0] * inv_m, atom->f[i][1] * inv_m, atom->f[i][2] * inv_m};
  wiregrain::gear5_start(history_[i], a);
  history_[i][kStartedFlag] = 1.0;
}

// The forces of the setup step give each new atom its first acceleration; atoms that
// carry a history (restart, earlier run) keep it.
void FixNVEGear::setup(int /*vflag*/) {
  if (scheme_ != GEAR5) return;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++)
    if ((atom->mask[i] & groupbit) && history_[i][kStartedFlag] == 0.0) start_history(i);
}

void FixNVEGear::initial_integrate(int /*vflag*/) {
  double **x = atom->x, **v = atom->v, **f = atom->f;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  if (scheme_ == GEAR5) {
    for (int i = 0; i < nlocal; i++)
      if (mask[i] & groupbit) wiregrain::gear5_predict(x[i], v[i], history_[i], dt_);
  } else {
    // the first half kick with the acceleration of the last step's end (kept with the
    // atom and in restart files: after a restart or between runs LIGGGHTS' setup
    // recomputes the forces with the full-step velocities, which changes velocity-
    // dependent forces such as contact damping); a new atom's from its setup force
    for (int i = 0; i < nlocal; i++)
      if (mask[i] & groupbit) {
        const double inv_m = force->ftm2v / mass_of(i);
        const double setup_a[3] = {f[i][0] * inv_m, f[i][1] * inv_m, f[i][2] * inv_m};
        const double *a = history_[i][kStartedFlag] != 0.0 ? history_[i] : setup_a;
        wiregrain::verlet_kick_drift(x[i], v[i], a, dt_);
      }
  }
}

void FixNVEGear::final_integrate() {
  double **x = atom->x, **v = atom->v, **f = atom->f;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const wiregrain::GearCorrector corrector(velocity_forces_
                                                ? wiregrain::GearCoefficients::velocity_forces()
                                                : wiregrain::GearCoefficients::position_forces(),
                                            dt_);
  if (checking_this_step_) {
    check_contact_loads();
    wire_->contact_load_wanted = false;
    checking_this_step_ = false;
  }
  int non_finite = -1;  // the first atom with a non-finite force, checked after the loop
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double inv_m = force->ftm2v / mass_of(i);
    const double a[3] = {f[i][0] * inv_m, f[i][1] * inv_m, f[i][2] * inv_m};
    if (non_finite < 0 && !std::isfinite(a[0] + a[1] + a[2])) non_finite = i;
    if (scheme_ == VERLET) {
      wiregrain::verlet_kick(v[i], a, dt_);
      for (int d = 0; d < 3; d++) history_[i][d] = a[d];  // x'', where Gear-5 keeps it
      history_[i][kStartedFlag] = 1.0;
    } else if (history_[i][kStartedFlag] == 0.0) {
      // an atom created during the run (fix insert/...): its first step predicted with a
      // zero history; start the history from the force it feels now.
      wiregrain::gear5_start(history_[i], a);
      history_[i][kStartedFlag] = 1.0;
    } else {
      wiregrain::gear5_correct(x[i], v[i], history_[i], a, corrector);
    }
  }
  // a NaN or inf from any force style stops here instead of spreading through the positions
  if (non_finite >= 0)
    error->one(FLERR, ("fix nve/gear (id " + std::string(id) + "): atom " + std::to_string(atom->tag[non_finite]) +
                       " has a non-finite force at step " + std::to_string(update->ntimestep) +
                       " (from a force style or fix acting on it)")
                          .c_str());
}

// The contact styles add to the beads' loads while they compute their forces (owned and
// ghost beads) in a step the check asks for, so the loads start from zero before them.
// (Forming and adding each contact's loads is what the check costs: +13 % per step on a
// piled wire checked every step, bench/compare_builds.py; 2026-11-26, commit ad0e38a.)
void FixNVEGear::pre_force(int /*vflag*/) {
  if (!wire_ || check_every_ == 0 || update->ntimestep % check_every_ != 0) return;
  checking_this_step_ = true;
  wire_->contact_load_wanted = true;
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++)
    for (int e = 0; e < wiregrain_lmp::kBeadContactLoadSize; e++) wire_->contact_load[i][e] = 0.0;
}

// Each owned bead's limit from its summed contact springs and dashpots against the step
// (core/contact/contact_time_step.h); the bead furthest beyond it is named by its owner.
void FixNVEGear::check_contact_loads() {
  if (!wire_) return;
  comm->reverse_comm_fix(this);
  // summed into their owners: cleared, so that another fix nve/gear adds nothing twice
  for (int i = atom->nlocal; i < atom->nlocal + atom->nghost; i++)
    for (int e = 0; e < wiregrain_lmp::kBeadContactLoadSize; e++) wire_->contact_load[i][e] = 0.0;
  const bool gear = scheme_ == GEAR5;
  struct {
    double ratio;
    int rank;
  } mine = {0.0, comm->me}, worst;
  double record[4] = {0.0, 0.0, 0.0, 0.0};  // tag, contacts, m, limit
  for (int i = 0; i < atom->nlocal; i++) {
    const double *row = wire_->contact_load[i];
    if (!(atom->mask[i] & groupbit) || row[wiregrain_lmp::kBeadContactLoadSize - 1] == 0.0) continue;  // no contact
    // the bound from the traces of K and Γ (core: bead_contact_time_step_bound): the
    // eigenvalues only for a bead that may be the worst and beyond half its limit
    const double bound = dt_ / wiregrain::bead_contact_time_step(row[0] + row[1] + row[2], row[6] + row[7] + row[8],
                                                                 mass_of(i))
                                   .limit(gear);
    if (bound <= mine.ratio) continue;
    if (bound <= kExactRatioAbove) {
      mine.ratio = bound;
      const double values[4] = {double(atom->tag[i]), row[wiregrain_lmp::kBeadContactLoadSize - 1], mass_of(i),
                                dt_ / bound};
      std::memcpy(record, values, sizeof(values));
      continue;
    }
    const wiregrain::BeadContactLoad load = wiregrain_lmp::bead_contact_load(row);
    const double limit = wiregrain::bead_contact_time_step(load, mass_of(i)).limit(gear);
    const double ratio = dt_ / limit;
    if (ratio > mine.ratio) {
      mine.ratio = ratio;
      const double values[4] = {double(atom->tag[i]), double(load.contacts), mass_of(i), limit};
      std::memcpy(record, values, sizeof(values));
    }
  }
  MPI_Allreduce(&mine, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, world);
  largest_ratio_ = worst.ratio;
  if (!(worst.ratio > 1.0)) return;
  unstable_steps_++;
  if (load_warnings_ >= 10) return;
  load_warnings_++;
  MPI_Bcast(record, 4, MPI_DOUBLE, worst.rank, world);
  if (comm->me != 0) return;
  char text[640];
  std::snprintf(text, sizeof(text),
                "fix nve/gear (id %s): at step %ld bead %.0f carries %.0f contact%s whose summed springs and dashpots "
                "on its mass %g give a %s limit of %g, below the timestep %g (such a bead rattles at the contact "
                "frequency instead of coming to rest); use a smaller timestep or less contact damping (restitution "
                "closer to 1)%s",
                id, (long)update->ntimestep, record[0], record[1], record[1] == 1.0 ? "" : "s", record[2],
                gear ? "gear5" : "Verlet", record[3], dt_,
                load_warnings_ == 10 ? " (the last such warning)" : "");
  error->warning(FLERR, text);
}

double FixNVEGear::compute_vector(int k) { return k == 0 ? double(unstable_steps_) : largest_ratio_; }

int FixNVEGear::pack_reverse_comm(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int e = 0; e < wiregrain_lmp::kBeadContactLoadSize; e++) buf[m++] = wire_->contact_load[i][e];
  return comm_reverse;
}

void FixNVEGear::unpack_reverse_comm(int n, int *list, double *buf) {
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int e = 0; e < wiregrain_lmp::kBeadContactLoadSize; e++) wire_->contact_load[list[k]][e] += buf[m++];
}

double FixNVEGear::memory_usage() { return double(atom->nmax) * kPerAtom * sizeof(double); }

void FixNVEGear::grow_arrays(int nmax) { memory->grow(history_, nmax, kPerAtom, "nve/gear:history"); }

void FixNVEGear::copy_arrays(int i, int j, int /*delflag*/) {
  std::memcpy(history_[j], history_[i], kPerAtom * sizeof(double));
}

void FixNVEGear::set_arrays(int i) {
  for (int k = 0; k < kPerAtom; k++) history_[i][k] = 0.0;
}

int FixNVEGear::pack_exchange(int i, double *buf) {
  for (int k = 0; k < kPerAtom; k++) buf[k] = history_[i][k];
  return kPerAtom;
}

int FixNVEGear::unpack_exchange(int nlocal, double *buf) {
  for (int k = 0; k < kPerAtom; k++) history_[nlocal][k] = buf[k];
  return kPerAtom;
}

int FixNVEGear::pack_restart(int i, double *buf) {
  buf[0] = kPerAtom + 1;
  for (int k = 0; k < kPerAtom; k++) buf[k + 1] = history_[i][k];
  return kPerAtom + 1;
}

void FixNVEGear::unpack_restart(int nlocal, int nth) {
  const double *record = wiregrain_lmp::fix_restart_record(atom, nlocal, nth, kPerAtom);
  if (!record) set_arrays(nlocal);  // created after read_restart: starts as new
  else
    for (int k = 0; k < kPerAtom; k++) history_[nlocal][k] = record[k];
}

int FixNVEGear::size_restart(int /*nlocal*/) { return kPerAtom + 1; }

int FixNVEGear::maxsize_restart() { return kPerAtom + 1; }
