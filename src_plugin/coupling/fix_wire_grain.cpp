#include "fix_wire_grain.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include <Eigen/Core>

#include "atom.h"
#include "atom_vec_polyhedron.h"
#include "atom_vec_wire.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_nscd_polyhedra.h"
#include "fix_wire_contact_history.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include "core/common/errors.h"
#include "core/common/validation.h"
#include "core/contact/contact_laws.h"
#include "core/contact/contact_list.h"
#include "core/contact/held_grains.h"
#include "core/contact/wire_grain_pairs.h"
#include "bead_contact_load.h"
#include "companion_fix.h"
#include "plugin_args.h"
#include "plugin_vector.h"
#include "plugin_comm.h"

using namespace LAMMPS_NS;
using namespace FixConst;
using wiregrain_lmp::vec3;

namespace {
// keyword skin's default (measured: docs/benchmarks.md, "Wire on grains")
constexpr double kDefaultSkin = 0.1;

}  // namespace

struct FixWireGrain::CoreState {
  std::unique_ptr<wiregrain::HeldGrains> held;
  std::unique_ptr<wiregrain::WireGrainPairCache> pairs;  // keyword skin > 0
  wiregrain::GrainLoadSums sums;
  wiregrain::ContactList contacts;
  wiregrain::ShapeLibrary no_shapes;  // the library of a system without atom_style polyhedron
  // superquadric grains: each pair's closest-point solution of the last evaluation, the
  // warm start of the next (core segment_contact's SmoothContactGuess; certified there,
  // so a missing or stale guess costs time, never accuracy). Key: the segment's first
  // bead tag and the grain tag; rank-local, not in restarts (a migrated bead starts cold).
  struct PairKeyHash {
    size_t operator()(const std::pair<long, long> &k) const {
      return std::hash<long>()(k.first) * 1000003u ^ std::hash<long>()(k.second);
    }
  };
  std::unordered_map<std::pair<long, long>, wiregrain::SmoothContactGuess, PairKeyHash> guesses, next_guesses;
};

const wiregrain::ContactList &FixWireGrain::published_contacts() const { return core_->contacts; }

FixWireGrain::FixWireGrain(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg),
      core_(new CoreState),
      grain_groupbit_(0),
      wire_(NULL),
      grains_(NULL),
      nscd_(NULL),
      history_(NULL),
      grain_atoms_(atom),
      stock_grains_(false),
      held_version_(-1),
      segment_reach_(0.0),
      max_stretch_(0.5),
      skin_(kDefaultSkin),
      stretch_warned_(false),
      summed_steps_(0),
      bead_force_(NULL),
      grain_load_(NULL),
      reverse_width_(3),
      loads_by_owner_(false),
      output_(NULL),
      nmax_ghost_(0),
      stats_step_(-1),
      deepest_bead_(0),
      deepest_grain_(0),
      deepest_overlap_(0.0),
      deepest_radius_(1.0) {
  wiregrain_lmp::StyleArgs args(error, "fix", "wire/grain", id, narg, arg, 3,
                                wiregrain_lmp::concat({"max_stretch", "skin", "warm_geometry", "E_w", "nu_w", "E_p", "nu_p"},
                                                      wiregrain_lmp::friction_keywords()));
  wire_ = AtomVecWire::of(atom);
  grains_ = AtomVecPolyhedron::of(atom);
  if (!wire_ || !(grains_ || atom->sphere_flag || atom->superquadric_flag))
    args.fail("needs atom_style hybrid with wire and polyhedron (or sphere, granular, superquadric), not '" +
              std::string(atom->atom_style) + "'");
  if (args.done()) args.fail("expected the grain group after 'wire/grain'");
  grain_group_ = args.next_word();
  const int igroup = group->find(grain_group_.c_str());
  if (igroup < 0) args.fail("grain group '" + grain_group_ + "' does not exist");
  grain_groupbit_ = group->bitmask[igroup];
  friction_ = wiregrain_lmp::table1_friction();
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "max_stretch") {
      max_stretch_ = args.value_positive(key);
      continue;
    }
    if (key == "skin") {
      skin_ = args.value_nonnegative(key);
      continue;
    }
    if (key == "warm_geometry") {
      const std::string v = args.value_word(key);
      if (v != "yes" && v != "no") args.fail("value of 'warm_geometry' must be yes or no, got '" + v + "'");
      warm_geometry_ = v == "yes";
      continue;
    }
    if (wiregrain_lmp::parse_material_keyword(args, key, "E_w", "nu_w", wire_given_)) continue;
    if (wiregrain_lmp::parse_material_keyword(args, key, "E_p", "nu_p", grain_given_)) continue;
    if (!wiregrain_lmp::parse_friction_keyword(args, key, friction_)) args.unknown_keyword(key);
  }
  wiregrain_lmp::check_friction(args, friction_);
  if (skin_ > 0.0) {
    core_->pairs.reset(new wiregrain::WireGrainPairCache(skin_));
    core_->pairs->set_warm_geometry(warm_geometry_);
  }

  restart_global = 1;
  vector_flag = 1;
  size_vector = 8;
  global_freq = 1;
  extvector = 0;
  peratom_flag = 1;
  size_peratom_cols = 6;
  peratom_freq = 1;
  comm_reverse = 6;  // bead forces (3) or grain loads (6): reverse_width_
  create_attribute = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(0);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
  for (double &s : local_stats_) s = 0.0;
  for (double &s : global_stats_) s = 0.0;
  for (double &s : average_force_) s = 0.0;
  history_id_ = std::string("WIRE_GRAIN_HISTORY_") + id;
}

