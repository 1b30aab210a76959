#include "pair_wire_contact.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "atom.h"
#include "atom_vec_wire.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_wire_contact_history.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

#include "core/common/errors.h"
#include "core/common/validation.h"
#include "core/geometry/segment_distance.h"
#include "core/contact/contact_laws.h"
#include "core/contact/contact_list.h"
#include "core/contact/contact_time_step.h"
#include "core/contact/soft_contact.h"
#include "core/contact/wire_wire_contact.h"
#include "bead_contact_load.h"
#include "companion_fix.h"
#include "plugin_args.h"
#include "plugin_comm.h"
#include "plugin_material.h"

using namespace LAMMPS_NS;

namespace {
// The bead-pair cutoff must reach the far ends of two segments: allow 25 % stretch.
constexpr double kStretchAllowance = 1.25;
const char kHistoryId[] = "WIRE_CONTACT_HISTORY";

Eigen::Vector3d as_vector(const double *x) { return Eigen::Vector3d(x[0], x[1], x[2]); }

void add_force(double *f, const Eigen::Vector3d &g) {
  f[0] += g.x();
  f[1] += g.y();
  f[2] += g.z();
}

// The published record of a touching pair (kind wire_wire, a and b the tags of the
// segments' first beads).
wiregrain::ContactRecord contact_record(int tag_a, int tag_b, const wiregrain::WireWireContact &c) {
  wiregrain::ContactRecord record;
  record.kind = wiregrain::ContactKind::wire_wire;
  record.a = tag_a;
  record.b = tag_b;
  record.point = c.point;
  record.normal = c.normal;
  record.force = c.force;
  record.overlap = c.overlap;
  record.status = c.sliding ? wiregrain::ContactStatus::slide : wiregrain::ContactStatus::stick;
  return record;
}

// The largest overlap ξ / r_w of a step (r_w the mean radius of the two segments) and its
// pair, for the overlap warning.
struct LargestOverlap {
  double ratio = 0.0, overlap = 0.0, radius = 1.0;
  int a = 0, b = 0;
  void consider(double xi, double r_a, double r_b, int tag_a, int tag_b) {
    if (!(xi > ratio * 0.5 * (r_a + r_b))) return;
    ratio = xi / (0.5 * (r_a + r_b));
    overlap = xi;
    radius = 0.5 * (r_a + r_b);
    a = tag_a;
    b = tag_b;
  }
};
}  // namespace

PairWireContact::PairWireContact(LAMMPS *lmp)
    : Pair(lmp),
      coefficients_(NULL),
      effective_modulus_(NULL),
      friction_(NULL),
      contacts_(new wiregrain::ContactList),
      wire_(NULL),
      history_(NULL),
      reach_(0.0),
      segment_next_(NULL),
      segment_end_(NULL),
      segment_capacity_(0) {
  defaults_.friction = wiregrain_lmp::table1_friction();  // E, ν: per atom type unless given
  comm_reverse = 3;
}

PairWireContact::~PairWireContact() {
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(coefficients_);
    memory->destroy(effective_modulus_);
    memory->destroy(friction_);
  }
  if (history_) wiregrain_lmp::delete_companion_fix(lmp, kHistoryId);
  memory->destroy(segment_next_);
  memory->destroy(segment_end_);
  delete contacts_;
}

const wiregrain::ContactList &PairWireContact::published_contacts() const { return *contacts_; }

void PairWireContact::allocate() {
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  memory->create(coefficients_, n + 1, n + 1, "pair:coefficients");
  memory->create(effective_modulus_, n + 1, n + 1, "pair:effective_modulus");
  memory->create(friction_, n + 1, n + 1, "pair:friction");
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) setflag[i][j] = 0;
}

void PairWireContact::parse(int narg, char **arg, int first, Coefficients &c, const char *kind) {
  const bool style_line = std::string(kind) == "pair_style";
  wiregrain_lmp::StyleArgs args(error, kind, "wire/contact", "-", narg, arg, first,
                                wiregrain_lmp::concat(style_line ? wiregrain_lmp::KeywordList{"cache", "E", "nu"}
                                                                 : wiregrain_lmp::KeywordList{"E", "nu"},
                                                      wiregrain_lmp::friction_keywords()));
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "cache") {
      const std::string v = args.value_word(key);
      if (v != "yes" && v != "no") args.fail("value of 'cache' must be yes or no, got '" + v + "'");
      cache_ = v == "yes";
    } else if (!wiregrain_lmp::parse_material_keyword(args, key, "E", "nu", c.material) &&
        !wiregrain_lmp::parse_friction_keyword(args, key, c.friction))
      args.unknown_keyword(key);
  }
  wiregrain_lmp::check_friction(args, c.friction);
}

