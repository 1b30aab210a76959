#include "fix_nscd_polyhedra.h"
#include "fix_nscd_polyhedra_state.h"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>

#include "atom.h"
#include "atom_vec_polyhedron.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include "core/common/stable_order.h"
#include "core/common/validation.h"
#include "core/contact/contact_list.h"
#include "core/geometry/shape_library.h"
#include "core/nscd/grain_step.h"
#include "core/nscd/overlap_projection.h"
#include "core/nscd/reduced_problem_io.h"
#include "atom_kinds.h"
#include "nscd_plate.h"
#include "plugin_args.h"
#include "plugin_vector.h"
#include "plugin_comm.h"
#include "rank_grains.h"

using namespace LAMMPS_NS;
using namespace FixConst;
using wiregrain_lmp::vec3;
using namespace fix_nscd_polyhedra_layout;

namespace {

constexpr int kMaxCapWarnings = 10;

// An overlap at a step start beyond this fraction of the sweep radius r_p is named in a
// warning (check_overlap).
constexpr double kLargeOverlapOfSweep = 0.5;
// The length that stands for r_p for sharp grains (r_p = 0), as a fraction of their
// bounding radius: Table 1's ratio r_p / a_max.
constexpr double kSharpReferenceOfBounding = 0.1;

// the first number of the fix's global restart data (older builds wrote 0 or 1 there);
// -2: points without rolling couples, -3: without the pair cache, -4: without the plates;
// all still read
constexpr double kRestartLayout = -5.0;               // + the plates
constexpr double kRestartLayoutWithoutPlates = -4.0;
constexpr double kRestartLayoutWithoutCache = -3.0;
constexpr double kRestartLayoutWithoutCouples = -2.0;

}  // namespace

const wiregrain::ContactList &FixNSCDPolyhedra::published_contacts() const { return core_->published; }

namespace {

using Args = wiregrain_lmp::StyleArgs;

// The value of `keyword` as one of `choices` (word, value), else stops with e.g. "value of
// 'order' must be forward, alternating or random, got 'x'".
template <class T>
T value_choice(Args &args, const std::string &keyword, std::initializer_list<std::pair<const char *, T>> choices) {
  const std::string word = args.value_word(keyword);
  std::string names;
  size_t i = 0;
  for (const auto &choice : choices) {
    if (word == choice.first) return choice.second;
    names += std::string(i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choice.first;
    i++;
  }
  args.fail("value of '" + keyword + "' must be " + names + ", got '" + word + "'");
}

bool value_yes_no(Args &args, const std::string &keyword) {
  return value_choice<bool>(args, keyword, {{"yes", true}, {"no", false}});
}

// 'wall_friction' and 'wall_velocity' apply to the last 'wall' or 'wall_fix' given
void require_wall(const Args &args, const std::vector<wiregrain::PlaneWall> &walls,
                  std::vector<std::string> &wall_fix_ids, const std::string &keyword) {
  if (walls.empty()) args.fail("'" + keyword + "' must follow a 'wall' or 'wall_fix'");
  wall_fix_ids.resize(walls.size());
}

}  // namespace

// The keywords in the order of the keyword table of docs/commands/fix_nscd_polyhedra.md
// (the unknown-keyword message lists them so). The solver's settings go to
// options.solver, the time-stepping law's to options.law.
const wiregrain_lmp::KeywordTable<FixNSCDPolyhedra> FixNSCDPolyhedra::keywords_ = {
    {"friction", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.friction = args.value_nonnegative(key);
     }},
    {"rolling_friction", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.rolling_friction = args.value_nonnegative(key);
     }},
    {"damping", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.damping = args.value_nonnegative(key);
     }},
    {"restitution", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.law.restitution = args.value_in_range(key, 0.0, 1.0, "[0, 1]");
     }},
    {"theta", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.law.theta = args.value_in_range(key, 0.5, 1.0, "[0.5, 1]");
     }},
    {"every", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.every_ = (int)args.value_int_in_range(key, 1);
       fix.every_given_ = true;
     }},
    {"timestep", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.nscd_timestep_ = args.value_positive(key);
     }},
    {"tolerance", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.solver.tolerance = args.value_positive(key);
     }},
    {"max_iterations", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.solver.max_iterations = (int)args.value_int_in_range(key, 1);
     }},
    {"convergence", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       using Measure = wiregrain::ConvergenceMeasure;
       fix.core_->options.solver.measure = value_choice<Measure>(
           args, key,
           {{"natural_map", Measure::natural_map}, {"increment", Measure::increment},
            {"both", Measure::increment_then_natural_map}});
     }},
    {"method", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       using Method = wiregrain::SolverMethod;
       fix.core_->options.solver.method =
           value_choice<Method>(args, key, {{"gauss_seidel", Method::gauss_seidel}, {"subspace", Method::subspace}});
     }},
    {"order", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       using Order = wiregrain::SweepOrder;
       fix.core_->options.solver.order = value_choice<Order>(
           args, key,
           {{"forward", Order::forward}, {"alternating", Order::alternating}, {"random", Order::random}, {"coloured", Order::coloured}});
     }},
    {"seed", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.solver.seed = (std::uint64_t)args.value_int_in_range(key, 1, LONG_MAX);
     }},
    {"freeze", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.solver.freeze = (int)args.value_int_in_range(key, 0, INT_MAX);
     }},
    {"subspace_regularization", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       const double v = args.value_positive(key);
       if (!(v < 1.0)) args.fail("value of 'subspace_regularization' must be in (0, 1), got " + wiregrain::format_number(v));
       fix.core_->options.solver.subspace_regularization = v;
     }},
    {"subspace_closing", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       const double v = args.value_nonnegative(key);
       if (!(v <= 1.0)) args.fail("value of 'subspace_closing' must be in [0, 1], got " + wiregrain::format_number(v));
       fix.core_->options.solver.subspace_closing = v;
     }},
    {"warm_start", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.warm_start = value_yes_no(args, key);
     }},
    {"warm_geometry", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.warm_geometry = value_yes_no(args, key);
     }},
    {"overlap_recovery", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.law.overlap_recovery = args.value_in_range(key, 0.0, 1.0, "[0, 1]");
     }},
    {"overlap_speed", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.law.overlap_speed = args.value_nonnegative(key);
     }},
    {"project", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.project_tolerance_ = args.value_nonnegative(key);
     }},
    {"project_passes", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.project_passes_ = (int)args.value_int_in_range(key, 1);
     }},
    {"margin", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.margin = args.value_nonnegative(key);
     }},
    {"skin", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->pair_skin = args.value_nonnegative(key);
     }},
    {"detection", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.share_detection_ = value_choice<bool>(args, key, {{"shared", true}, {"replicated", false}});
     }},
    {"solve", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       using Choice = FixNSCDPolyhedra::SolveChoice;
       fix.solve_choice_ = value_choice<Choice>(
           args, key, {{"auto", Choice::automatic}, {"replicated", Choice::replicated}, {"distributed", Choice::distributed}});
     }},
    {"manifold", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.near_vertices = value_choice<bool>(args, key, {{"near_vertices", true}, {"closest", false}});
     }},
    {"sleep", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->options.sleep.speed = args.value_nonnegative(key);
       fix.core_->options.sleep.time = args.value_positive(key);
     }},
    {"wall", [](Args &args, FixNSCDPolyhedra &fix, const std::string &) {
       wiregrain::PlaneWall w;
       for (int d = 0; d < 3; d++) w.point[d] = args.value_double("wall");
       for (int d = 0; d < 3; d++) w.normal[d] = args.value_double("wall");
       const double n = std::sqrt(w.normal[0] * w.normal[0] + w.normal[1] * w.normal[1] + w.normal[2] * w.normal[2]);
       if (!(n > 0.0))
         args.fail("wall " + std::to_string(fix.core_->walls.size() + 1) + ": the normal (nx ny nz) must not be zero");
       for (int d = 0; d < 3; d++) w.normal[d] /= n;
       w.velocity.setZero();
       fix.core_->walls.push_back(w);
       fix.core_->own_wall_friction.push_back(false);
     }},
    {"wall_fix", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.core_->walls.push_back(wiregrain::PlaneWall());
       fix.core_->own_wall_friction.push_back(false);
       fix.wall_fix_ids_.resize(fix.core_->walls.size());
       fix.wall_fix_ids_.back() = args.value_word(key);
     }},
    {"wall_friction", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       require_wall(args, fix.core_->walls, fix.wall_fix_ids_, key);
       fix.core_->walls.back().friction = args.value_nonnegative(key);
       fix.core_->own_wall_friction.back() = true;
     }},
    {"wall_velocity", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       require_wall(args, fix.core_->walls, fix.wall_fix_ids_, key);
       const std::string &wall_fix = fix.wall_fix_ids_.back();
       if (!wall_fix.empty())
         args.fail("'wall_velocity' does not apply to 'wall_fix " + wall_fix + "' (the fix moves the plane: fix_modify " +
                   wall_fix + " velocity ...)");
       for (int d = 0; d < 3; d++) fix.core_->walls.back().velocity[d] = args.value_double(key);
     }},
    {"plate", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       require_wall(args, fix.core_->walls, fix.wall_fix_ids_, key);
       fix.core_->plates.parse(args, fix.core_->walls.size() - 1, fix.wall_fix_ids_.back());
     }},
    {"write_problems", [](Args &args, FixNSCDPolyhedra &fix, const std::string &key) {
       fix.problem_every_ = (int)args.value_int_in_range(key, 1, INT_MAX, "'write_problems' (every N steps)");
       fix.problem_file_ = args.value_word(key);
       if (fix.problem_file_.find('*') == std::string::npos)
         args.fail("the file name of 'write_problems' must contain a '*' (replaced by the step), got '" +
                   fix.problem_file_ + "'");
     }},
};

