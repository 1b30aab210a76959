#include "fix_wire_elastic.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include <Eigen/Core>

#include "atom.h"
#include "atom_vec_wire.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "fix_nve_gear.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include "core/common/errors.h"
#include "core/common/validation.h"
#include "core/wire/gear_integrator.h"
#include "core/wire/wire_elasticity.h"
#include "atom_kinds.h"
#include "contact_checks.h"
#include "plugin_args.h"
#include "plugin_comm.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
constexpr double kPi = 3.14159265358979323846;
// Ghost beads must reach two segments away (the bending term at a neighbour needs the
// neighbour's neighbour); allow segments stretched by 25 %.
constexpr double kGhostReachInRestLengths = 2.5;

Eigen::Vector3d as_vector(const double *x) { return Eigen::Vector3d(x[0], x[1], x[2]); }

void add_force(double *f, const Eigen::Vector3d &g) {
  f[0] += g.x();
  f[1] += g.y();
  f[2] += g.z();
}
}  // namespace

FixWireElastic::FixWireElastic(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg),
      m_elo_(1.0),
      m_rot_(0.1),
      wire_(NULL),
      bead_energy_(NULL),
      sums_step_(-1),
      forces_step_(-1),
      reported_time_step_(false) {
  wiregrain_lmp::StyleArgs args(error, "fix", "wire/elastic", id, narg, arg, 3, {"E", "m_elo", "m_rot"});
  wire_ = AtomVecWire::of(atom);
  if (!wire_)
    args.fail("needs atom_style wire (or hybrid with wire), not '" + std::string(atom->atom_style) + "'");
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "E") {
      material_keywords_.youngs_modulus = args.value_positive(key);
      material_keywords_.has_youngs_modulus = true;
    }
    else if (key == "m_elo") m_elo_ = args.value_nonnegative(key);
    else if (key == "m_rot") m_rot_ = args.value_nonnegative(key);
    else args.unknown_keyword(key);
  }

  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 5;
  global_freq = 1;
  extscalar = 1;
  extvector = 0;
  peratom_flag = 1;
  size_peratom_cols = kBeadColumns;
  peratom_freq = 1;
  local_sums_[0] = local_sums_[1] = local_sums_[2] = 0.0;
  global_sums_[0] = global_sums_[1] = global_sums_[2] = 0.0;

  grow_arrays(atom->nmax);
  atom->add_callback(0);
}

FixWireElastic::~FixWireElastic() {
  atom->delete_callback(id, 0);
  memory->destroy(bead_energy_);
}

int FixWireElastic::setmask() {
  int mask = 0;
  mask |= POST_FORCE;
  mask |= MIN_POST_FORCE;
  mask |= THERMO_ENERGY;
  return mask;
}

void FixWireElastic::init() {
  // a grain in the group would enter the time-step check as a bead of its radius and mass
  wiregrain_lmp::require_no_grains(lmp, igroup, "fix", "wire/elastic", id);
  // E_w of each atom type (plugin_material.h)
  youngs_modulus_of_type_.assign(atom->ntypes + 1, 0.0);
  for (int type = 1; type <= atom->ntypes; type++)
    youngs_modulus_of_type_[type] =
        wiregrain_lmp::wire_material_of_type(lmp, type, material_keywords_, "fix", "wire/elastic", id).youngs_modulus;
  // the longest rest length decides how far ghost beads must reach
  double longest_local = 0.0, longest = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) longest_local = std::max(longest_local, wire_->wire_rest[i]);
  MPI_Allreduce(&longest_local, &longest, 1, MPI_DOUBLE, MPI_MAX, world);
  const double reach = kGhostReachInRestLengths * longest + neighbor->skin;
  wiregrain_lmp::ensure_ghost_reach(lmp, reach);
  // Without a pair style the neighbour cutoff is 0 and LIGGGHTS' atom sorting would stop
  // with "bin size = 0"; sort the beads on the ghost reach instead.
  if (force->pair == NULL && atom->sortfreq > 0) {
    char freq[32], bin[32];
    snprintf(freq, sizeof(freq), "%d", atom->sortfreq);
    snprintf(bin, sizeof(bin), "%.17g", reach);
    char sort[] = "sort";
    char *sort_args[3] = {sort, freq, bin};
    atom->modify_params(3, sort_args);
  }
}