void PairWireContact::settings(int narg, char **arg) {
  parse(narg, arg, 0, defaults_, "pair_style");
  if (allocated)  // a new pair_style command resets the coefficients
    for (int i = 1; i <= atom->ntypes; i++)
      for (int j = i; j <= atom->ntypes; j++) setflag[i][j] = 0;
}

void PairWireContact::coeff(int narg, char **arg) {
  if (narg < 2) error->all(FLERR, "pair_coeff wire/contact (id -): expected: pair_coeff I J [keywords]");
  if (!allocated) allocate();
  // atom types as LIGGGHTS writes them (N, *, N*, *N, M*N), checked here for a clear message
  // a type N, or a range *, N*, *N, M*N that must select types within 1..ntypes
  const auto type_range = [&](const std::string &word, int &lo, int &hi) {
    const std::string::size_type star = word.find('*');
    const auto number = [&](const std::string &text, int otherwise) {
      if (text.empty()) return otherwise;
      char *end = NULL;
      const long t = std::strtol(text.c_str(), &end, 10);
      return end == text.c_str() || *end != '\0' || t < 1 || t > atom->ntypes ? -1 : (int)t;
    };
    lo = number(star == std::string::npos ? word : word.substr(0, star), 1);
    hi = star == std::string::npos ? lo : number(word.substr(star + 1), atom->ntypes);
    if (lo < 1 || hi < 1 || lo > hi || word.find('*', star == std::string::npos ? 0 : star + 1) != std::string::npos)
      error->all(FLERR, ("pair_coeff wire/contact (id -): atom type '" + word + "' is not one of 1.." +
                         std::to_string(atom->ntypes) + (star == std::string::npos ? "" : " (nor a range of them)"))
                            .c_str());
  };
  int ilo, ihi, jlo, jhi;
  type_range(arg[0], ilo, ihi);
  type_range(arg[1], jlo, jhi);
  Coefficients c = defaults_;
  parse(narg, arg, 2, c, "pair_coeff");
  for (int i = ilo; i <= ihi; i++)
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      coefficients_[i][j] = coefficients_[j][i] = c;
      setflag[i][j] = 1;
    }
}

void PairWireContact::init_style() {
  wire_ = AtomVecWire::of(atom);
  if (!wire_)
    error->all(FLERR, ("pair wire/contact (id -): needs atom_style wire (or hybrid with wire), not '" +
                       std::string(atom->atom_style) + "'").c_str());
  // a half list built as with newton off: every owned–ghost pair is seen by both ranks,
  // and the rank that owns the segment with the smaller tag computes it
  const int irequest = neighbor->request(this);
  neighbor->requests[irequest]->newton = 2;
  // the damping needs the velocities of ghost beads
  comm->ghost_velocity = 1;

  extent_ = gather_wire_extent();
  const double thickest = *std::max_element(extent_.radius.begin(), extent_.radius.end());
  reach_ = 2.0 * thickest + 2.0 * kStretchAllowance * extent_.rest;
  // the next bead of a ghost segment must be a ghost too
  wiregrain_lmp::ensure_ghost_reach(lmp, reach_ + kStretchAllowance * extent_.rest + neighbor->skin);

  history_ = dynamic_cast<FixWireContactHistory *>(
      wiregrain_lmp::ensure_companion_fix(lmp, kHistoryId, "wire/contact/history"));
  if (!history_) error->all(FLERR, "pair wire/contact (id -): fix WIRE_CONTACT_HISTORY has the wrong style");
}