// after Modify::add_fix has finished with this fix, which a nested add_fix would upset
void FixWireGrain::post_create() {
  wiregrain_lmp::ensure_companion_fix(lmp, history_id_, "wire/contact/history");
}

FixWireGrain::~FixWireGrain() {
  atom->delete_callback(id, 0);
  wiregrain_lmp::delete_companion_fix(lmp, history_id_);
  memory->destroy(bead_force_);
  memory->destroy(grain_load_);
  memory->destroy(output_);
}

int FixWireGrain::setmask() { return PRE_FORCE | POST_FORCE; }

void FixWireGrain::fail(const std::string &what) { wiregrain_lmp::style_error(error, "fix", "wire/grain", id, what); }

// for a condition found on one rank only (error->one: the others need not take part)
void FixWireGrain::fail_one(const std::string &what) {
  error->one(FLERR, ("fix wire/grain (id " + std::string(id) + "): " + what).c_str());
  throw std::logic_error(what);  // not reached
}

bool FixWireGrain::is_grain(int i) const {
  if (!(atom->mask[i] & grain_groupbit_)) return false;
  return stock_grains_ ? !(atom->mask[i] & groupbit) : grain_atoms_.is_polyhedron(i);
}

// The groups (beads that are not grains; grains: the polyhedra of the grain group, all
// integrated by one fix nscd/polyhedra, or else its stock spheres), the moduli per type
// pair and the segment reach.
void FixWireGrain::init() {
  const int igroup = group->find(grain_group_.c_str());
  if (igroup < 0) fail("grain group '" + grain_group_ + "' no longer exists");
  grain_groupbit_ = group->bitmask[igroup];
  const int *mask = atom->mask, *prev = wire_->wire_prev, *next = wire_->wire_next;
  const double *rest = wire_->wire_rest, *radius = atom->radius;
  // counts (summed over the ranks), then extremes (maximised)
  enum {
    kBeads,             // wire-group atoms that are no polyhedra
    kPolyhedra,         // polyhedra of the grain group
    kPolyhedraInWire,   // polyhedra in the wire group
    kOthers,            // other atoms of the grain group (stock spheres)
    kOthersLinked,      // ... of these the linked wire beads
    kOthersInWire,      // ... and those in the wire group
    kCounts,
    kMaxRest = kCounts, // the longest rest length of the wire group
    kMaxRadius,         // its thickest bead
    kMaxGrainRadius,    // the largest bounding radius of the grain group
    kValues
  };
  double local[kValues] = {}, global[kValues];
  for (int i = 0; i < atom->nlocal; i++) {
    const bool polyhedron = grain_atoms_.is_polyhedron(i);
    if (mask[i] & groupbit) {
      if (polyhedron) local[kPolyhedraInWire] += 1.0;
      else {
        local[kBeads] += 1.0;
        local[kMaxRest] = std::max(local[kMaxRest], rest[i]);
        local[kMaxRadius] = std::max(local[kMaxRadius], radius[i]);
      }
    }
    if (!(mask[i] & grain_groupbit_)) continue;
    if (!(mask[i] & groupbit)) local[kMaxGrainRadius] = std::max(local[kMaxGrainRadius], radius[i]);
    if (polyhedron) local[kPolyhedra] += 1.0;
    else {
      local[kOthers] += 1.0;
      if (prev[i] || next[i]) local[kOthersLinked] += 1.0;
      if (mask[i] & groupbit) local[kOthersInWire] += 1.0;
    }
  }
  MPI_Allreduce(local, global, kCounts, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(local + kCounts, global + kCounts, kValues - kCounts, MPI_DOUBLE, MPI_MAX, world);
  const std::string wire_group = group->names[this->igroup];
  if (global[kBeads] == 0.0) fail("wire group '" + wire_group + "' has no wire beads");
  if (global[kPolyhedraInWire] > 0.0)
    fail("wire group '" + wire_group + "' holds " + std::to_string((long)global[kPolyhedraInWire]) +
         " grains (give the wire beads only)");
  stock_grains_ = global[kPolyhedra] == 0.0;
  // stock granular spheres or superquadrics when the grain group has no polyhedra
  if (stock_grains_ && (global[kOthers] == 0.0 || !(atom->sphere_flag || atom->superquadric_flag)))
    fail("grain group '" + grain_group_ +
         "' has no grains (polyhedra, or spheres of atom_style sphere or granular, or superquadrics, in the "
         "hybrid)");
  if (global[kOthersLinked] > 0.0)  // beads beside polyhedra would be ignored, beside spheres taken as grains
    fail("grain group '" + grain_group_ + "' holds " + std::to_string((long)global[kOthersLinked]) +
         " wire beads (give the grains only)");
  if (stock_grains_ && global[kOthersInWire] > 0.0)
    fail("wire group '" + wire_group + "' holds " + std::to_string((long)global[kOthersInWire]) +
         " grains (give the wire beads only)");
  segment_reach_ = 0.5 * (1.0 + max_stretch_) * global[kMaxRest] + global[kMaxRadius];
  const double longest_segment = global[kMaxRest];

  // the one fix nscd/polyhedra that integrates all grains of the grain group; stock
  // spheres are integrated by LIGGGHTS every step (fix nve/sphere)
  nscd_ = NULL;
  const int *shape = atom->shapetype;
  for (int k = 0; k < modify->nfix && !nscd_ && !stock_grains_; k++) {
    FixNSCDPolyhedra *candidate = dynamic_cast<FixNSCDPolyhedra *>(modify->fix[k]);
    if (!candidate) continue;
    long outside = 0, total;
    for (int i = 0; i < atom->nlocal; i++)
      if ((mask[i] & grain_groupbit_) && shape[i] >= 0 && !(mask[i] & candidate->groupbit)) outside++;
    MPI_Allreduce(&outside, &total, 1, MPI_LONG, MPI_SUM, world);
    if (total == 0) nscd_ = candidate;
  }
  if (!nscd_ && !stock_grains_)
    fail("needs a fix nscd/polyhedra that integrates all grains of group '" + grain_group_ + "'");
  loads_by_owner_ = stock_grains_ || nscd_->solves_distributed();

  const int ntypes = atom->ntypes;
  modulus_.assign((ntypes + 1) * (ntypes + 1), 0.0);
  for (int w = 1; w <= ntypes; w++) {
    const wiregrain::ElasticMaterial wire = wiregrain_lmp::wire_material_of_type(lmp, w, wire_given_, "fix", "wire/grain", id);
    for (int g = 1; g <= ntypes; g++)
      modulus_[w * (ntypes + 1) + g] = wiregrain::wire_grain_modulus(
          wire, wiregrain_lmp::grain_material_of_type(lmp, g, grain_given_, "fix", "wire/grain", id));
  }
  history_ = dynamic_cast<FixWireContactHistory *>(wiregrain_lmp::find_companion_fix(lmp, history_id_));
  comm->ghost_velocity = 1;  // the damping needs the velocity of the segment's ghost bead
  // The next bead of an owned bead must be owned or a ghost, and so must every grain its
  // segment can touch (hold_grains): a grain's surface lies within L + r_w (+ the pair
  // cache's skin) of the segment's first bead, L ≤ (1 + s) ℓ the segment's length (a
  // longer one loses its far bead: an error); LIGGGHTS' skin covers the atoms' drift
  // between neighbour lists.
  wiregrain_lmp::ensure_ghost_reach(lmp, (1.0 + max_stretch_) * longest_segment + neighbor->skin);
  wiregrain_lmp::ensure_ghost_reach(lmp, 2.0 * segment_reach_ + (core_->pairs ? skin_ : 0.0) + neighbor->skin,
                                    global[kMaxGrainRadius]);
  held_version_ = -1;
}

// Forces of the setup (after LIGGGHTS cleared them, before the other styles add theirs):
// so that the first NSCD solve, in fix nscd/polyhedra's setup, sees them whatever the
// order of the fixes. Springs are not advanced; the grains get this step's force as is.
void FixWireGrain::setup_pre_force(int /*vflag*/) {
  check_time_step();
  // each run starts with the pair cache empty (it is per rank and not in restart files:
  // a continued run then does what the straight one does; its pairs' GJK simplices are
  // warm starts)
  if (core_->pairs) core_->pairs->clear();
  hold_grains();
  evaluate(true);
}

void FixWireGrain::post_force(int /*vflag*/) {
  // (several ranks: a new neighbour list brings other ghost grains)
  if (stock_grains_ || held_version_ != nscd_->pose_version() || (comm->nprocs > 1 && neighbor->ago == 0) ||
      !segments_within_reach())
    hold_grains();
  evaluate(false);
}

// Whether every owned segment (half its length + its radius + the pair cache's skin) is
// still within the reach the grains were held with, on all ranks. Within an NSCD step of
// several wire sub-steps a pinched segment can grow beyond the room held_reach() left it
// (a quarter of its half length); the grains are then held again, wider (the same poses:
// they move only at the NSCD step's end), instead of the run stopping.
bool FixWireGrain::segments_within_reach() {
  const int *mask = atom->mask, *next = wire_->wire_next;
  const double margin = core_->pairs ? skin_ : 0.0;
  double local = 0.0, needed = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit) || !next[i]) continue;
    const int j = wire_->linked_bead(next[i]);
    if (j < 0) continue;  // reported by evaluate()
    const wiregrain::WireSegmentState segment = segment_of(i, j);
    local = std::max(local, 0.5 * (segment.x1 - segment.x0).norm() + segment.radius + margin);
  }
  MPI_Allreduce(&local, &needed, 1, MPI_DOUBLE, MPI_MAX, world);
  return needed <= core_->held->segment_reach();
}