FixNSCDPolyhedra::FixNSCDPolyhedra(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg),
      core_(new CoreState),
      grains_(NULL),
      solved_once_(false),
      contact_force_(NULL),
      step_start_velocity_(NULL),
      force_sum_(NULL),
      sleep_state_(NULL) {
  Args args(error, "fix", "nscd/polyhedra", id, narg, arg, 3, keywords_.keywords());
  grains_ = AtomVecPolyhedron::of(atom);
  if (!grains_)
    args.fail("needs atom_style polyhedron (or hybrid with polyhedron), not '" + std::string(atom->atom_style) + "'");
  project_tolerance_ = kDefaultProjectTolerance;
  project_passes_ = kDefaultProjectPasses;
  keywords_.parse(args, *this);
  if (every_given_ && nscd_timestep_ > 0.0) args.fail("give 'every' or 'timestep', not both");
  if (problem_every_ > 0 && core_->options.rolling_friction > 0.0)
    args.fail("'write_problems' cannot carry 'rolling_friction' (a reduced FCLib problem has no rolling couples)");
  if (core_->options.solver.freeze > 0 && core_->options.solver.measure == wiregrain::ConvergenceMeasure::increment)
    args.fail("'freeze' needs 'convergence natural_map' or 'convergence both' (the increment does not see frozen contacts)");
  if (core_->pair_skin > 0.0) core_->pairs.reset(new wiregrain::GrainPairCache(core_->pair_skin));
  // solve auto: distributed where it gathers nothing and is faster (more than one rank;
  // docs/benchmarks.md, "Grains over ranks"), replicated on one rank and where the
  // keywords need it
  distributed_ = solve_choice_ == SolveChoice::distributed ||
                 (solve_choice_ == SolveChoice::automatic && comm->nprocs > 1 && distributed_refusal().empty());
  if (distributed_) {
    check_distributed_keywords();
    rank_grains_.reset(new wiregrain_lmp::RankGrains(lmp, this));
    comm_forward = comm_reverse = wiregrain_lmp::RankGrains::kMaxWidth;
  }
  wall_fix_ids_.resize(core_->walls.size());
  core_->walls_take_grain_friction();
  time_integrate = 1;
  restart_global = 1;
  vector_flag = 1;
  size_vector = 6 + 3 * (int)core_->walls.size() + 18 + core_->plates.output_size() + 7;
  wall_forces_.assign(3 * core_->walls.size(), 0.0);
  peratom_flag = 1;
  size_peratom_cols = 6;
  peratom_freq = 1;
  restart_peratom = 1;
  create_attribute = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(0);
  atom->add_callback(1);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
  global_freq = 1;
  extvector = 0;
  for (double &s : stats_) s = 0.0;
  timings_[0] = timings_[1] = 0.0;
}

FixNSCDPolyhedra::~FixNSCDPolyhedra() {
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  memory->destroy(contact_force_);
  memory->destroy(step_start_velocity_);
  memory->destroy(run_end_velocity_);
  memory->destroy(force_sum_);
  memory->destroy(sleep_state_);
}

void FixNSCDPolyhedra::grow_arrays(int nmax) {
  memory->grow(contact_force_, nmax, 6, "nscd/polyhedra:contact_force");
  memory->grow(step_start_velocity_, nmax, 6, "nscd/polyhedra:step_start_velocity");
  memory->grow(run_end_velocity_, nmax, 7, "nscd/polyhedra:run_end_velocity");
  memory->grow(force_sum_, nmax, 6, "nscd/polyhedra:force_sum");
  memory->grow(sleep_state_, nmax, kSleepState, "nscd/polyhedra:sleep_state");
  array_atom = contact_force_;
}

void FixNSCDPolyhedra::copy_arrays(int i, int j, int /*delflag*/) {
  for (int k = 0; k < 6; k++) {
    contact_force_[j][k] = contact_force_[i][k];
    step_start_velocity_[j][k] = step_start_velocity_[i][k];
    force_sum_[j][k] = force_sum_[i][k];
  }
  for (int k = 0; k < kSleepState; k++) sleep_state_[j][k] = sleep_state_[i][k];
  for (int k = 0; k < 7; k++) run_end_velocity_[j][k] = run_end_velocity_[i][k];
}