double PairWireContact::init_one(int i, int j) {
  if (setflag[i][j] == 0) {
    coefficients_[i][j] = defaults_;
    coefficients_[j][i] = defaults_;
  }
  // each side's material: the pair's keywords, else its atom type's (plugin_material.h)
  const Coefficients &c = coefficients_[i][j];
  const wiregrain::ElasticMaterial side_i = wiregrain_lmp::wire_material_of_type(lmp, i, c.material, "pair", "wire/contact", "-");
  const wiregrain::ElasticMaterial side_j = wiregrain_lmp::wire_material_of_type(lmp, j, c.material, "pair", "wire/contact", "-");
  effective_modulus_[i][j] = effective_modulus_[j][i] = wiregrain::wire_wire_modulus(side_i, side_j);
  friction_[i][j] = friction_[j][i] = c.friction;
  // (a grain type's pairs, 0: LIGGGHTS then lists none of them; before, every pair within
  // twice the largest radius of any atom was listed, grains' too: 315–375 neighbours per
  // atom in a 20-layer column where the beads need 12)
  if (extent_.radius[i] == 0.0 || extent_.radius[j] == 0.0) return 0.0;
  return extent_.radius[i] + extent_.radius[j] + 2.0 * kStretchAllowance * extent_.rest;
}

PairWireContact::WireExtent PairWireContact::gather_wire_extent() const {
  const int ntypes = atom->ntypes, *type = atom->type;
  const int *next = wire_->wire_next, *prev = wire_->wire_prev;
  // per type the largest radius; then the longest rest length, −the lightest mass
  std::vector<double> local(ntypes + 3, 0.0), global(ntypes + 3);
  local[ntypes + 2] = -INFINITY;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!next[i] && !prev[i]) continue;  // a lone bead is no segment
    local[type[i]] = std::max(local[type[i]], atom->radius[i]);
    if (next[i]) local[ntypes + 1] = std::max(local[ntypes + 1], wire_->wire_rest[i]);
    local[ntypes + 2] = std::max(local[ntypes + 2], -atom->rmass[i]);
  }
  MPI_Allreduce(local.data(), global.data(), ntypes + 3, MPI_DOUBLE, MPI_MAX, world);
  WireExtent extent;
  extent.radius.assign(global.begin(), global.begin() + ntypes + 1);
  extent.radius[0] = 0.0;
  extent.rest = global[ntypes + 1];
  extent.lightest_mass = -global[ntypes + 2];
  return extent;
}

// Each bead's next bead and that bead's image nearest to it (segment_next_, segment_end_),
// for owned beads and ghosts, once per step.
void PairWireContact::find_segments() {
  double **x = atom->x;
  const int *tag = atom->tag, *next = wire_->wire_next;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  if (nall > segment_capacity_) {
    segment_capacity_ = nall;
    memory->destroy(segment_next_);
    memory->destroy(segment_end_);
    memory->create(segment_next_, segment_capacity_, "pair:segment_next");
    memory->create(segment_end_, segment_capacity_, 3, "pair:segment_end");
  }
  for (int i = 0; i < nall; i++) {
    segment_next_[i] = -1;
    if (!next[i]) continue;
    const int j = wire_->linked_bead(next[i]);
    if (j < 0) {
      if (i < nlocal)
        error->one(FLERR, ("pair wire/contact (id -): bead " + std::to_string(tag[i]) + " links to bead " +
                           std::to_string(next[i]) + ", which is neither owned nor a ghost here").c_str());
      segment_next_[i] = -2;  // a ghost at the edge of the ghost shell
      continue;
    }
    double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
    domain->minimum_image(d);
    segment_next_[i] = j;
    for (int k = 0; k < 3; k++) segment_end_[i][k] = x[i][k] + d[k];
  }
}

// The segment pairs (a, b) of the neighbour list this rank computes (candidates_); with
// the cache, only those that may touch before the list is built again
// (segments_may_touch with the neighbour skin). Sorted by the segments' tags (then the
// ghost's index: periodic images of one segment), not the list's bin order: the forces
// are then summed in the same order whenever the list was built (a run split into chunks
// rebuilds it at each start) and however fine the bins.
void PairWireContact::select_candidates() {
  double **x = atom->x;
  const int *tag = atom->tag, *next = wire_->wire_next;
  const double *radius = atom->radius;
  const int nlocal = atom->nlocal;
  candidates_.clear();
  candidates_built_at_ = neighbor->ncalls;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    if (segment_next_[i] == -1) continue;
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (segment_next_[j] == -1) continue;
      const int a = tag[i] < tag[j] ? i : j;
      const int b = a == i ? j : i;
      if (a >= nlocal) continue;
      if (next[a] == tag[b] || next[b] == tag[a]) continue;  // segments sharing a bead
      if (segment_next_[b] == -2)
        error->one(FLERR, ("pair wire/contact (id -): the next bead of ghost bead " + std::to_string(tag[b]) +
                           " is missing (a segment stretched beyond 25 %?)").c_str());
      if (cache_ && !wiregrain::segments_may_touch(as_vector(x[a]), as_vector(segment_end_[a]), as_vector(x[b]),
                                                   as_vector(segment_end_[b]), radius[a], radius[b], neighbor->skin))
        continue;
      candidates_.emplace_back(a, b);
    }
  }
  std::sort(candidates_.begin(), candidates_.end(), [tag](const std::pair<int, int> &p, const std::pair<int, int> &q) {
    if (tag[p.first] != tag[q.first]) return tag[p.first] < tag[q.first];
    if (tag[p.second] != tag[q.second]) return tag[p.second] < tag[q.second];
    return p.second < q.second;
  });
}