// At the setup of each run (all ranks): the stiffest contact spring of each pair of a
// bead type and a grain type present (the longest segment, the thickest bead) on the
// lightest bead alone: the grain is held during the wire's sub-steps, and heavier.
void FixWireGrain::check_time_step() {
  const int ntypes = atom->ntypes, *type = atom->type, *mask = atom->mask;
  const int *next = wire_->wire_next, *prev = wire_->wire_prev;
  // per type: a bead of a segment present, a grain present; then the longest rest
  // length, the largest radius, −the lightest bead's mass
  std::vector<double> local(2 * ntypes + 5, 0.0), global(2 * ntypes + 5);
  const int beads = 0, grains = ntypes + 1, extremes = 2 * ntypes + 2;
  local[extremes + 2] = -INFINITY;
  for (int i = 0; i < atom->nlocal; i++) {
    if (is_grain(i)) local[grains + type[i]] = 1.0;
    if (!(mask[i] & groupbit) || (!next[i] && !prev[i])) continue;
    local[beads + type[i]] = 1.0;
    if (next[i]) local[extremes] = std::max(local[extremes], wire_->wire_rest[i]);
    local[extremes + 1] = std::max(local[extremes + 1], atom->radius[i]);
    local[extremes + 2] = std::max(local[extremes + 2], -atom->rmass[i]);
  }
  MPI_Allreduce(local.data(), global.data(), 2 * ntypes + 5, MPI_DOUBLE, MPI_MAX, world);
  std::vector<wiregrain_lmp::ContactSpring> springs;
  if (global[extremes] > 0.0 && std::isfinite(global[extremes + 2]))
    for (int w = 1; w <= ntypes; w++)
      for (int g = 1; g <= ntypes; g++) {
        if (global[beads + w] == 0.0 || global[grains + g] == 0.0) continue;
        wiregrain_lmp::ContactSpring s;
        s.effective_modulus = modulus_[w * (ntypes + 1) + g];
        s.segment_length = global[extremes];
        s.radius = global[extremes + 1];
        s.friction = friction_;
        s.mass = -global[extremes + 2];
        s.mass_name = "the lightest bead, the grain held";
        springs.push_back(s);
      }
  time_step_check_.check(lmp, "fix", "wire/grain", id, springs);
}