// a grain that never went through a solve starts from its current velocity
void FixNSCDPolyhedra::set_arrays(int i) {
  for (int d = 0; d < 3; d++) {
    contact_force_[i][d] = contact_force_[i][3 + d] = 0.0;
    force_sum_[i][d] = force_sum_[i][3 + d] = 0.0;
    step_start_velocity_[i][d] = atom->v[i][d];
    step_start_velocity_[i][3 + d] = atom->angmom[i][d];
  }
  for (int k = 0; k < kSleepState; k++) sleep_state_[i][k] = 0.0;  // awake
  for (int k = 0; k < 7; k++) run_end_velocity_[i][k] = 0.0;       // not seen at a run's end
}

// per grain (kAtomRecord): v_n, L_n (6), the force and torque summed over this step's
// sub-steps (6), the sleep state (kSleepState)
void FixNSCDPolyhedra::pack_record(int i, double *buf) const {
  for (int k = 0; k < 6; k++) buf[k] = step_start_velocity_[i][k];
  for (int k = 0; k < 6; k++) buf[6 + k] = force_sum_[i][k];
  for (int k = 0; k < kSleepState; k++) buf[12 + k] = sleep_state_[i][k];
}

void FixNSCDPolyhedra::unpack_record(int i, const double *buf) {
  for (int k = 0; k < 6; k++) step_start_velocity_[i][k] = buf[k];
  for (int k = 0; k < 6; k++) force_sum_[i][k] = buf[6 + k];
  for (int k = 0; k < 6; k++) contact_force_[i][k] = 0.0;
  for (int k = 0; k < kSleepState; k++) sleep_state_[i][k] = buf[12 + k];
}

// exchange (kExchangeRecord): the record, then the last run's end velocities (setup)
int FixNSCDPolyhedra::pack_exchange(int i, double *buf) {
  pack_record(i, buf);
  for (int k = 0; k < 7; k++) buf[kAtomRecord + k] = run_end_velocity_[i][k];
  return kExchangeRecord;
}

int FixNSCDPolyhedra::unpack_exchange(int nlocal, double *buf) {
  unpack_record(nlocal, buf);
  for (int k = 0; k < 7; k++) run_end_velocity_[nlocal][k] = buf[kAtomRecord + k];
  return kExchangeRecord;
}

// restart (kAtomRecord): the record; a run's end velocities are not in it
int FixNSCDPolyhedra::pack_restart(int i, double *buf) {
  buf[0] = kAtomRecord + 1;
  pack_record(i, buf + 1);
  return kAtomRecord + 1;
}

void FixNSCDPolyhedra::unpack_restart(int nlocal, int nth) {
  const double *record = wiregrain_lmp::fix_restart_record(atom, nlocal, nth, kAtomRecord);
  set_arrays(nlocal);  // created after read_restart: starts from its own state
  if (record) unpack_record(nlocal, record);
}

int FixNSCDPolyhedra::size_restart(int /*nlocal*/) { return kAtomRecord + 1; }

int FixNSCDPolyhedra::maxsize_restart() { return kAtomRecord + 1; }

double FixNSCDPolyhedra::memory_usage() { return double(atom->nmax) * (18 + kSleepState) * sizeof(double); }

int FixNSCDPolyhedra::setmask() { return INITIAL_INTEGRATE | FINAL_INTEGRATE; }

void FixNSCDPolyhedra::init() {
  // a bead in the group would be a grain without a shape
  wiregrain_lmp::require_no_beads(lmp, igroup, "fix", "nscd/polyhedra", id);
  wiregrain_lmp::ensure_sole_integrator(lmp, this, "fix", "nscd/polyhedra", "grains");
  // the solve's results go back to the grains by tag (atom_style polyhedron turns the map on)
  if (atom->map_style == 0)
    wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id,
                               "needs an atom map (atom_modify map array or hash before the box is defined)");
  core_->walls_take_grain_friction();
  wall_fixes_.assign(wall_fix_ids_.size(), NULL);
  for (size_t w = 0; w < wall_fix_ids_.size(); w++) {
    if (wall_fix_ids_[w].empty()) continue;
    const int ifix = modify->find_fix(wall_fix_ids_[w].c_str());
    if (ifix < 0)
      wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id,
                                 "wall_fix " + wall_fix_ids_[w] + ": no fix with this ID");
    wall_fixes_[w] = dynamic_cast<const wiregrain_lmp::MovingPlaneWall *>(modify->fix[ifix]);
    if (!wall_fixes_[w])
      wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id,
                                 "wall_fix " + wall_fix_ids_[w] + ": fix style is " + modify->fix[ifix]->style +
                                     ", not wire/wall");
  }
  core_->plates.init(lmp, id, wall_fix_ids_);
  if (nscd_timestep_ > 0.0) {
    const double ratio = nscd_timestep_ / update->dt;
    if (std::round(ratio) < 1.0 || std::abs(ratio - std::round(ratio)) > 1e-9 * ratio)
      wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id,
                                 "value of 'timestep' (" + wiregrain::format_number(nscd_timestep_) +
                                     ") must be an integer multiple of the LIGGGHTS timestep (" +
                                     wiregrain::format_number(update->dt) + ")");
    if (ratio > INT_MAX)  // the solve interval is an int step count
      wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id,
                                 "value of 'timestep' (" + wiregrain::format_number(nscd_timestep_) + ") must be at most " +
                                     std::to_string(INT_MAX) + " LIGGGHTS timesteps (" +
                                     wiregrain::format_number(update->dt) + ")");
  }
  const int missing = grains_->count_without_shape(groupbit);
  if (missing)
    wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id,
                               std::to_string(missing) + " grains have no shape (made by create_atoms? use create_grains)");
  largest_radius_ = largest_bounding_radius();
  check_periodic_box();
  if (distributed_) check_distributed_keywords();  // (fix_modify may have turned sleeping on)
}

// The simulation box for the core (core/geometry/periodic_box.h): its bounds and which
// dimensions are periodic.
wiregrain::PeriodicBox FixNSCDPolyhedra::periodic_box() const {
  wiregrain::PeriodicBox box;
  box.lo = vec3(domain->boxlo);
  box.hi = vec3(domain->boxhi);
  for (int d = 0; d < 3; d++) box.periodic[d] = domain->periodicity[d] != 0;
  return box;
}

// The largest bounding radius of the group's grains (all ranks).
double FixNSCDPolyhedra::largest_bounding_radius() const {
  double local = 0.0, largest = 0.0;
  const wiregrain::ShapeLibrary &shapes = grains_->shapes();
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && atom->shapetype[i] >= 0 && atom->shapetype[i] < shapes.size())
      local = std::max(local, shapes[atom->shapetype[i]].bounding_radius);
  MPI_Allreduce(&local, &largest, 1, MPI_DOUBLE, MPI_MAX, world);
  return largest;
}