double FixWireElastic::critical_time_step() {
  // the stiffest segment (shortest rest length, thickest bead, stiffest material) and the
  // lightest bead
  double local[4] = {1e300, 0.0, 1e300, 0.0}, global[4];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    if (wire_->wire_next[i] != 0) local[0] = std::min(local[0], wire_->wire_rest[i]);
    local[1] = std::max(local[1], atom->radius[i]);
    local[2] = std::min(local[2], atom->rmass[i]);
    local[3] = std::max(local[3], youngs_modulus_of_type_[atom->type[i]]);
  }
  local[1] = -local[1];
  local[3] = -local[3];
  MPI_Allreduce(local, global, 4, MPI_DOUBLE, MPI_MIN, world);
  if (global[0] >= 1e300) return 1e300;  // no segment in the group
  wiregrain::WireMaterial m;
  m.youngs_modulus = -global[3];
  m.elongation_multiplier = m_elo_;
  m.rotation_multiplier = m_rot_;
  m.segment_length = global[0];
  m.radius = -global[1];
  m.density = global[2] / (kPi * m.radius * m.radius * m.segment_length);
  return wiregrain::wire_critical_time_step(m);
}

void FixWireElastic::setup(int vflag) {
  // reported at the first run that has a segment (a deck may lay its wire later)
  const double dt_crit = reported_time_step_ ? 0.0 : critical_time_step();
  if (!reported_time_step_ && dt_crit < 1e300) {
    reported_time_step_ = true;
    const bool gear = wiregrain_lmp::gear5_integrates(lmp);
    // Verlet is stable for ω·dt < 2, the 6-value Gear corrector for ω·dt < 0.313
    const double limit = gear ? dt_crit * wiregrain::kGear5StableOmegaDt / 2.0 : dt_crit;
    if (comm->me == 0) {
      char line[512];
      snprintf(line, sizeof(line),
               "fix wire/elastic (id %s): elastic critical time step %.6g (Verlet limit), "
               "%s limit %.6g; timestep %.6g = %.3g of it\n",
               id, dt_crit, gear ? "gear5" : "verlet", limit, update->dt, update->dt / limit);
      if (screen) fputs(line, screen);
      if (logfile) fputs(line, logfile);
    }
    if (update->dt > limit && comm->me == 0) {
      char line[512];
      snprintf(line, sizeof(line),
               "fix wire/elastic (id %s): timestep %.6g exceeds the stable limit %.6g of the "
               "%s integrator for these wire springs",
               id, update->dt, limit, gear ? "gear5" : "verlet");
      error->warning(FLERR, line);
    }
  }
  post_force(vflag);
}

void FixWireElastic::min_setup(int vflag) { post_force(vflag); }

void FixWireElastic::min_post_force(int vflag) { post_force(vflag); }

int FixWireElastic::bead_index(int tag, int from_tag) {
  const int j = wire_->linked_bead(tag);
  if (j < 0) {
    const std::string msg = "fix wire/elastic (id " + std::string(id) + "): bead " +
                            std::to_string(from_tag) + " links to bead " + std::to_string(tag) +
                            ", which is neither owned nor a ghost here (a segment longer than "
                            "the ghost cutoff, or a link to a deleted bead)";
    error->one(FLERR, msg.c_str());
  }
  return j;
}