// The grains this rank's segments can reach, as the NSCD fix left them (stock spheres: as
// they are this step): its own and its ghost grains (LIGGGHTS' ghosts, within the reach
// init() asked for), one copy of each grain (the owned one, else the first ghost: a
// periodic image is found by HeldGrains' minimum image from any copy). No grain record
// leaves its rank.
void FixWireGrain::hold_grains() {
  // each grain once (a ghost may be a periodic image of an owned grain): its first copy in
  // LIGGGHTS' order, the grains in tag order
  const int nall = atom->nlocal + atom->nghost;
  held_copies_.clear();
  for (int i = 0; i < nall; i++)
    if (is_grain(i)) held_copies_.push_back(i);
  std::stable_sort(held_copies_.begin(), held_copies_.end(), [&](int a, int b) { return atom->tag[a] < atom->tag[b]; });
  held_copies_.erase(std::unique(held_copies_.begin(), held_copies_.end(),
                                 [&](int a, int b) { return atom->tag[a] == atom->tag[b]; }),
                     held_copies_.end());
  std::vector<wiregrain::HeldGrain> grains;
  grains.reserve(held_copies_.size());
  const bool superquadric = stock_grains_ && atom->superquadric_flag;
  for (int i : held_copies_) {
    wiregrain::HeldGrain g;
    g.tag = atom->tag[i];
    g.material = atom->type[i];
    g.position = vec3(atom->x[i]);
    g.motion.velocity = vec3(atom->v[i]);
    g.motion.angular_velocity = vec3(atom->omega[i]);
    g.motion.mass = atom->rmass[i];
    if (superquadric) {
      g.shape = wiregrain::HeldGrain::kSuperquadric;
      g.superquadric.half_axes = vec3(atom->shape[i]);
      g.superquadric.n1 = atom->blockiness[i][0];
      g.superquadric.n2 = atom->blockiness[i][1];
    } else if (stock_grains_) {
      g.shape = wiregrain::HeldGrain::kSphere;
      g.sphere_radius = atom->radius[i];
    } else {
      g.shape = atom->shapetype[i];
    }
    if (superquadric || !stock_grains_) {  // polyhedra and superquadrics carry a quaternion, spheres none
      const double *q = atom->quaternion[i];
      g.orientation = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
    } else {
      g.orientation = Eigen::Quaterniond::Identity();
    }
    grains.push_back(g);
  }
  wiregrain::PeriodicBox box;
  box.lo = vec3(domain->boxlo);
  box.hi = vec3(domain->boxhi);
  for (int d = 0; d < 3; d++) box.periodic[d] = domain->periodicity[d] != 0;
  try {
    core_->held.reset(new wiregrain::HeldGrains(grains, grains_ ? grains_->shapes() : core_->no_shapes, box,
                                                held_reach() + skin_));
    if (core_->pairs) core_->pairs->hold(*core_->held);
  } catch (const std::exception &e) {  // the same on every rank
    fail(std::string("cannot hold the grains at step ") + std::to_string(update->ntimestep) + ": " + e.what());
  }
  held_version_ = stock_grains_ ? -1 : nscd_->pose_version();
}