// Periodic boundaries: every grain pair is taken in its minimum image, which must be the
// only image that can touch: each periodic length at least twice the pair reach,
// L >= 2 (2 R_max + skin + margin) (R_max the largest bounding radius of the group's
// grains; the core checks it again at every step with the activation distance, which
// grows with the grains' speeds), and the walls parallel to the periodic dimensions.
void FixNSCDPolyhedra::check_periodic_box() {
  const wiregrain::PeriodicBox box = periodic_box();
  if (!box.any()) return;
  if (domain->triclinic)
    wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id,
                               "periodic boundaries need an orthogonal box (triclinic boxes are not supported)");
  for (size_t w = 0; w < core_->walls.size(); w++) {
    const Eigen::Vector3d normal = wall_fixes_[w] ? vec3(wall_fixes_[w]->normal()) : core_->walls[w].normal;
    for (int d = 0; d < 3; d++)
      if (box.periodic[d] && normal[d] != 0.0)
        wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id,
                                   "wall " + std::to_string(w + 1) + " is not parallel to the periodic dimension " +
                                       "xyz"[d] + " (its normal has a component along " + "xyz"[d] +
                                       "): a wall must not cut a periodic dimension");
  }
  const double largest = largest_radius_;
  const double skin = core_->pairs ? core_->pair_skin : 0.0, margin = core_->options.margin;
  const double reach = 2.0 * largest + skin + margin;
  for (int d = 0; d < 3; d++)
    if (box.periodic[d] && !(box.length(d) >= 2.0 * reach))
      wiregrain_lmp::style_error(
          error, "fix", "nscd/polyhedra", id,
          std::string("the periodic box is ") + wiregrain::format_number(box.length(d)) + " long along " + "xyz"[d] +
              ", below 2 x the pair reach (2 x the largest bounding radius " + wiregrain::format_number(largest) +
              " + skin " + wiregrain::format_number(skin) + " + margin " + wiregrain::format_number(margin) +
              ") = " + wiregrain::format_number(2.0 * reach) +
              ": a grain could touch two images of another; enlarge the box along " + "xyz"[d]);
}

int FixNSCDPolyhedra::solve_interval() const {
  return nscd_timestep_ > 0.0 ? std::max(1, (int)std::lround(nscd_timestep_ / update->dt)) : every_;
}

bool FixNSCDPolyhedra::solves_at_end_of_step(bigint step) const { return step % solve_interval() == 0; }

// The first run starts with a contact solve on the setup forces (h = N dt), so that the
// first position update already uses constrained velocities; later runs continue. A
// later run whose grains the deck gave new velocities after the last solve (`velocity
// set`, `set atom`) starts like the first: the pending move of that solve, made with the
// velocities the deck replaced, is dropped and the step solved again from the new ones
// (else the grains would move one step at the new velocities unconstrained: a launched
// box stopped h v0 further than launched before the first run). Not detected after
// read_restart (the velocities of the run's end are not in the restart file).
void FixNSCDPolyhedra::setup(int /*vflag*/) {
  grains_known_ = group->count(igroup);
  if (run_end_known_ && move_pending_ && summed_steps_ == 0) {
    // grains seen at the last run's end (created ones are no change of the others), each
    // rank its own (the record migrates with the grain)
    int changed = 0, anywhere = 0;
    for (int i = 0; i < atom->nlocal && !changed; i++) {
      if (!(atom->mask[i] & groupbit) || run_end_velocity_[i][0] == 0.0) continue;
      for (int d = 0; d < 3; d++)
        if (run_end_velocity_[i][1 + d] != atom->v[i][d] || run_end_velocity_[i][4 + d] != atom->angmom[i][d])
          changed = 1;
    }
    MPI_Allreduce(&changed, &anywhere, 1, MPI_INT, MPI_MAX, world);
    if (anywhere) {
      move_pending_ = false;
      solved_once_ = false;
    }
  }
  run_end_known_ = false;
  if (!solved_once_ && solves_at_end_of_step(update->ntimestep)) solve_step();
  pose_version_++;
}

void FixNSCDPolyhedra::post_run() {
  for (int i = 0; i < atom->nlocal; i++) {
    const bool grain = (atom->mask[i] & groupbit) != 0;
    run_end_velocity_[i][0] = grain ? 1.0 : 0.0;
    for (int d = 0; d < 3; d++) {
      run_end_velocity_[i][1 + d] = grain ? atom->v[i][d] : 0.0;
      run_end_velocity_[i][4 + d] = grain ? atom->angmom[i][d] : 0.0;
    }
  }
  run_end_known_ = true;
}

// The grains move once per solve, at the start of the step after it; they are held
// in between (every N > 1). The pose update is the core's θ-method (grain_step.h).
void FixNSCDPolyhedra::initial_integrate(int /*vflag*/) {
  if (!move_pending_) return;
  move_pending_ = false;
  pose_version_++;
  const double h = last_h_;
  double **x = atom->x, **quat = atom->quaternion;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double *start = step_start_velocity_[i];
    const wiregrain::GrainPose pose = wiregrain::advance_grain_pose(
        {vec3(x[i]), Eigen::Quaterniond(quat[i][0], quat[i][1], quat[i][2], quat[i][3])}, vec3(atom->inertia[i]),
        vec3(start), vec3(atom->v[i]), vec3(start + 3), vec3(atom->angmom[i]), h, core_->options.law.theta);
    for (int d = 0; d < 3; d++) x[i][d] = pose.position[d];
    // back into the box along periodic dimensions, with the image flags (LIGGGHTS' own
    // rule, that of its reneighbouring): every position the fix writes lies in the box, so
    // a grain wraps at the step it crosses, whatever the ranks and restarts
    domain->remap(x[i], atom->image[i]);
    quat[i][0] = pose.orientation.w();
    quat[i][1] = pose.orientation.x();
    quat[i][2] = pose.orientation.y();
    quat[i][3] = pose.orientation.z();
    grains_->omega_from_angmom(i);
  }
}

// Every step adds its forces and torques to the sums; the solve sees their average over
// the steps since the last solve (paper Fig. 5: the wire's sub-steps).
void FixNSCDPolyhedra::final_integrate() {
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    for (int d = 0; d < 3; d++) {
      force_sum_[i][d] += atom->f[i][d];
      force_sum_[i][3 + d] += atom->torque[i][d];
    }
  }
  summed_steps_++;
  core_->plates.sum_wire_forces();
  if (solves_at_end_of_step(update->ntimestep)) solve_step();
}