// Every owned bead computes the terms it takes part in and keeps its own share; a term
// whose partners are all owned is computed once and shared, one that spans ranks is
// computed by each rank for its own beads. No force goes to a ghost, so nothing needs a
// reverse communication and 1 and N ranks add the same terms.
void FixWireElastic::post_force(int /*vflag*/) {
  double **x = atom->x, **f = atom->f;
  const int *tag = atom->tag, *mask = atom->mask;
  const int *prev = wire_->wire_prev, *next = wire_->wire_next;
  const double *rest = wire_->wire_rest, *radius = atom->radius;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;

  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < kBeadColumns; k++) bead_energy_[i][k] = 0.0;

  // image of bead j nearest to position `ref`
  const auto image_near = [&](int j, const Eigen::Vector3d &ref) {
    double d[3] = {x[j][0] - ref.x(), x[j][1] - ref.y(), x[j][2] - ref.z()};
    domain->minimum_image(d);
    return Eigen::Vector3d(ref.x() + d[0], ref.y() + d[1], ref.z() + d[2]);
  };
  // the material of the segment from bead i to the next (of bead i's type and radius)
  const auto material_of = [&](int i, double segment_length) {
    wiregrain::WireMaterial m;
    m.youngs_modulus = youngs_modulus_of_type_[type[i]];
    m.radius = radius[i];
    m.segment_length = segment_length;
    m.elongation_multiplier = m_elo_;
    m.rotation_multiplier = m_rot_;
    return m;
  };
  // k_s = m_elo E A / l0 of the segment from bead i to the next
  const auto axial = [&](int i) { return material_of(i, rest[i]).axial_stiffness(); };
  // κ = m_rot E I / l at inner node c, l the mean rest length of its two segments (p to c, c on)
  const auto bending = [&](int c, int p) { return material_of(c, 0.5 * (rest[p] + rest[c])).bending_stiffness(); };

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const Eigen::Vector3d xi = as_vector(x[i]);
    const int p = prev[i] ? bead_index(prev[i], tag[i]) : -1;
    const int n = next[i] ? bead_index(next[i], tag[i]) : -1;
    const Eigen::Vector3d xp = p >= 0 ? image_near(p, xi) : xi;
    const Eigen::Vector3d xn = n >= 0 ? image_near(n, xi) : xi;

    if (n >= 0) {  // segment to the next bead: computed here, shared if the next is owned
      const wiregrain::StretchResult s = wiregrain::wire_stretch(xi, xn, axial(i), rest[i]);
      add_force(f[i], s.force_i);
      bead_energy_[i][0] += 0.5 * s.energy;
      if (n < nlocal) {
        add_force(f[n], s.force_j);
        bead_energy_[n][0] += 0.5 * s.energy;
      }
      bead_energy_[i][2] = (xn - xi).norm();
      bead_energy_[i][3] = s.tension;
      if (!(bead_energy_[i][2] > 0.0))  // the stretching force along (xn − xi)/|xn − xi| has no direction
        error->one(FLERR, ("fix wire/elastic (id " + std::string(id) + "): the segment from bead " +
                           std::to_string(tag[i]) + " to bead " + std::to_string(next[i]) + " has zero length at step " +
                           std::to_string(update->ntimestep) + " (rest length " + wiregrain::format_number(rest[i]) +
                           "): two beads at one position")
                              .c_str());
    }
    if (p >= nlocal) {  // segment from a ghost previous bead: our share only
      const wiregrain::StretchResult s = wiregrain::wire_stretch(xp, xi, axial(p), rest[p]);
      add_force(f[i], s.force_j);
      bead_energy_[i][0] += 0.5 * s.energy;
    }
    if (p >= 0 && n >= 0) {  // bending at this bead, shared with owned neighbours
      const wiregrain::BendResult b = wiregrain::wire_bend(xp, xi, xn, bending(i, p));
      add_force(f[i], b.force_j);
      if (p < nlocal) add_force(f[p], b.force_i);
      if (n < nlocal) add_force(f[n], b.force_k);
      bead_energy_[i][1] += b.energy;
    }
    if (p >= nlocal && prev[p] != 0) {  // bending at a ghost previous bead: our share
      const int pp = bead_index(prev[p], tag[p]);
      const wiregrain::BendResult b = wiregrain::wire_bend(image_near(pp, xp), xp, xi, bending(p, pp));
      add_force(f[i], b.force_k);
    }
    if (n >= nlocal && next[n] != 0) {  // bending at a ghost next bead: our share
      const int nn = bead_index(next[n], tag[n]);
      const wiregrain::BendResult b = wiregrain::wire_bend(xi, xn, image_near(nn, xn), bending(n, i));
      add_force(f[i], b.force_i);
    }
  }

  local_sums_[0] = local_sums_[1] = local_sums_[2] = 0.0;
  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < 3; k++) local_sums_[k] += bead_energy_[i][k];
  if (!std::isfinite(local_sums_[0] + local_sums_[1] + local_sums_[2])) {
    const std::string msg = "fix wire/elastic (id " + std::string(id) + "): non-finite bead position or "
                            "elastic energy at step " + std::to_string(update->ntimestep) +
                            " (time step too large for the wire springs?)";
    error->one(FLERR, msg.c_str());
  }
  sums_step_ = -1;
  forces_step_ = update->ntimestep;
}

void FixWireElastic::reduce_sums() {
  if (sums_step_ == update->ntimestep) return;
  MPI_Allreduce(local_sums_, global_sums_, 3, MPI_DOUBLE, MPI_SUM, world);
  sums_step_ = update->ntimestep;
}

double FixWireElastic::compute_scalar() {
  reduce_sums();
  return global_sums_[0] + global_sums_[1];
}

double FixWireElastic::compute_vector(int n) {
  reduce_sums();
  wiregrain::WireEnergyTotals totals;
  totals.stretching_energy = global_sums_[0];
  totals.bending_energy = global_sums_[1];
  totals.length = global_sums_[2];
  switch (n) {
    case 0: return totals.stretching_energy;
    case 1: return totals.bending_energy;
    case 2: return totals.total_energy();
    case 3: return totals.length;
    default: return totals.energy_per_length();
  }
}

wiregrain::BeadElasticEnergy FixWireElastic::bead_energy(int i) const {
  wiregrain::BeadElasticEnergy e;
  e.stretching = bead_energy_[i][0];
  e.bending = bead_energy_[i][1];
  e.segment_length = bead_energy_[i][2];
  return e;
}

void FixWireElastic::grow_arrays(int nmax) {
  memory->grow(bead_energy_, nmax, kBeadColumns, "wire/elastic:bead_energy");
  array_atom = bead_energy_;
}

void FixWireElastic::copy_arrays(int i, int j, int /*delflag*/) {
  for (int k = 0; k < kBeadColumns; k++) bead_energy_[j][k] = bead_energy_[i][k];
}

double FixWireElastic::memory_usage() { return double(atom->nmax) * kBeadColumns * sizeof(double); }