// The reach of the contact search for the coming NSCD step: segment_reach_ (max_stretch),
// or 1.25 ℓ/2 + r_w of the longest segment now when that is larger, i.e. once a segment is
// 20 % longer than its rest length at max_stretch 0.5 (a soft wire pinched by a grain
// can stretch a segment by more than 50 %: Table 1's segment carries one grain's weight
// at about 50 % strain), with a warning the first time. The ghost cutoff stays
// (1 + max_stretch) × rest + skin: on several ranks a longer segment loses its far bead
// and stops the run with an error naming it.
double FixWireGrain::held_reach() {
  const int *mask = atom->mask, *next = wire_->wire_next;
  double local = 0.0, needed;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit) || !next[i]) continue;
    const int j = wire_->linked_bead(next[i]);
    if (j < 0) continue;  // reported by evaluate()
    const wiregrain::WireSegmentState segment = segment_of(i, j);
    // room for the segment to grow by a quarter within the NSCD step
    local = std::max(local, 1.25 * 0.5 * (segment.x1 - segment.x0).norm() + segment.radius);
  }
  MPI_Allreduce(&local, &needed, 1, MPI_DOUBLE, MPI_MAX, world);
  if (needed <= segment_reach_) return segment_reach_;
  if (!stretch_warned_ && comm->me == 0) {
    const std::string text = "fix wire/grain (id " + std::string(id) + "): at step " +
                             std::to_string(update->ntimestep) + " a segment needs a reach of " +
                             wiregrain::format_number(needed) + " (1.25 × half its length + its radius), beyond " +
                             wiregrain::format_number(segment_reach_) + " (max_stretch = " +
                             wiregrain::format_number(max_stretch_) +
                             "): the contact search widens to follow it; on several ranks raise max_stretch";
    error->warning(FLERR, text.c_str());
  }
  stretch_warned_ = true;
  return needed;
}

// The segment from owned bead i to its next bead j (the image nearest to i).
wiregrain::WireSegmentState FixWireGrain::segment_of(int i, int j) const {
  double **x = atom->x, **v = atom->v;
  double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
  domain->minimum_image(d);
  wiregrain::WireSegmentState segment;
  segment.x0 = vec3(x[i]);
  segment.x1 = segment.x0 + vec3(d);
  segment.v0 = vec3(v[i]);
  segment.v1 = vec3(v[j]);
  segment.m0 = atom->rmass[i];
  segment.m1 = atom->rmass[j];
  segment.radius = atom->radius[i];
  return segment;
}