// Segment i (bead i to segment_next_[i]) as the neighbour list has it: ghosts are the
// right periodic images, the end the next bead's image nearest to bead i. Positions and
// radius (what the geometry reads); add_motion adds the beads' velocities and masses for
// a touching pair.
inline wiregrain::WireSegmentState PairWireContact::segment_state(int i) const {
  wiregrain::WireSegmentState s;
  s.x0 = as_vector(atom->x[i]);
  s.x1 = as_vector(segment_end_[i]);
  s.radius = atom->radius[i];
  return s;
}

inline void PairWireContact::add_motion(int i, wiregrain::WireSegmentState &s) const {
  const int i1 = segment_next_[i];
  s.v0 = as_vector(atom->v[i]);
  s.v1 = as_vector(atom->v[i1]);
  s.m0 = atom->rmass[i];
  s.m1 = atom->rmass[i1];
}

// The forces of contact c between segments a and b on their four beads, in the order b,
// its next bead, a, its next bead; and the contact's springs on them for the beads'
// time-step check (contact_time_step.h): four moving beads, weights summing to 2.
inline void PairWireContact::scatter(int a, int b, const wiregrain::SoftContactLaw &law,
                                     const wiregrain::WireWireContact &c) {
  double **f = atom->f;
  const int a1 = segment_next_[a], b1 = segment_next_[b];
  add_force(f[b], c.force_b0);
  add_force(f[b1], c.force_b1);
  add_force(f[a], c.force_a0);
  add_force(f[a1], c.force_a1);
  if (!wire_->contact_load_wanted) return;
  const double s = c.closest.s, t = c.closest.t;
  const wiregrain::ContactLoadEntries load =
      wiregrain::contact_load_entries(wiregrain::contact_spring_dashpot(law, c.effective_mass), c.normal);
  const std::pair<int, double> loaded[4] = {{a, 1.0 - s}, {a1, s}, {b, 1.0 - t}, {b1, t}};
  for (const auto &[bead, weight] : loaded)
    wiregrain_lmp::add_bead_contact_load(wire_->contact_load[bead], 2.0 * weight, load);
}

