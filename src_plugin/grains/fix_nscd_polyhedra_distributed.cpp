// fix nscd/polyhedra `solve distributed` (docs/commands/fix_nscd_polyhedra.md, "MPI"):
// each rank steps the pairs it owns with its own grains and LIGGGHTS' ghost grains
// (core/nscd/grain_step.h, GrainPartition; grains/rank_grains.h for the communication).
#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

#include "atom.h"
#include "atom_vec_polyhedron.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "neighbor.h"
#include "update.h"

#include "core/common/validation.h"
#include "core/geometry/shape_library.h"
#include "fix_nscd_polyhedra.h"
#include "fix_nscd_polyhedra_state.h"
#include "plugin_args.h"
#include "plugin_comm.h"
#include "plugin_vector.h"
#include "rank_grains.h"

using namespace LAMMPS_NS;
using namespace fix_nscd_polyhedra_layout;
using wiregrain_lmp::vec3;

namespace {

// The activation distance the ghost cutoff allows for at a run start, beyond the margin,
// as a fraction of the largest bounding radius (the step's own is 4 h v_max; a run that
// needs more stops with an ERROR naming the cutoff to set).
constexpr double kGhostActivationOfRadius = 0.25;

}  // namespace

// The options distributed steps do not carry, as the end of a sentence "... does not
// <what>" ("" when the fix's keywords and box allow solve distributed).
std::string FixNSCDPolyhedra::distributed_refusal() const {
  if (core_->options.sleep.on()) return "take sleeping grains (keyword 'sleep'): use 'solve replicated'";
  if (core_->options.rolling_friction > 0.0) return "take 'rolling_friction': use 'solve replicated'";
  if (problem_every_ > 0) return "write the whole problem ('write_problems'): use 'solve replicated'";
  if (core_->options.warm_geometry)
    return "take 'warm_geometry yes' (its GJK simplices are not in the restart file): use 'solve replicated'";
  if (domain->triclinic) return "take a triclinic box: use 'solve replicated'";
  if (!core_->plates.empty()) return "take a 'plate' (the plate would be a body of every rank): use 'solve replicated'";
  return "";
}

// Checked when the fix is defined and at each run start (fix_modify may turn sleeping on,
// also after solve auto chose distributed).
void FixNSCDPolyhedra::check_distributed_keywords() {
  const std::string refusal = distributed_refusal();
  if (refusal.empty()) return;
  const std::string mode = solve_choice_ == SolveChoice::automatic
                               ? "'solve auto' (distributed on " + std::to_string(comm->nprocs) + " ranks)"
                               : "'solve distributed'";
  wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id, mode + " does not " + refusal);
}

// The ghost cutoff that holds every partner within `activation` of a rank's own grains
// as ghosts until the next reneighbouring (atoms move at most skin/2 before it): a pair
// reaches 2 R_max + activation between centres. LIGGGHTS' granular communication
// (an atom style with a radius, orthogonal box: Comm::use_gran_opt) sends an atom within
// cutghost/2 + skin/2 + its radius of a subdomain, which asks 2 R_max + 2 activation +
// skin; otherwise an atom within cutghost, which asks 2 R_max + activation + skin.
double FixNSCDPolyhedra::needed_ghost_cutoff(double activation) const {
  const bool halved = domain->triclinic == 0 && atom->radius != nullptr;
  return 2.0 * largest_radius_ + (halved ? 2.0 : 1.0) * activation + neighbor->skin;
}

// The cutoff asked of LIGGGHTS at each Comm::setup (it adds the skin): the margin and
// kGhostActivationOfRadius R_max of activation, or twice the largest activation seen.
double FixNSCDPolyhedra::extend_cut_ghost() {
  if (!distributed_) return 0.0;
  const double allowance = std::max(core_->options.margin + kGhostActivationOfRadius * largest_radius_,
                                    2.0 * largest_activation_);
  return needed_ghost_cutoff(allowance) - neighbor->skin;
}

void FixNSCDPolyhedra::check_ghost_cutoff(double activation) {
  largest_activation_ = std::max(largest_activation_, activation);
  const double needed = needed_ghost_cutoff(activation);
  const double held = std::min({comm->cutghost[0], comm->cutghost[1], comm->cutghost[2]});
  if (held >= needed) return;
  const bool halved = domain->triclinic == 0 && atom->radius != nullptr;
  const std::string R = wiregrain::format_number(largest_radius_), skin = wiregrain::format_number(neighbor->skin);
  wiregrain_lmp::style_error(
      error, "fix", "nscd/polyhedra", id,
      "solve distributed: step " + std::to_string(update->ntimestep) + " has an activation distance of " +
          wiregrain::format_number(activation) + " (4 h v_max + margin), so the ghost cutoff must be " +
          wiregrain::format_number(needed) +
          (halved ? " (2 x (the largest bounding radius " + R + " + the activation distance) + the neighbor skin " + skin
                  : " (2 x the largest bounding radius " + R + " + the activation distance + the neighbor skin " + skin) +
          "), but it is " + wiregrain::format_number(held) + ": set 'communicate single cutoff " +
          wiregrain::format_number(std::ceil(1.25 * needed * 100.0) / 100.0) + "' or a smaller timestep");
}