// Statistics and the published record of a touching pair (segment from bead i).
void FixWireGrain::record_contact(const wiregrain::WireGrainContact &c, int i, long grain_tag) {
  local_stats_[0] += 1.0;
  segment_contacts_[i]++;
  if (c.sliding) local_stats_[4] += 1.0;
  local_stats_[1] = std::max(local_stats_[1], c.overlap);
  if (c.overlap / atom->radius[i] > local_stats_[2]) {
    local_stats_[2] = c.overlap / atom->radius[i];
    deepest_bead_ = atom->tag[i];
    deepest_grain_ = grain_tag;
    deepest_overlap_ = c.overlap;
    deepest_radius_ = atom->radius[i];
  }
  wiregrain::ContactRecord record;
  record.kind = wiregrain::ContactKind::wire_grain;
  record.a = atom->tag[i];
  record.b = grain_tag;
  record.point = c.point;
  record.normal = -c.normal;  // from a (the wire) to b (the grain)
  record.force = c.force_grain;
  record.overlap = c.overlap;
  record.status = c.sliding ? wiregrain::ContactStatus::slide : wiregrain::ContactStatus::stick;
  core_->contacts.add(record);
}

// One sub-step: every owned segment against the held grains within reach. Bead forces
// go to bead_force_ (ghosts included), grain loads to `loads`.
void FixWireGrain::evaluate(bool setup) {
  const int *mask = atom->mask, *tag = atom->tag, *type = atom->type, *next = wire_->wire_next;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost, ntypes = atom->ntypes;
  if (nall > nmax_ghost_) {
    nmax_ghost_ = atom->nmax;
    memory->destroy(bead_force_);
    memory->create(bead_force_, nmax_ghost_, 3, "wire/grain:bead_force");
    memory->destroy(grain_load_);
    memory->create(grain_load_, nmax_ghost_, 6, "wire/grain:grain_load");
  }
  for (int i = 0; i < nall; i++) bead_force_[i][0] = bead_force_[i][1] = bead_force_[i][2] = 0.0;
  const wiregrain::HeldGrains &held = *core_->held;
  wiregrain::GrainLoadSums step_loads;
  wiregrain::GrainLoadSums &loads = setup ? step_loads : core_->sums;
  core_->contacts.clear();
  segment_contacts_.assign(nlocal, 0);
  for (double &s : local_stats_) s = 0.0;
  stats_step_ = -1;
  long evaluations = 0;
  const double dt = setup ? 0.0 : update->dt;  // the setup call does not advance the springs

  history_->begin_step();
  core_->next_guesses.clear();
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit) || !next[i]) continue;
    const int j = wire_->linked_bead(next[i]);
    if (j < 0)
      fail_one("bead " + std::to_string(tag[i]) + " links to bead " + std::to_string(next[i]) +
               ", which is neither owned nor a ghost here");
    const wiregrain::WireSegmentState segment = segment_of(i, j);
    // the pair's contact; returns its gap (for the pair cache: exact below exact_gap_below)
    const auto evaluate_pair = [&](int k, const Eigen::Vector3d &shift, double exact_gap_below,
                                   wiregrain::GjkSimplex *simplex) {
      evaluations++;
      const long grain_tag = held.grain(k).tag;
      const wiregrain::SoftContactLaw law = wiregrain::segment_contact_law(
          modulus_[type[i] * (ntypes + 1) + held.grain(k).material], wire_->wire_rest[i], segment.radius, friction_);
      wiregrain::TangentialHistory h;
      history_->lookup(i, (int)grain_tag, h);
      wiregrain::TangentialHistory advanced = h;
      wiregrain::SmoothContactGuess guess, *warm = nullptr;
      const std::pair<long, long> key(tag[i], grain_tag);
      if (held.grain(k).shape == wiregrain::HeldGrain::kSuperquadric) {
        const auto found = core_->guesses.find(key);
        if (found != core_->guesses.end()) guess = found->second;
        warm = &guess;
      }
      const wiregrain::WireGrainContact c =
          held.contact(k, shift, law, segment, dt, advanced, exact_gap_below, warm, simplex);
      if (warm && guess.normal.squaredNorm() > 0.0) core_->next_guesses[key] = guess;
      if (!c.touching) return -c.overlap;  // a pair apart forgets its spring
      history_->store(i, (int)grain_tag, setup ? h : advanced);
      for (int e = 0; e < 3; e++) {
        bead_force_[i][e] += c.force_bead0[e];
        bead_force_[j][e] += c.force_bead1[e];
      }
      // the beads' time-step check (contact_time_step.h): the weights of the moving
      // bodies sum to 1 with the grain held during the sub-steps, to 2 with stock grains
      if (wire_->contact_load_wanted) {
        const double moving = stock_grains_ ? 2.0 : 1.0, t = c.load_parameter;
        const wiregrain::ContactLoadEntries load = wiregrain::contact_load_entries(c.spring_dashpot, c.normal);
        wiregrain_lmp::add_bead_contact_load(wire_->contact_load[i], (1.0 - t) * moving, load);
        wiregrain_lmp::add_bead_contact_load(wire_->contact_load[j], t * moving, load);
      }
      loads.add(grain_tag, c.force_grain, c.torque_grain);
      record_contact(c, i, grain_tag);
      return -c.overlap;
    };
    try {
      if (core_->pairs)
        core_->pairs->for_each_pair(tag[i], held, segment.x0, segment.x1, segment.radius, evaluate_pair);
      else
        held.for_each_candidate(segment.x0, segment.x1, segment.radius, 0.0,
                                [&](int k, const Eigen::Vector3d &shift) { evaluate_pair(k, shift, 0.0, nullptr); });
    } catch (const std::exception &e) {  // InvalidArgument, NumericalFailure of the geometry
      fail_one("segment " + std::to_string(tag[i]) + "-" + std::to_string(next[i]) + ": " + e.what() +
               " (a segment that grew by a fifth of its reach within one NSCD step?)");
    }
  }
  history_->end_step();
  core_->guesses.swap(core_->next_guesses);
  core_->contacts.count_evaluations(evaluations);
  local_stats_[3] = double(evaluations);
  if (overlap_warnings_.due(local_stats_[2]))
    overlap_warnings_.warn(lmp, "fix", "wire/grain", id, deepest_overlap_, deepest_radius_,
                            "the segment of bead " + std::to_string(deepest_bead_) + " and grain " +
                                std::to_string(deepest_grain_),
                            "stiffer materials (E_w, E_p)");
  apply_bead_forces();

  if (setup) {
    apply_grain_loads(step_loads, 1);
    return;
  }
  summed_steps_++;
  if (stock_grains_ || nscd_->solves_at_end_of_step(update->ntimestep)) {  // the last sub-step of the NSCD step
    apply_grain_loads(core_->sums, summed_steps_);
    core_->sums.clear();
    summed_steps_ = 0;
  }
}