// Each segment pair is computed once, by the rank that owns the first bead of the segment
// with the smaller tag, which also keeps the pair's tangential spring (core/contact/
// wire_wire_contact.h). Forces go to all four beads; those on ghosts are summed to their
// owners by reverse communication (by LIGGGHTS when newton is on, here otherwise).
void PairWireContact::compute(int eflag, int vflag) {
  if (eflag || vflag) ev_setup(eflag, vflag);
  else evflag = vflag_fdotr = 0;

  double **f = atom->f;
  const int *tag = atom->tag, *type = atom->type;
  const double *rest = wire_->wire_rest;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const bool own_reverse_comm = !force->newton_pair;
  if (own_reverse_comm)
    for (int i = nlocal; i < nall; i++) f[i][0] = f[i][1] = f[i][2] = 0.0;
  find_segments();

  history_->begin_step();
  contacts_->clear();
  long evaluations = 0;  // exact segment–segment distances computed
  const double dt = update->dt;
  const bool setup = update->setupflag != 0;
  if (setup) {
    check_rest_geometry();
    check_time_step();
  }
  LargestOverlap largest;  // this rank's largest overlap / r_w of the step, and its pair

  // The candidates are chosen again at a run's setup: LIGGGHTS' Verlet::setup sorts and
  // exchanges the atoms, builds the list and then resets neighbor->ncalls to 0, so after a
  // run without a rebuild the count is the same while the local and ghost indices are not
  // (stale pairs would crash a 10 000-bead coil with the default atom sorting;
  // bench/wire_scaling.py)
  if (!cache_ || setup || neighbor->ncalls != candidates_built_at_) select_candidates();
  double **x = atom->x;
  const double *radius = atom->radius;
  for (const auto &[a, b] : candidates_) {
    // bounding spheres of the two spherocylinders first (most pairs)
    if (!wiregrain::segments_may_touch(as_vector(x[a]), as_vector(segment_end_[a]), as_vector(x[b]),
                                       as_vector(segment_end_[b]), radius[a], radius[b], 0.0))
      continue;
    evaluations++;
    wiregrain::WireSegmentState sa = segment_state(a), sb = segment_state(b);
    const wiregrain::WireWireGeometry g = wiregrain::wire_wire_geometry(sa, sb);
    if (!g.touching) continue;
    largest.consider(g.overlap, sa.radius, sb.radius, tag[a], tag[b]);
    add_motion(a, sa);
    add_motion(b, sb);
    // l_w and r_w: the means of the two segments'
    const wiregrain::SoftContactLaw law =
        wiregrain::segment_contact_law(effective_modulus_[type[a]][type[b]], 0.5 * (rest[a] + rest[b]),
                                       0.5 * (sa.radius + sb.radius), friction_[type[a]][type[b]]);
    wiregrain::TangentialHistory h;
    history_->lookup(a, tag[b], h);
    // the setup force call of a run must not advance the springs (a restart would
    // otherwise count the step twice): evaluate on a copy, keep the history
    wiregrain::TangentialHistory advanced = h;
    const wiregrain::WireWireContact c = wiregrain::load_wire_wire_pair(law, sa, sb, setup ? 0.0 : dt, advanced, g);
    history_->store(a, tag[b], setup ? h : advanced);
    scatter(a, b, law, c);
    if (eflag) eng_vdwl += c.elastic_energy;
    contacts_->add(contact_record(tag[a], tag[b], c));
  }
  history_->end_step();
  contacts_->count_evaluations(evaluations);
  if (overlap_warnings_.due(largest.ratio))
    overlap_warnings_.warn(lmp, "pair", "wire/contact", "-", largest.overlap, largest.radius,
                           "the segments of beads " + std::to_string(largest.a) + " and " + std::to_string(largest.b),
                           "a stiffer material (E)");

  if (own_reverse_comm) comm->reverse_comm_pair(this);
}

// At the setup of each run (all ranks), after find_segments: segments that share no bead
// touch (docs/design.md, section 1.2), so the segments on either side of a segment of rest
// length l, of radii r_a and r_b, overlap in the straight wire at rest when r_a + r_b > l
// (the paper's wire, r_w = 0.1 and l_w = 0.2, is at the limit). Such a wire is refused: its
// contacts would push at rest and keep it vibrating.
void PairWireContact::check_rest_geometry() {
  const int *tag = atom->tag, *prev = wire_->wire_prev, *next = wire_->wire_next;
  const double *radius = atom->radius, *rest = wire_->wire_rest;
  constexpr int kNone = std::numeric_limits<int>::max();
  int mine = kNone;  // this rank's lowest first bead of such a middle segment
  double mine_values[4] = {0.0, 0.0, 0.0, 0.0};  // its rest length, the two radii, its next bead
  for (int i = 0; i < atom->nlocal; i++) {
    const int j = segment_next_[i];
    if (j < 0 || !prev[i] || !next[j] || tag[i] >= mine) continue;
    const int p = wire_->linked_bead(prev[i]);
    if (p < 0 || !(radius[p] + radius[j] > rest[i] * (1.0 + 1e-12))) continue;
    mine = tag[i];
    mine_values[0] = rest[i];
    mine_values[1] = radius[p];
    mine_values[2] = radius[j];
    mine_values[3] = next[i];
  }
  int lowest = kNone;
  MPI_Allreduce(&mine, &lowest, 1, MPI_INT, MPI_MIN, world);
  if (lowest == kNone) return;
  double owned[4] = {0.0, 0.0, 0.0, 0.0}, values[4];  // only the owner adds its values
  if (mine == lowest)
    for (int k = 0; k < 4; k++) owned[k] = mine_values[k];
  MPI_Allreduce(owned, values, 4, MPI_DOUBLE, MPI_SUM, world);
  error->all(FLERR, ("pair wire/contact (id -): the segment from bead " + std::to_string(lowest) + " to bead " +
                     std::to_string(static_cast<long>(values[3])) + " (rest length " +
                     wiregrain::format_number(values[0]) + ") is shorter than the radii of the segments on "
                     "either side, " + wiregrain::format_number(values[1]) + " + " +
                     wiregrain::format_number(values[2]) + ": these segments, which share no bead, overlap "
                     "in the straight wire at rest; a wire's segments must be at least twice its radius long "
                     "(create_wire: segment >= 2 radius)")
                        .c_str());
}