// One grain step: replicated (every rank solves the whole problem, keeps its own grains'
// results) or distributed (each rank its own pairs, with its ghost grains; core/nscd/
// grain_step.h, GrainPartition). h = (steps summed) dt; the setup solve, with no steps
// summed, uses the setup forces and h = N dt.
void FixNSCDPolyhedra::solve_step() {
  solved_once_ = true;
  sync_wall_fixes();
  const double h = (summed_steps_ > 0 ? summed_steps_ : solve_interval()) * update->dt;
  core_->plates.prepare(lmp, core_->walls, h);
  core_->options.box = periodic_box();
  const double start = MPI_Wtime();
  const std::vector<wiregrain::GrainState> grains = distributed_ ? rank_grains() : gather_grains();
  const size_t own_count = distributed_ ? (size_t)rank_grains_->owned() : grains.size();
  bigint grain_count = (bigint)own_count;
  if (distributed_) {
    MPI_Allreduce(MPI_IN_PLACE, &grain_count, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    rank_grains_->count_reduction();
  }
  check_lost_grains(grain_count);
  wiregrain::GrainStepProblem problem;
  try {
    // replicated, detection shared: each rank computes a block of the candidate pairs, the
    // blocks are all-gathered (the same problem on every rank, to the bit)
    const wiregrain::WorkShare share = rank_share();
    wiregrain::GrainPartition partition;
    if (distributed_) {
      partition.owned = rank_grains_->owned();
      partition.exchange = rank_grains_.get();
    }
    problem = wiregrain::assemble_grain_step(grains, grains_->shapes(), core_->walls, h, core_->options, core_->impulses,
                                             core_->pairs.get(), share_detection_ && !distributed_ ? &share : nullptr,
                                             distributed_ ? &partition : nullptr);
  } catch (const std::exception &e) {  // the same on every rank (a collective step)
    solve_failed(e);
  }
  if (distributed_) check_ghost_cutoff(problem.activation);
  const double detected = MPI_Wtime();
  if (problem_every_ > 0 && update->ntimestep % problem_every_ == 0 && comm->me == 0) write_problem(problem.step);
  wiregrain::GrainStepResult result;
  try {
    result = wiregrain::solve_grain_step(problem, grains, core_->options, (std::uint64_t)update->ntimestep, core_->impulses);
  } catch (const std::exception &e) {
    solve_failed(e);
  }
  timings_[0] = detected - start;
  timings_[1] = MPI_Wtime() - detected;
  const double solved = MPI_Wtime();
  scatter_results(grains, result, own_count);
  project_overlaps(grains, problem, result);
  clocks_[0] += timings_[0];
  clocks_[1] += timings_[1];
  clocks_[2] += MPI_Wtime() - solved;
  record_stats(result);
  check_overlap(grains, result.stats.max_overlap, h);
  publish_contacts(result);
  core_->plates.advance(core_->walls, result, h, core_->options.law.theta);
  // the wall positions for the next detection (wall_fix walls: taken from their fix)
  for (wiregrain::PlaneWall &w : core_->walls) w.point += w.velocity * h;
  sync_wall_fixes();
  last_h_ = h;
  move_pending_ = true;
  summed_steps_ = 0;
  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < 6; k++) force_sum_[i][k] = 0.0;
}

// The ranks as workers of the shared detection (detection shared): each computes a block
// of the candidate pairs, the blocks are all-gathered.
wiregrain::WorkShare FixNSCDPolyhedra::rank_share() {
  wiregrain::WorkShare share;
  share.worker = comm->me;
  share.workers = comm->nprocs;
  share.all_gather = [this](const std::vector<double> &mine) { return wiregrain_lmp::all_gather_records(world, mine); };
  return share;
}

// The walls defined by a fix wire/wall (wall_fix, common/moving_plane_wall.h): its plane and
// velocity at this step.
void FixNSCDPolyhedra::sync_wall_fixes() {
  for (size_t w = 0; w < wall_fixes_.size(); w++) {
    if (!wall_fixes_[w]) continue;
    double p[3];
    wall_fixes_[w]->current_point(p);
    core_->walls[w].point = vec3(p);
    core_->walls[w].normal = vec3(wall_fixes_[w]->normal());
    core_->walls[w].velocity = vec3(wall_fixes_[w]->velocity());
  }
}

// Replicated, every rank fails alike (error->all); distributed, a rank may fail alone and
// stops the others (error->one: "ERROR on proc N: ...").
void FixNSCDPolyhedra::solve_failed(const std::exception &e) {
  const std::string what = "contact solve failed at step " + std::to_string(update->ntimestep) + ": " + e.what();
  if (distributed_) error->one(FLERR, ("fix nscd/polyhedra (id " + std::string(id) + "): " + what).c_str());
  wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id, what);
  throw;  // not reached: style_error stops the run
}

// The state record of grain i (kStateRecord numbers, fix_nscd_polyhedra_state.h), its force
// and torque averaged over the summed steps (the setup solve: the current ones).
void FixNSCDPolyhedra::write_grain_record(int i, double *r) const {
  r[0] = double(atom->tag[i]);
  r[1] = double(atom->shapetype[i]);
  for (int d = 0; d < 4; d++) r[5 + d] = atom->quaternion[i][d];
  for (int d = 0; d < 3; d++) {
    r[2 + d] = atom->x[i][d];
    r[9 + d] = atom->v[i][d];
    r[12 + d] = atom->omega[i][d];
    r[15 + d] = summed_steps_ > 0 ? force_sum_[i][d] / summed_steps_ : atom->f[i][d];
    r[18 + d] = summed_steps_ > 0 ? force_sum_[i][3 + d] / summed_steps_ : atom->torque[i][d];
    r[22 + d] = atom->inertia[i][d];
  }
  r[21] = atom->rmass[i];
}

// Every rank gathers every grain of the group, in tag order, with the force and torque
// averaged over the summed steps (the setup solve: the current ones), in velocity units
// (F ftm2v, T ftm2v). A non-finite state stops with an ERROR naming the grain.
std::vector<wiregrain::GrainState> FixNSCDPolyhedra::gather_grains() {
  const double ftm2v = force->ftm2v;
  std::vector<double> mine;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    double record[kStateRecord];
    write_grain_record(i, record);
    mine.insert(mine.end(), record, record + kStateRecord);
    mine.insert(mine.end(), sleep_state_[i], sleep_state_[i] + kSleepState);
  }
  const std::vector<double> all = wiregrain_lmp::all_gather_records(world, mine);
  // in tag order, each grain built once in place
  const std::vector<size_t> by_tag =
      wiregrain::stable_order(all.size() / kGrainRecord, [&](size_t k) { return all[k * kGrainRecord]; });
  std::vector<wiregrain::GrainState> grains(by_tag.size());
  for (size_t k = 0; k < grains.size(); k++) {
    const double *r = &all[by_tag[k] * kGrainRecord];
    wiregrain::GrainState &g = grains[k];
    g = grain_from_record(r, ftm2v);
    g.orientation.normalize();
    g.asleep = r[25] != 0.0;
    g.quiet_time = r[26];
    g.drift = vec3(r + 27);
    g.drift_angular = vec3(r + 30);
    g.load = vec3(r + 33);
    g.load_moment = vec3(r + 36);
  }
  // every rank holds the same grains, so error->all is safe here
  for (const wiregrain::GrainState &g : grains)
    if (const int part = non_finite_part(g))
      wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id,
                                 "grain " + std::to_string(g.tag) + " has a non-finite " + non_finite_words(part) +
                                     " at step " +
                                     std::to_string(update->ntimestep));
  return grains;
}