// The forces on ghost beads summed to their owners, then added to f.
void FixWireGrain::apply_bead_forces() {
  comm->reverse_comm_fix(this);
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    for (int e = 0; e < 3; e++) {
      atom->f[i][e] += bead_force_[i][e];
      output_[i][e] = bead_force_[i][e];
      output_[i][3 + e] = 0.0;
    }
    output_[i][3] = segment_contacts_[i];
  }
}

// The loads on the grains, added to the owned grains' force and torque: this step's
// (setup) or the sums over the NSCD step's sub-steps; the outputs show them averaged over
// `steps`. Grains distributed: each load is put on the rank's copy of its grain (owned or
// ghost) and LIGGGHTS' reverse communication adds the ghosts' loads to their owners; a
// load on a grain the rank no longer holds goes to every rank (an all-gather of those
// loads alone, when a reduction finds any). Replicated: every rank takes every rank's
// loads, added in rank order.
void FixWireGrain::apply_grain_loads(const wiregrain::GrainLoadSums &loads, int steps) {
  steps = std::max(steps, 1);
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & grain_groupbit_)
      for (int e = 0; e < 6; e++) output_[i][e] = 0.0;
  const int nlocal = atom->nlocal;
  const auto add_to_owned = [&](int i, const double *load) {
    for (int e = 0; e < 3; e++) {
      atom->f[i][e] += load[e];
      atom->torque[i][e] += load[3 + e];
      output_[i][e] = load[e] / steps;
      output_[i][3 + e] = load[3 + e] / steps;
    }
  };
  const auto flat_load = [](const wiregrain::GrainLoadSums::Load &load, double *out) {
    for (int e = 0; e < 3; e++) {
      out[e] = load.force[e];
      out[3 + e] = load.torque[e];
    }
  };
  double load[6];
  if (!loads_by_owner_) {
    wiregrain::GrainLoadSums total;
    total.add_flat(wiregrain_lmp::all_gather_records(world, loads.flatten()));
    for (double &s : average_force_) s = 0.0;
    for (const auto &entry : total.loads()) {
      for (int e = 0; e < 3; e++) average_force_[e] += entry.second.force[e] / steps;
      const int i = atom->map((int)entry.first);
      if (i < 0 || i >= nlocal) continue;
      flat_load(entry.second, load);
      add_to_owned(i, load);
    }
    return;
  }
  const int nall = nlocal + atom->nghost;
  for (int i = 0; i < nall; i++)
    for (int e = 0; e < 6; e++) grain_load_[i][e] = 0.0;
  wiregrain::GrainLoadSums absent;  // loads on grains this rank no longer holds
  double sums[4] = {0.0, 0.0, 0.0, 0.0}, totals[4];  // Σ force / steps, absent loads
  for (const auto &entry : loads.loads()) {
    for (int e = 0; e < 3; e++) sums[e] += entry.second.force[e] / steps;
    const int i = atom->map((int)entry.first);
    if (i < 0) {
      absent.add(entry.first, entry.second.force, entry.second.torque);
      sums[3] += 1.0;
      continue;
    }
    flat_load(entry.second, load);
    for (int e = 0; e < 6; e++) grain_load_[i][e] += load[e];
  }
  MPI_Allreduce(sums, totals, 4, MPI_DOUBLE, MPI_SUM, world);
  for (int e = 0; e < 3; e++) average_force_[e] = totals[e];
  reverse_width_ = 6;
  comm->reverse_comm_fix(this);
  reverse_width_ = 3;
  if (totals[3] > 0.0) {
    wiregrain::GrainLoadSums gathered;
    gathered.add_flat(wiregrain_lmp::all_gather_records(world, absent.flatten()));
    for (const auto &entry : gathered.loads()) {
      const int i = atom->map((int)entry.first);
      if (i < 0 || i >= nlocal) continue;
      flat_load(entry.second, load);
      for (int e = 0; e < 6; e++) grain_load_[i][e] += load[e];
    }
  }
  for (int i = 0; i < nlocal; i++)
    if (atom->mask[i] & grain_groupbit_) add_to_owned(i, grain_load_[i]);
}