// At the setup of each run (all ranks): the stiffest contact spring of every pair of
// wire types present, the longest segment and the thickest bead, on the reduced mass of
// two of the lightest beads (the contact point at a segment end moves with its bead).
void PairWireContact::check_time_step() {
  const WireExtent extent = gather_wire_extent();
  const int ntypes = atom->ntypes;
  const double thickest = *std::max_element(extent.radius.begin(), extent.radius.end());
  std::vector<wiregrain_lmp::ContactSpring> springs;
  if (extent.rest > 0.0 && std::isfinite(extent.lightest_mass))
    for (int i = 1; i <= ntypes; i++)
      for (int j = i; j <= ntypes; j++) {
        if (extent.radius[i] == 0.0 || extent.radius[j] == 0.0) continue;
        wiregrain_lmp::ContactSpring s;
        s.effective_modulus = effective_modulus_[i][j];
        s.segment_length = extent.rest;
        s.radius = thickest;
        s.friction = friction_[i][j];
        s.mass = wiregrain::reduced_mass(extent.lightest_mass, extent.lightest_mass);
        s.mass_name = "the reduced mass of two of the lightest beads";
        springs.push_back(s);
      }
  time_step_check_.check(lmp, "pair", "wire/contact", "-", springs);
}

// Comm::reverse_comm_pair of this LIGGGHTS expects the values per atom, not the total.
int PairWireContact::pack_reverse_comm(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++) {
    buf[m++] = atom->f[i][0];
    buf[m++] = atom->f[i][1];
    buf[m++] = atom->f[i][2];
  }
  return comm_reverse;
}

void PairWireContact::unpack_reverse_comm(int n, int *list, double *buf) {
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    atom->f[j][0] += buf[m++];
    atom->f[j][1] += buf[m++];
    atom->f[j][2] += buf[m++];
  }
}

// Restart files keep pair_style and pair_coeff: a restarted run needs neither command.
void PairWireContact::write_restart(FILE *fp) {
  if (comm->me != 0) return;
  fwrite(&defaults_, sizeof(Coefficients), 1, fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j]) fwrite(&coefficients_[i][j], sizeof(Coefficients), 1, fp);
    }
}

void PairWireContact::read_restart(FILE *fp, const int /*major*/, const int /*minor*/) {
  allocate();
  const int me = comm->me;
  if (me == 0 && fread(&defaults_, sizeof(Coefficients), 1, fp) != 1)
    error->one(FLERR, "pair wire/contact (id -): restart file is truncated");
  MPI_Bcast(&defaults_, sizeof(Coefficients), MPI_CHAR, 0, world);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0 && fread(&setflag[i][j], sizeof(int), 1, fp) != 1)
        error->one(FLERR, "pair wire/contact (id -): restart file is truncated");
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (!setflag[i][j]) continue;
      if (me == 0 && fread(&coefficients_[i][j], sizeof(Coefficients), 1, fp) != 1)
        error->one(FLERR, "pair wire/contact (id -): restart file is truncated");
      MPI_Bcast(&coefficients_[i][j], sizeof(Coefficients), MPI_CHAR, 0, world);
      coefficients_[j][i] = coefficients_[i][j];
    }
}

double PairWireContact::memory_usage() {
  const int n = atom->ntypes + 1;
  return double(n) * n * (sizeof(int) + 2 * sizeof(double) + sizeof(Coefficients) + sizeof(wiregrain::ContactFriction)) +
         double(contacts_->size()) * sizeof(wiregrain::ContactRecord) +
         double(candidates_.capacity()) * sizeof(std::pair<int, int>);
}