// LIGGGHTS deletes an atom that leaves a fixed boundary, and by default says nothing
// (thermo_modify lost ignore): a grain of the group missing since the run start or the
// last solve is named in a warning (the first kMaxCapWarnings times).
void FixNSCDPolyhedra::check_lost_grains(bigint now) {
  if (now < grains_known_ && comm->me == 0 && lost_warnings_ < kMaxCapWarnings) {
    lost_warnings_++;
    char line[512];
    snprintf(line, sizeof(line),
             "fix nscd/polyhedra (id %s): " BIGINT_FORMAT " grain(s) of the group lost by step " BIGINT_FORMAT
             ", " BIGINT_FORMAT " left (a grain outside a fixed boundary is deleted: close the box with a wall, or "
             "enlarge it)%s",
             id, grains_known_ - now, update->ntimestep, now,
             lost_warnings_ == kMaxCapWarnings ? "; further losses are not reported" : "");
    error->warning(FLERR, line, 0);
  }
  grains_known_ = now;
}

// An overlap at the step start beyond kLargeOverlapOfSweep r_p: the NSCD step keeps grains
// apart through gap anticipation at the current velocities, so a grain that moves about
// its sweep radius r_p in one step (h v ≳ r_p) can carry its core into a partner before
// the contact is constrained; the overlap is then pushed out over later steps
// (overlap_recovery, overlap_speed). r_p: the smallest of the group's grains (sharp grains
// without sweep: kSharpReferenceOfBounding of their bounding radius). Named in a warning
// with h and the fastest grain's speed at the step start, the first kMaxCapWarnings
// times; the solve is replicated, so rank 0 speaks for all.
void FixNSCDPolyhedra::check_overlap(const std::vector<wiregrain::GrainState> &grains, double max_overlap, double h) {
  if (overlap_warnings_ >= kMaxCapWarnings || !(max_overlap > 0.0) || grains.empty()) return;
  const wiregrain::ShapeLibrary &shapes = grains_->shapes();
  double r_p = INFINITY, v_max = 0.0;
  bool sharp = false;  // r_p stands for a sharp grain's
  for (const wiregrain::GrainState &g : grains) {
    const wiregrain::GrainShape &s = shapes[g.shape];
    const double sweep = s.shape.sweep_radius();
    const double reference = sweep > 0.0 ? sweep : kSharpReferenceOfBounding * s.bounding_radius;
    if (reference < r_p) {
      r_p = reference;
      sharp = !(sweep > 0.0);
    }
    v_max = std::max(v_max, g.velocity.norm());
  }
  if (!(max_overlap > kLargeOverlapOfSweep * r_p)) return;
  overlap_warnings_++;
  if (comm->me != 0) return;
  char line[512];
  snprintf(line, sizeof(line),
           "fix nscd/polyhedra (id %s): step " BIGINT_FORMAT " starts with an overlap of %.3g = %.3g r_p (beyond "
           "%.2g r_p, r_p = %.3g%s): the step h = %.3g moves the fastest grain (speed %.3g) h v = %.3g r_p; use a "
           "smaller timestep%s",
           id, update->ntimestep, max_overlap, max_overlap / r_p, kLargeOverlapOfSweep, r_p,
           sharp ? ", for sharp grains a tenth of the bounding radius" : "", h, v_max, h * v_max / r_p,
           overlap_warnings_ == kMaxCapWarnings ? "; further large overlaps are not reported" : "");
  error->warning(FLERR, line, 0);
}

// The own grains: new v, ω (and L), the step-start v_n, L_n (θ-method), contact force and
// torque; of grains[0, grain_count) (distributed: the own grains, not the ghosts).
void FixNSCDPolyhedra::scatter_results(const std::vector<wiregrain::GrainState> &grains,
                                       const wiregrain::GrainStepResult &result, size_t grain_count) {
  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < 6; k++) contact_force_[i][k] = 0.0;
  for (size_t k = 0; k < grain_count; k++) {
    const int i = atom->map(grains[k].tag);
    if (i < 0 || i >= atom->nlocal) continue;
    for (int d = 0; d < 3; d++) {
      contact_force_[i][d] = result.contact_forces[k][d];
      contact_force_[i][3 + d] = result.contact_torques[k][d];
      step_start_velocity_[i][d] = atom->v[i][d];
      step_start_velocity_[i][3 + d] = atom->angmom[i][d];
      atom->v[i][d] = result.velocities[k][d];
      atom->omega[i][d] = result.angular_velocities[k][d];
    }
    const bool sleeping = !result.asleep.empty();
    sleep_state_[i][0] = sleeping ? result.asleep[k] : 0.0;
    sleep_state_[i][1] = sleeping ? result.quiet_time[k] : 0.0;
    for (int d = 0; d < 3; d++) {
      sleep_state_[i][2 + d] = sleeping ? result.drift[k][d] : 0.0;
      sleep_state_[i][5 + d] = sleeping ? result.drift_angular[k][d] : 0.0;
      sleep_state_[i][8 + d] = sleeping ? result.load[k][d] : 0.0;
      sleep_state_[i][11 + d] = sleeping ? result.load_moment[k][d] : 0.0;
    }
    grains_->angmom_from_omega(i);
  }
}

// The end-of-step overlaps deeper than `project` pushed out by translating the grains, not
// by their velocities (core/nscd/overlap_projection.h). The same on every rank
// (replicated); the own grains take their translations now, before the deferred move of
// initial_integrate adds the step's (translations commute).
void FixNSCDPolyhedra::project_overlaps(const std::vector<wiregrain::GrainState> &grains,
                                        const wiregrain::GrainStepProblem &problem,
                                        const wiregrain::GrainStepResult &result) {
  projected_depth_ = 0.0;
  if (!(project_tolerance_ > 0.0)) return;
  wiregrain::OverlapProjectionStats stats;
  std::vector<Eigen::Vector3d> corrections;
  try {
    corrections = wiregrain::project_overlaps(grains, grains_->shapes(), core_->walls, problem, result,
                                              core_->options.law.theta, project_tolerance_, project_passes_,
                                              &stats);
  } catch (const std::exception &e) {
    solve_failed(e);
  }
  size_t grain_count = grains.size();
  if (distributed_) {  // each grain moved by every rank's pairs on its copies
    std::vector<double> moved(3 * grains.size());
    for (size_t k = 0; k < grains.size(); k++)
      for (int d = 0; d < 3; d++) moved[3 * k + d] = corrections[k][d];
    rank_grains_->sum_over_copies(moved, 3);
    for (size_t k = 0; k < grains.size(); k++)
      for (int d = 0; d < 3; d++) corrections[k][d] = moved[3 * k + d];
    grain_count = (size_t)rank_grains_->owned();
    double counts[2] = {double(stats.projections), stats.max_overlap_before};
    MPI_Allreduce(MPI_IN_PLACE, &counts[0], 1, MPI_DOUBLE, MPI_SUM, world);
    MPI_Allreduce(MPI_IN_PLACE, &counts[1], 1, MPI_DOUBLE, MPI_MAX, world);
    rank_grains_->count_reduction(2);
    stats.projections = (int)counts[0];
    stats.max_overlap_before = counts[1];
  }
  double **x = atom->x;
  for (size_t k = 0; k < grain_count; k++) {
    if (corrections[k].isZero(0.0)) continue;
    const int i = atom->map(grains[k].tag);
    if (i < 0 || i >= atom->nlocal) continue;
    for (int d = 0; d < 3; d++) x[i][d] += corrections[k][d];
    domain->remap(x[i], atom->image[i]);  // as after the move (initial_integrate)
  }
  projections_ += stats.projections;
  projected_depth_ = stats.max_overlap_before;
}