double FixWireGrain::compute_vector(int k) {
  if (stats_step_ != update->ntimestep) {
    double sums[3] = {local_stats_[0], local_stats_[3], local_stats_[4]}, total[3], extremes[2];
    MPI_Allreduce(sums, total, 3, MPI_DOUBLE, MPI_SUM, world);
    MPI_Allreduce(local_stats_ + 1, extremes, 2, MPI_DOUBLE, MPI_MAX, world);
    global_stats_[0] = total[0];
    global_stats_[1] = extremes[0];
    global_stats_[2] = extremes[1];
    for (int e = 0; e < 3; e++) global_stats_[3 + e] = average_force_[e];
    global_stats_[6] = total[1];
    global_stats_[7] = total[2];
    stats_step_ = update->ntimestep;
  }
  return global_stats_[k];
}

int FixWireGrain::pack_reverse_comm(int n, int first, double *buf) {
  int m = 0;
  double **values = reverse_width_ == 6 ? grain_load_ : bead_force_;
  for (int i = first; i < first + n; i++)
    for (int e = 0; e < reverse_width_; e++) buf[m++] = values[i][e];
  return reverse_width_;
}

void FixWireGrain::unpack_reverse_comm(int n, int *list, double *buf) {
  int m = 0;
  double **values = reverse_width_ == 6 ? grain_load_ : bead_force_;
  for (int k = 0; k < n; k++)
    for (int e = 0; e < reverse_width_; e++) values[list[k]][e] += buf[m++];
}

void FixWireGrain::grow_arrays(int nmax) {
  memory->grow(output_, nmax, 6, "wire/grain:output");
  array_atom = output_;
}

void FixWireGrain::copy_arrays(int i, int j, int /*delflag*/) {
  for (int e = 0; e < 6; e++) output_[j][e] = output_[i][e];
}

void FixWireGrain::set_arrays(int i) {
  for (int e = 0; e < 6; e++) output_[i][e] = 0.0;
}

int FixWireGrain::pack_exchange(int i, double *buf) {
  for (int e = 0; e < 6; e++) buf[e] = output_[i][e];
  return 6;
}

int FixWireGrain::unpack_exchange(int nlocal, double *buf) {
  for (int e = 0; e < 6; e++) output_[nlocal][e] = buf[e];
  return 6;
}

// restart in the middle of an NSCD step: the sub-steps summed so far and the sums of all
// ranks (kept by rank 0 after reading; the others start from zero, the sums add up)
void FixWireGrain::write_restart(FILE *fp) {
  const std::vector<double> sums = wiregrain_lmp::all_gather_records(world, core_->sums.flatten());
  wiregrain::GrainLoadSums total;
  total.add_flat(sums);
  const std::vector<double> flat = total.flatten();
  std::vector<double> data = {double(summed_steps_), double(flat.size())};
  data.insert(data.end(), flat.begin(), flat.end());
  if (comm->me != 0) return;
  const int size = (int)(data.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(data.data(), sizeof(double), data.size(), fp);
}

void FixWireGrain::restart(char *buf) {
  const double *d = reinterpret_cast<const double *>(buf);
  summed_steps_ = (int)d[0];
  const size_t count = (size_t)d[1];
  core_->sums.clear();
  if (comm->me == 0) core_->sums.add_flat(std::vector<double>(d + 2, d + 2 + count));
}

double FixWireGrain::memory_usage() {
  return double(atom->nmax) * 6 * sizeof(double) + double(nmax_ghost_) * 9 * sizeof(double) +
         double(core_->contacts.size()) * sizeof(wiregrain::ContactRecord);
}