// This rank's own grains (ascending tags) and its ghost grains, with the force and torque
// averaged over the summed steps (the setup solve: the current ones) in velocity units;
// each ghost's record comes from its owner (forward communication). A non-finite state
// stops every rank with an ERROR naming the grain of the smallest tag that has one.
std::vector<wiregrain::GrainState> FixNSCDPolyhedra::rank_grains() {
  const double ftm2v = force->ftm2v;
  // after each reneighbouring, the built shapes of the grains that left this rank's own and
  // ghost grains are dropped (the library's records stay): the shapes built on a rank fall
  // with its share of the grains. No posed shape is held here: fix wire/grain poses its
  // grains again after each grain step.
  if (neighbor->lastcall != shapes_released_at_) {
    AtomVecPolyhedron::of(atom)->release_shapes_of_absent_grains();
    shapes_released_at_ = neighbor->lastcall;
  }
  rank_grains_->collect(groupbit);
  const std::vector<int> &atoms = rank_grains_->atoms();
  const int owned = rank_grains_->owned();
  std::vector<double> records(std::size_t(atom->nlocal + atom->nghost) * kStateRecord, 0.0);
  for (int k = 0; k < owned; k++) write_grain_record(atoms[k], &records[std::size_t(atoms[k]) * kStateRecord]);
  rank_grains_->copy_to_ghosts(records, kStateRecord);
  std::vector<wiregrain::GrainState> grains(atoms.size());
  double bad_tag = INFINITY, bad_what = 0.0;  // the smallest tag with a non-finite state
  for (size_t k = 0; k < atoms.size(); k++) {
    const int i = atoms[k];
    wiregrain::GrainState &g = grains[k] = grain_from_record(&records[std::size_t(i) * kStateRecord], ftm2v);
    g.position = vec3(atom->x[i]);  // (a ghost: its image's position)
    const int part = non_finite_part(g);
    if (part == 0) g.orientation.normalize();
    if (part != 0 && (int)k < owned && g.tag < bad_tag) {
      bad_tag = (double)g.tag;
      bad_what = part;
    }
  }
  double bad[2] = {bad_tag, 0.0}, smallest[2];
  MPI_Allreduce(bad, smallest, 1, MPI_DOUBLE, MPI_MIN, world);
  rank_grains_->count_reduction();
  if (std::isfinite(smallest[0])) {
    bad[1] = smallest[0] == bad_tag ? bad_what : 0.0;
    MPI_Allreduce(&bad[1], &smallest[1], 1, MPI_DOUBLE, MPI_MAX, world);
    wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id,
                               "grain " + std::to_string((long)smallest[0]) + " has a non-finite " +
                                   non_finite_words((int)smallest[1]) +
                                   " at step " + std::to_string(update->ntimestep));
  }
  return grains;
}

// Every rank's warm starts (its own pairs'), for rank 0's restart record: kImpulseRecord
// numbers per point. Collective.
std::vector<double> FixNSCDPolyhedra::all_ranks_impulses() {
  std::vector<double> mine;
  for (const wiregrain::GrainImpulseMemory::Entry &e : core_->impulses.points()) {
    const wiregrain::GrainImpulseMemory::Impulse &s = e.impulse;
    const double record[kImpulseRecord] = {double(e.pair.first), double(e.pair.second),
                                           s.position[0], s.position[1], s.position[2],
                                           s.impulse[0], s.impulse[1], s.impulse[2],
                                           s.normal[0], s.normal[1], s.normal[2],
                                           s.gap, double(static_cast<int>(s.status)),
                                           s.couple[0], s.couple[1], s.couple[2]};
    mine.insert(mine.end(), record, record + kImpulseRecord);
  }
  return wiregrain_lmp::all_gather_records(world, mine);
}

int FixNSCDPolyhedra::pack_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/) {
  return rank_grains_->pack_comm(n, list, buf);
}

void FixNSCDPolyhedra::unpack_comm(int n, int first, double *buf) { rank_grains_->unpack_comm(n, first, buf); }

int FixNSCDPolyhedra::pack_reverse_comm(int n, int first, double *buf) {
  return rank_grains_->pack_reverse_comm(n, first, buf);
}

void FixNSCDPolyhedra::unpack_reverse_comm(int n, int *list, double *buf) {
  rank_grains_->unpack_reverse_comm(n, list, buf);
}