void FixNSCDPolyhedra::record_stats(const wiregrain::GrainStepResult &result) {
  const wiregrain::GrainStepStats &stats = result.stats;
  stats_[0] = stats.sweeps;
  solves_ += 1.0;
  sweeps_ += stats.sweeps;
  colours_ += stats.colours;
  stats_[1] = stats.residual;
  stats_[2] = stats.contact_points;
  stats_[3] = stats.max_overlap;
  largest_overlap_ = std::max(largest_overlap_, stats.max_overlap);
  stick_solves_[0] += stats.subspace_solves;
  stick_solves_[1] += stats.subspace_accepted;
  stick_solves_[2] += stats.subspace_factorizations;
  stats_[4] = stats.max_predicted_penetration;
  sleep_stats_[0] = stats.sleeping;
  sleep_stats_[1] = stats.woken;
  sleep_stats_[2] = stats.frozen_points;
  sleep_stats_[3] = stats.sleeper_checks;
  for (size_t w = 0; w < result.wall_forces.size(); w++)
    for (int d = 0; d < 3; d++) wall_forces_[3 * w + d] = result.wall_forces[w][d];
  if (!stats.hit_iteration_cap) return;
  stats_[5] += 1.0;
  // the first kMaxCapWarnings steps that hit the cap are named; the count goes on in f_ID[6]
  if (comm->me == 0 && stats_[5] == kMaxCapWarnings + 1)
    error->warning(FLERR, ("fix nscd/polyhedra (id " + std::string(id) +
                           "): further steps that hit the iteration cap are only counted (f_" + id + "[6])").c_str(), 0);
  if (comm->me == 0 && stats_[5] <= kMaxCapWarnings) {
    char line[256];
    snprintf(line, sizeof(line),
             "fix nscd/polyhedra (id %s): step " BIGINT_FORMAT " hit the iteration cap %d, residual %.3g "
             "(tolerance %.3g)",
             id, update->ntimestep, core_->options.solver.max_iterations, stats.residual, core_->options.solver.tolerance);
    error->warning(FLERR, line, 0);
  }
}

// Replicated, each contact is published by the rank that owns grain b; distributed, each
// rank holds its own pairs' contacts only and publishes them all.
void FixNSCDPolyhedra::publish_contacts(const wiregrain::GrainStepResult &result) {
  core_->published.clear();
  for (const wiregrain::ContactRecord &c : result.contacts.records()) {
    if (distributed_) {
      core_->published.add(c);
      continue;
    }
    const int i = atom->map((int)c.b);
    if (i >= 0 && i < atom->nlocal) core_->published.add(c);
  }
}

// The reduced problem (W, q, μ) of this step as a text file (core/reduced_problem_io.h);
// bench/fclib_nscd turns it into an FCLib file and solves it with Siconos and with ours.
void FixNSCDPolyhedra::write_problem(const wiregrain::NscdStep &step) {
  std::string path = problem_file_;
  path.replace(path.find('*'), 1, std::to_string(update->ntimestep));
  std::ofstream out(path);
  if (!out)  // rank 0 alone writes: error->one, not style_error's error->all
    error->one(FLERR, ("fix nscd/polyhedra (id " + std::string(id) + "): cannot open '" + path + "' for writing").c_str());
  char title[256];
  snprintf(title, sizeof(title), "fix nscd/polyhedra (id %s) step " BIGINT_FORMAT ": %d grains, %d contact points, h = %g",
           id, update->ntimestep, (int)step.bodies.size(), (int)step.contacts.size(), step.time_step);
  wiregrain::write_reduced_problem(out, wiregrain::assemble_reduced(step), title);
}

// fix_modify ID damping γ | overlap_recovery β | overlap_speed v | tolerance t | friction μ |
// sleep v t | subspace_closing κ, e.g. to relax a deposit with damping and go on without
// it, keeping the warm start (in.column: no closing stick solve in the relaxation only).
int FixNSCDPolyhedra::modify_param(int narg, char **arg) {
  if (narg < 1) return 0;
  const std::string key = arg[0];
  if (key != "damping" && key != "overlap_recovery" && key != "overlap_speed" && key != "tolerance" &&
      key != "friction" && key != "sleep" && key != "subspace_closing")
    return 0;
  const int used = key == "sleep" ? 3 : 2;
  wiregrain_lmp::StyleArgs args(error, "fix_modify", "nscd/polyhedra", id, std::min(narg, used), arg, 0);
  args.next_word();
  if (key == "sleep") {
    core_->options.sleep.speed = args.value_nonnegative(key);
    core_->options.sleep.time = args.value_positive(key);
  } else if (key == "damping") core_->options.damping = args.value_nonnegative(key);
  else if (key == "overlap_recovery") core_->options.law.overlap_recovery = args.value_in_range(key, 0.0, 1.0, "[0, 1]");
  else if (key == "overlap_speed") core_->options.law.overlap_speed = args.value_nonnegative(key);
  else if (key == "tolerance") core_->options.solver.tolerance = args.value_positive(key);
  else if (key == "subspace_closing") core_->options.solver.subspace_closing = args.value_in_range(key, 0.0, 1.0, "[0, 1]");
  else {
    core_->options.friction = args.value_nonnegative(key);
    core_->walls_take_grain_friction();
  }
  return used;
}

double FixNSCDPolyhedra::compute_vector(int k) {
  if (k < 6) return stats_[k];
  if (k < 6 + (int)wall_forces_.size()) return wall_forces_[k - 6];
  if (k < 8 + (int)wall_forces_.size()) return timings_[k - 6 - (int)wall_forces_.size()];
  if (k == 8 + (int)wall_forces_.size()) return largest_overlap_;
  if (k < 11 + (int)wall_forces_.size()) return stick_solves_[k - 9 - (int)wall_forces_.size()];
  // the overlap projection: pair corrections since the fix was made, the deepest
  // end-of-step overlap it found in the last solve (relative to the pair's size)
  if (k == 13 + (int)wall_forces_.size()) return double(projections_);
  if (k == 14 + (int)wall_forces_.size()) return projected_depth_;
  // sleeping: grains asleep after the last solve, woken in it, frozen contact points,
  // sleepers solved in its equilibrium checks
  // the stick solves' factorisations since the fix was made; last, the pair cache's kept
  // pairs skipped as still apart
  if (k == 22 + (int)wall_forces_.size()) return stick_solves_[2];
  if (k == 23 + (int)wall_forces_.size()) return core_->pairs ? double(core_->pairs->skipped()) : 0.0;
  // last, the solves and sweeps since the fix was made, and this rank's traffic in
  // `solve distributed` (rank_grains.h; 0 replicated)
  const int counts = 24 + (int)wall_forces_.size() + core_->plates.output_size();
  if (k == counts) return solves_;
  if (k == counts + 1) return sweeps_;
  if (k == counts + 5) return colours_;
  if (k == counts + 6) return distributed_ ? 1.0 : 0.0;  // the solve mode taken (solve auto)
  if (k >= counts + 2) {
    if (!rank_grains_) return 0.0;
    const wiregrain_lmp::RankGrains::Traffic &t = rank_grains_->traffic();
    return k == counts + 2 ? t.values_sent : k == counts + 3 ? t.rounds : t.reductions;
  }
  if (k >= 24 + (int)wall_forces_.size()) return core_->plates.output(k - 24 - (int)wall_forces_.size());
  if (k >= 19 + (int)wall_forces_.size()) return clocks_[k - 19 - (int)wall_forces_.size()];
  if (k >= 15 + (int)wall_forces_.size()) return sleep_stats_[k - 15 - (int)wall_forces_.size()];
  // the pair cache: detections that searched (builds) and that reused the pairs
  if (!core_->pairs) return 0.0;
  return k == 11 + (int)wall_forces_.size() ? double(core_->pairs->builds()) : double(core_->pairs->reuses());
}

// restart: a layout mark, whether a solve happened, the sub-cycle state (steps summed, a
// pending move and its h), the wall positions, the warm-start impulses (with each point's
// normal, gap and status: frozen points; and its rolling couple), the stick-solve backoff
// and the pair cache (its kept pairs' GJK simplices are warm starts: without them the
// continued run would differ from the straight one in the last bits), the plates' state
void FixNSCDPolyhedra::write_restart(FILE *fp) {
  // distributed: each rank holds its own pairs' warm starts, rank 0 writes them all
  const std::vector<double> all_impulses = distributed_ ? all_ranks_impulses() : std::vector<double>();
  if (comm->me != 0) return;
  std::vector<double> data = {kRestartLayout, solved_once_ ? 1.0 : 0.0, double(summed_steps_), move_pending_ ? 1.0 : 0.0, last_h_,
                              double(core_->walls.size())};
  for (const wiregrain::PlaneWall &w : core_->walls) data.insert(data.end(), w.point.data(), w.point.data() + 3);
  // per pair (ascending): its key, its point count, then each point
  wiregrain::GrainImpulseMemory all_ranks;
  for (size_t k = 0; k + kImpulseRecord <= all_impulses.size(); k += kImpulseRecord) {
    const double *r = &all_impulses[k];
    wiregrain::GrainImpulseMemory::Impulse point{vec3(r + 2), vec3(r + 5)};
    point.normal = vec3(r + 8);
    point.gap = r[11];
    point.status = static_cast<wiregrain::ContactStatus>((int)r[12]);
    point.couple = vec3(r + 13);
    all_ranks.add({(long)r[0], (long)r[1]}, point);
  }
  all_ranks.commit();
  const std::vector<wiregrain::GrainImpulseMemory::Entry> &points =
      distributed_ ? all_ranks.points() : core_->impulses.points();
  const size_t pairs_at = data.size();
  data.push_back(0.0);
  size_t count_at = 0;
  for (size_t e = 0; e < points.size(); e++) {
    if (e == 0 || points[e].pair != points[e - 1].pair) {
      data[pairs_at] += 1.0;
      data.push_back(points[e].pair.first);
      data.push_back(points[e].pair.second);
      count_at = data.size();
      data.push_back(0.0);
    }
    const wiregrain::GrainImpulseMemory::Impulse &s = points[e].impulse;
    data[count_at] += 1.0;
    data.insert(data.end(), s.position.data(), s.position.data() + 3);
    data.insert(data.end(), s.impulse.data(), s.impulse.data() + 3);
    data.insert(data.end(), s.normal.data(), s.normal.data() + 3);
    data.push_back(s.gap);
    data.push_back(double(static_cast<int>(s.status)));
    data.insert(data.end(), s.couple.data(), s.couple.data() + 3);
  }
  data.push_back(core_->impulses.backoff.skip);
  data.push_back(core_->impulses.backoff.wait);
  // (distributed: each rank's cache holds its own grains; a continued run builds them anew,
  // which finds the same pairs)
  const std::vector<double> cache =
      core_->pairs && !distributed_ ? core_->pairs->serialize() : std::vector<double>();
  data.push_back(double(cache.size()));  // 0: no cache
  data.insert(data.end(), cache.begin(), cache.end());
  const std::vector<double> plates = core_->plates.state();
  data.insert(data.end(), plates.begin(), plates.end());
  const int size = (int)(data.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(data.data(), sizeof(double), data.size(), fp);
}

void FixNSCDPolyhedra::restart(char *buf) {
  const double *d = reinterpret_cast<const double *>(buf);
  if (d[0] != kRestartLayout && d[0] != kRestartLayoutWithoutPlates && d[0] != kRestartLayoutWithoutCache &&
      d[0] != kRestartLayoutWithoutCouples) {  // a file of a build before sleeping
    if (comm->me == 0)
      error->warning(FLERR, ("fix nscd/polyhedra (id " + std::string(id) +
                             "): the restart file comes from an older build: the grains start without warm start")
                                .c_str(), 0);
    return;
  }
  size_t k = 1;
  solved_once_ = d[k++] != 0.0;
  summed_steps_ = (int)d[k++];
  move_pending_ = d[k++] != 0.0;
  last_h_ = d[k++];
  const size_t nwalls = (size_t)d[k++];
  for (size_t w = 0; w < nwalls; w++, k += 3)
    if (w < core_->walls.size()) core_->walls[w].point = vec3(d + k);
  const size_t point_record = d[0] == kRestartLayoutWithoutCouples ? 11 : 14;
  const size_t entries = (size_t)d[k++];
  core_->impulses.clear();
  for (size_t e = 0; e < entries; e++) {
    const wiregrain::GrainImpulseMemory::PairKey pair((long)d[k], (long)d[k + 1]);
    const size_t count = (size_t)d[k + 2];
    k += 3;
    for (size_t c = 0; c < count; c++, k += point_record) {
      wiregrain::GrainImpulseMemory::Impulse point{vec3(d + k), vec3(d + k + 3)};
      point.normal = vec3(d + k + 6);
      point.gap = d[k + 9];
      point.status = static_cast<wiregrain::ContactStatus>((int)d[k + 10]);
      if (point_record == 14) point.couple = vec3(d + k + 11);
      core_->impulses.add(pair, point);
    }
  }
  core_->impulses.commit();
  core_->impulses.backoff.skip = (int)d[k++];
  core_->impulses.backoff.wait = (int)d[k++];
  const bool has_cache = d[0] == kRestartLayout || d[0] == kRestartLayoutWithoutPlates;
  const size_t cache_numbers = has_cache ? (size_t)d[k++] : 0;
  try {
    if (cache_numbers > 0 && core_->pairs) core_->pairs->restore(d + k, cache_numbers);
    k += cache_numbers;
    if (d[0] == kRestartLayout) core_->plates.restore(d + k);
  } catch (const std::exception &e) {
    wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id, std::string("restart file: ") + e.what());
  }
}
