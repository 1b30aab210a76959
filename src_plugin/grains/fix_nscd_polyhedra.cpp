#include "fix_nscd_polyhedra.h"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <unordered_map>

#include <Eigen/Geometry>

#include "atom.h"
#include "atom_vec_polyhedron.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "update.h"

#include "core/geometry/contact_geometry.h"
#include "core/common/errors.h"
#include "core/nscd/nscd_solver.h"
#include "core/nscd/reduced_problem_io.h"
#include "core/nscd/rigid_body.h"
#include "core/geometry/shape_library.h"
#include "plugin_args.h"
#include "plugin_comm.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

constexpr int kMaxCapWarnings = 10;

// per grain in the all-gather: tag shape x(3) q(4) v(3) ω(3) F(3) T(3) m I(3)
constexpr int kGrainRecord = 25;

struct Grain {
  int tag, shape;
  Eigen::Vector3d x, v, w, f, t, inertia;
  Eigen::Quaterniond q;
  double mass;
};

Eigen::Vector3d vec(const double *p) { return Eigen::Vector3d(p[0], p[1], p[2]); }

// A uniform grid over the grains' centres, for the candidate pairs of the contact search.
class CellGrid {
 public:
  CellGrid(const std::vector<Grain> &grains, double cell) : cell_(cell) {
    for (int k = 0; k < (int)grains.size(); k++) cells_[key(index(grains[k].x))].push_back(k);
  }
  // calls visit(k) for every grain in the 27 cells around x
  template <class F>
  void around(const Eigen::Vector3d &x, F visit) const {
    const std::array<long, 3> c = index(x);
    for (long i = -1; i <= 1; i++)
      for (long j = -1; j <= 1; j++)
        for (long k = -1; k <= 1; k++) {
          const auto it = cells_.find(key({c[0] + i, c[1] + j, c[2] + k}));
          if (it != cells_.end())
            for (int g : it->second) visit(g);
        }
  }

 private:
  double cell_;
  std::unordered_map<long, std::vector<int> > cells_;
  std::array<long, 3> index(const Eigen::Vector3d &x) const {
    return {(long)std::floor(x.x() / cell_), (long)std::floor(x.y() / cell_), (long)std::floor(x.z() / cell_)};
  }
  static long key(const std::array<long, 3> &c) {
    return ((c[0] & 0x1FFFFF) << 42) | ((c[1] & 0x1FFFFF) << 21) | (c[2] & 0x1FFFFF);
  }
};

}  // namespace

FixNSCDPolyhedra::FixNSCDPolyhedra(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg),
      friction_(0.5),
      tolerance_(1e-4),
      restitution_(0.0),
      margin_(0.0),
      theta_(1.0),
      overlap_recovery_(1.0),
      overlap_speed_(0.1),
      damping_(0.0),
      max_iterations_(1000),
      order_(0),
      convergence_(0),
      seed_(1),
      warm_start_(true),
      grains_(NULL),
      solved_once_(false),
      contact_force_(NULL),
      step_start_velocity_(NULL) {
  wiregrain_lmp::StyleArgs args(error, "fix", "nscd/polyhedra", id, narg, arg, 3);
  grains_ = AtomVecPolyhedron::of(atom);
  if (!grains_)
    args.fail("needs atom_style polyhedron (or hybrid with polyhedron), not '" + std::string(atom->atom_style) + "'");
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "friction") friction_ = args.value_nonnegative(key);
    else if (key == "tolerance") tolerance_ = args.value_positive(key);
    else if (key == "max_iterations") {
      const long n = args.value_int(key);
      if (n < 1) args.fail("value of 'max_iterations' must be >= 1, got " + std::to_string(n));
      max_iterations_ = (int)n;
    } else if (key == "order") {
      const std::string v = args.value_word(key);
      if (v == "forward") order_ = 0;
      else if (v == "alternating") order_ = 1;
      else if (v == "random") order_ = 2;
      else args.fail("value of 'order' must be forward, alternating or random, got '" + v + "'");
    } else if (key == "seed") {
      seed_ = args.value_int(key);
      if (seed_ < 1) args.fail("value of 'seed' must be >= 1");
    } else if (key == "warm_start") {
      const std::string v = args.value_word(key);
      if (v != "yes" && v != "no") args.fail("value of 'warm_start' must be yes or no, got '" + v + "'");
      warm_start_ = v == "yes";
    } else if (key == "restitution") {
      restitution_ = args.value_in_range(key, 0.0, 1.0, "[0, 1]");
    } else if (key == "convergence") {
      const std::string v = args.value_word(key);
      if (v == "natural_map") convergence_ = 0;
      else if (v == "increment") convergence_ = 1;
      else if (v == "both") convergence_ = 2;
      else args.fail("value of 'convergence' must be natural_map, increment or both, got '" + v + "'");
    } else if (key == "theta") {
      theta_ = args.value_in_range(key, 0.5, 1.0, "[0.5, 1]");
    } else if (key == "overlap_recovery") {
      overlap_recovery_ = args.value_in_range(key, 0.0, 1.0, "[0, 1]");
    } else if (key == "overlap_speed") {
      overlap_speed_ = args.value_nonnegative(key);
    } else if (key == "damping") {
      damping_ = args.value_nonnegative(key);
    } else if (key == "write_problems") {
      const long every = args.value_int(key);
      if (every < 1) args.fail("value of 'write_problems' (every N steps) must be >= 1, got " + std::to_string(every));
      problem_every_ = (int)every;
      problem_file_ = args.value_word(key);
      if (problem_file_.find('*') == std::string::npos)
        args.fail("the file name of 'write_problems' must contain a '*' (replaced by the step), got '" + problem_file_ + "'");
    } else if (key == "margin") {
      margin_ = args.value_nonnegative(key);
    } else if (key == "wall") {
      Wall w;
      for (int d = 0; d < 3; d++) w.point[d] = args.value_double("wall");
      for (int d = 0; d < 3; d++) w.normal[d] = args.value_double("wall");
      const double n = std::sqrt(w.normal[0] * w.normal[0] + w.normal[1] * w.normal[1] + w.normal[2] * w.normal[2]);
      if (!(n > 0.0)) args.fail("wall " + std::to_string(walls_.size() + 1) + ": the normal (nx ny nz) must not be zero");
      for (int d = 0; d < 3; d++) {
        w.normal[d] /= n;
        w.velocity[d] = 0.0;
      }
      w.friction = friction_;
      walls_.push_back(w);
    } else if (key == "wall_friction" || key == "wall_velocity") {
      if (walls_.empty()) args.fail("'" + key + "' must follow a 'wall'");
      if (key == "wall_friction") walls_.back().friction = args.value_nonnegative(key);
      else
        for (int d = 0; d < 3; d++) walls_.back().velocity[d] = args.value_double(key);
    } else {
      args.unknown_keyword(key);
    }
  }
  time_integrate = 1;
  restart_global = 1;
  vector_flag = 1;
  size_vector = 6 + 3 * (int)walls_.size() + 3;
  wall_forces_.assign(3 * walls_.size(), 0.0);
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
}

void FixNSCDPolyhedra::grow_arrays(int nmax) {
  memory->grow(contact_force_, nmax, 6, "nscd/polyhedra:contact_force");
  memory->grow(step_start_velocity_, nmax, 6, "nscd/polyhedra:step_start_velocity");
  array_atom = contact_force_;
}

void FixNSCDPolyhedra::copy_arrays(int i, int j, int /*delflag*/) {
  for (int k = 0; k < 6; k++) {
    contact_force_[j][k] = contact_force_[i][k];
    step_start_velocity_[j][k] = step_start_velocity_[i][k];
  }
}

// a grain that never went through a solve starts from its current velocity
void FixNSCDPolyhedra::set_arrays(int i) {
  for (int d = 0; d < 3; d++) {
    contact_force_[i][d] = contact_force_[i][3 + d] = 0.0;
    step_start_velocity_[i][d] = atom->v[i][d];
    step_start_velocity_[i][3 + d] = atom->angmom[i][d];
  }
}

int FixNSCDPolyhedra::pack_exchange(int i, double *buf) {
  for (int k = 0; k < 6; k++) buf[k] = step_start_velocity_[i][k];
  return 6;
}

int FixNSCDPolyhedra::unpack_exchange(int nlocal, double *buf) {
  for (int k = 0; k < 6; k++) step_start_velocity_[nlocal][k] = buf[k];
  for (int k = 0; k < 6; k++) contact_force_[nlocal][k] = 0.0;
  return 6;
}

int FixNSCDPolyhedra::pack_restart(int i, double *buf) {
  buf[0] = 7;
  for (int k = 0; k < 6; k++) buf[k + 1] = step_start_velocity_[i][k];
  return 7;
}

void FixNSCDPolyhedra::unpack_restart(int nlocal, int nth) {
  const double *record = wiregrain_lmp::fix_restart_record(atom, nlocal, nth);
  for (int k = 0; k < 6; k++) step_start_velocity_[nlocal][k] = record[k];
}

int FixNSCDPolyhedra::size_restart(int /*nlocal*/) { return 7; }

int FixNSCDPolyhedra::maxsize_restart() { return 7; }

double FixNSCDPolyhedra::memory_usage() { return double(atom->nmax) * 12 * sizeof(double); }

int FixNSCDPolyhedra::setmask() { return INITIAL_INTEGRATE | FINAL_INTEGRATE; }

void FixNSCDPolyhedra::init() {
  wiregrain_lmp::ensure_sole_integrator(lmp, this, "fix", "nscd/polyhedra", "grains");
  const int missing = grains_->count_without_shape(groupbit);
  if (missing)
    wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id,
                               std::to_string(missing) + " grains have no shape (made by create_atoms? use create_grains)");
}

// The first run starts with a contact solve on the setup forces, so that the first
// position update already uses constrained velocities; later runs continue.
void FixNSCDPolyhedra::setup(int /*vflag*/) {
  if (!solved_once_) solve_step();
}

void FixNSCDPolyhedra::initial_integrate(int /*vflag*/) {
  const double h = update->dt;
  double **x = atom->x, **v = atom->v, **angmom = atom->angmom, **quat = atom->quaternion, **inertia = atom->inertia;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    // θ-method: x += h((1 − θ) v_n + θ v_{n+1}); the rotation with (1 − θ) L_n + θ L_{n+1}
    const double *start = step_start_velocity_[i];
    const Eigen::Vector3d velocity = (1.0 - theta_) * vec(start) + theta_ * vec(v[i]);
    const Eigen::Vector3d momentum = (1.0 - theta_) * vec(start + 3) + theta_ * vec(angmom[i]);
    for (int d = 0; d < 3; d++) x[i][d] += h * velocity[d];
    wiregrain::RigidRotation body(vec(inertia[i]), Eigen::Quaterniond(quat[i][0], quat[i][1], quat[i][2], quat[i][3]),
                                  momentum);
    body.rotate_free(h);
    const Eigen::Quaterniond &q = body.orientation();
    quat[i][0] = q.w();
    quat[i][1] = q.x();
    quat[i][2] = q.y();
    quat[i][3] = q.z();
    grains_->omega_from_angmom(i);
  }
}

void FixNSCDPolyhedra::final_integrate() { solve_step(); }

void FixNSCDPolyhedra::solve_step() {
  solved_once_ = true;
  const double h = update->dt;
  const double ftm2v = force->ftm2v;

  const double start = MPI_Wtime();
  // 1. every rank gathers every grain of the group, in tag order
  std::vector<double> mine;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double record[kGrainRecord] = {
        double(atom->tag[i]), double(atom->shapetype[i]), atom->x[i][0], atom->x[i][1], atom->x[i][2],
        atom->quaternion[i][0], atom->quaternion[i][1], atom->quaternion[i][2], atom->quaternion[i][3],
        atom->v[i][0], atom->v[i][1], atom->v[i][2], atom->omega[i][0], atom->omega[i][1], atom->omega[i][2],
        atom->f[i][0], atom->f[i][1], atom->f[i][2], atom->torque[i][0], atom->torque[i][1], atom->torque[i][2],
        atom->rmass[i], atom->inertia[i][0], atom->inertia[i][1], atom->inertia[i][2]};
    mine.insert(mine.end(), record, record + kGrainRecord);
  }
  const int nprocs = comm->nprocs;
  int my_count = (int)mine.size();
  std::vector<int> counts(nprocs), offsets(nprocs, 0);
  MPI_Allgather(&my_count, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  for (int p = 1; p < nprocs; p++) offsets[p] = offsets[p - 1] + counts[p - 1];
  std::vector<double> all(offsets[nprocs - 1] + counts[nprocs - 1]);
  MPI_Allgatherv(mine.data(), my_count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, world);
  const int n = (int)all.size() / kGrainRecord;
  std::vector<Grain> grains(n);
  for (int k = 0; k < n; k++) {
    const double *r = &all[k * kGrainRecord];
    Grain &g = grains[k];
    g.tag = (int)r[0];
    g.shape = (int)r[1];
    g.x = vec(r + 2);
    g.q = Eigen::Quaterniond(r[5], r[6], r[7], r[8]).normalized();
    g.v = vec(r + 9);
    g.w = vec(r + 12);
    g.f = vec(r + 15);
    g.t = vec(r + 18);
    g.mass = r[21];
    g.inertia = vec(r + 22);
  }
  std::sort(grains.begin(), grains.end(), [](const Grain &a, const Grain &b) { return a.tag < b.tag; });
  // every rank holds the same grains, so error->all is safe here
  for (const Grain &g : grains) {
    const char *what = !(g.x.allFinite() && g.q.coeffs().allFinite()) ? "position or orientation"
                       : !(g.v.allFinite() && g.w.allFinite())         ? "velocity"
                       : !(g.f.allFinite() && g.t.allFinite())         ? "force or torque (from another style)"
                                                                        : nullptr;
    if (what)
      wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id,
                                 "grain " + std::to_string(g.tag) + " has a non-finite " + what + " at step " +
                                     std::to_string(update->ntimestep));
  }

  // 2. bodies: free velocities after the external forces and torques of this step
  const wiregrain::ShapeLibrary &library = grains_->shapes();
  wiregrain::NscdStep step;
  step.time_step = h;
  std::vector<wiregrain::PosedShape> posed;
  posed.reserve(n);
  double largest_radius = 0.0, fastest = 0.0;
  for (const Grain &g : grains) {
    posed.emplace_back(library[g.shape].shape, g.x, g.q);
    const Eigen::Matrix3d r = g.q.toRotationMatrix();
    // optional viscous damping at rate γ, implicit: m (v_{k+1} − v_k) = h F − h γ m v_{k+1} + Hᵀ r,
    // i.e. the free velocity (v_k + h F/m)/(1 + h γ) and the mass (1 + h γ) m seen by the
    // impulses (so a grain at rest still presses with its full weight); the same for L
    const double damped = 1.0 / (1.0 + h * damping_);
    wiregrain::NscdBody b;
    b.inverse_mass = damped / g.mass;
    b.inverse_inertia = damped * (r * g.inertia.cwiseInverse().asDiagonal() * r.transpose());
    const Eigen::Matrix3d inertia_world = r * g.inertia.asDiagonal() * r.transpose();
    b.velocity_begin = g.v;
    b.angular_velocity_begin = g.w;
    b.velocity_free = damped * (g.v + h * ftm2v * g.f / g.mass);
    b.angular_velocity_free = b.inverse_inertia * (inertia_world * g.w + h * ftm2v * g.t);
    step.bodies.push_back(b);
    const double radius = library[g.shape].bounding_radius;
    largest_radius = std::max(largest_radius, radius);
    fastest = std::max(fastest, b.velocity_free.norm() + b.angular_velocity_free.norm() * radius);
  }

  // 3. contact points: every pair and wall whose gap may close within the step
  double wall_speed = 0.0;
  for (const Wall &w : walls_) wall_speed = std::max(wall_speed, vec(w.velocity).norm());
  const double activation = margin_ + 2.0 * h * (2.0 * fastest + wall_speed) + 1e-12;
  std::vector<std::pair<int, int> > keys;  // (tag_a or −wall−1, tag_b) per contact point
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Matrix3d> frames;
  const auto add_point = [&](int body_a, int body_b, const wiregrain::ContactPoint &p, double mu,
                             const Eigen::Vector3d &wall_velocity, int key_a) {
    wiregrain::NscdContact c;
    const Eigen::Matrix3d frame = wiregrain::contact_frame(p.normal);
    c.body_a = body_a;
    c.body_b = body_b;
    if (body_a >= 0) c.jacobian_a = wiregrain::contact_jacobian(frame, p.position - grains[body_a].x, -1.0);
    c.jacobian_b = wiregrain::contact_jacobian(frame, p.position - grains[body_b].x, 1.0);
    c.velocity_offset = -frame.transpose() * wall_velocity;
    c.friction = mu;
    c.gap = p.gap;
    step.contacts.push_back(c);
    keys.emplace_back(key_a, grains[body_b].tag);
    positions.push_back(p.position);
    frames.push_back(frame);
  };
  if (n > 0) {
    const CellGrid grid(grains, 2.0 * largest_radius + activation);
    for (int a = 0; a < n; a++) {
      const double ra = library[grains[a].shape].bounding_radius;
      grid.around(grains[a].x, [&](int b) {
        if (b <= a) return;
        const double reach = ra + library[grains[b].shape].bounding_radius + activation;
        if ((grains[b].x - grains[a].x).squaredNorm() >= reach * reach) return;
        const wiregrain::ContactManifold m = wiregrain::contact_manifold(posed[a], posed[b], activation);
        for (const wiregrain::ContactPoint &p : m.points)
          add_point(a, b, p, friction_, Eigen::Vector3d::Zero(), grains[a].tag);
      });
    }
  }
  for (int w = 0; w < (int)walls_.size(); w++) {
    wiregrain::Plane plane;
    plane.point = vec(walls_[w].point);
    plane.normal = vec(walls_[w].normal);
    for (int b = 0; b < n; b++) {
      if (plane.normal.dot(grains[b].x - plane.point) > library[grains[b].shape].bounding_radius + activation) continue;
      const wiregrain::ContactManifold m = wiregrain::plane_contact(plane, posed[b], activation);
      for (const wiregrain::ContactPoint &p : m.points)
        add_point(-1, b, p, walls_[w].friction, vec(walls_[w].velocity), -w - 1);
    }
  }

  // Contacts listed from the top down (descending z of the contact point, ties in detection
  // order): a forward sweep then carries the weight of a pile under gravity along −z to the
  // floor in one pass. The order changes the sweeps needed, not the solution.
  {
    std::vector<int> top_down(step.contacts.size());
    for (int c = 0; c < (int)top_down.size(); c++) top_down[c] = c;
    std::stable_sort(top_down.begin(), top_down.end(),
                     [&](int a, int b) { return positions[a].z() > positions[b].z(); });
    std::vector<wiregrain::NscdContact> contacts(top_down.size());
    std::vector<std::pair<int, int> > sorted_keys(top_down.size());
    std::vector<Eigen::Vector3d> sorted_positions(top_down.size());
    std::vector<Eigen::Matrix3d> sorted_frames(top_down.size());
    for (int c = 0; c < (int)top_down.size(); c++) {
      contacts[c] = step.contacts[top_down[c]];
      sorted_keys[c] = keys[top_down[c]];
      sorted_positions[c] = positions[top_down[c]];
      sorted_frames[c] = frames[top_down[c]];
    }
    step.contacts.swap(contacts);
    keys.swap(sorted_keys);
    positions.swap(sorted_positions);
    frames.swap(sorted_frames);
  }

  // 4. warm start: last step's impulse of the nearest point of the same pair
  const int ncontacts = (int)step.contacts.size();
  std::vector<Eigen::Vector3d> warm;
  if (warm_start_) {
    warm.assign(ncontacts, Eigen::Vector3d::Zero());
    const double near2 = std::pow(0.25 * largest_radius, 2);
    for (int c = 0; c < ncontacts; c++) {
      const auto it = impulses_.find(keys[c]);
      if (it == impulses_.end()) continue;
      double best = near2;
      for (const StoredImpulse &s : it->second) {
        const double d2 = (vec(s.position) - positions[c]).squaredNorm();
        if (d2 < best) {
          best = d2;
          warm[c] = frames[c].transpose() * vec(s.impulse);
        }
      }
    }
  }

  // 5. solve
  const double detected = MPI_Wtime();
  wiregrain::NscdOptions options;
  options.tolerance = tolerance_;
  options.max_iterations = max_iterations_;
  options.order = order_ == 0 ? wiregrain::SweepOrder::forward
                              : order_ == 1 ? wiregrain::SweepOrder::alternating : wiregrain::SweepOrder::random;
  options.seed = (std::uint64_t)seed_ + (std::uint64_t)update->ntimestep;
  options.restitution = restitution_;
  options.theta = theta_;
  options.overlap_recovery = overlap_recovery_;
  options.overlap_speed = overlap_speed_;
  options.measure = convergence_ == 0 ? wiregrain::ConvergenceMeasure::natural_map
                    : convergence_ == 1 ? wiregrain::ConvergenceMeasure::increment
                                        : wiregrain::ConvergenceMeasure::increment_then_natural_map;
  if (problem_every_ > 0 && update->ntimestep % problem_every_ == 0 && comm->me == 0) write_problem(step, options);
  wiregrain::NscdStepResult result;
  try {
    result = wiregrain::solve_nscd_step(step, options, warm);
  } catch (const std::exception &e) {  // the same on every rank (replicated solve)
    wiregrain_lmp::style_error(error, "fix", "nscd/polyhedra", id,
                               "contact solve failed at step " + std::to_string(update->ntimestep) + ": " + e.what());
  }
  timings_[0] = detected - start;
  timings_[1] = MPI_Wtime() - detected;

  // 6. keep this step's impulses (world frame) and write back the own grains
  impulses_.clear();
  for (int c = 0; c < ncontacts; c++) {
    StoredImpulse s;
    const Eigen::Vector3d world = frames[c] * result.contacts.impulses[c];
    for (int d = 0; d < 3; d++) {
      s.position[d] = positions[c][d];
      s.impulse[d] = world[d];
    }
    impulses_[keys[c]].push_back(s);
  }
  // contact forces and torques per grain, forces on the walls (impulse / h)
  std::vector<Eigen::Vector3d> force(n, Eigen::Vector3d::Zero()), torque(n, Eigen::Vector3d::Zero());
  std::fill(wall_forces_.begin(), wall_forces_.end(), 0.0);
  for (int c = 0; c < ncontacts; c++) {
    const Eigen::Vector3d on_b = frames[c] * result.contacts.impulses[c] / h;
    const wiregrain::NscdContact &con = step.contacts[c];
    force[con.body_b] += on_b;
    torque[con.body_b] += (positions[c] - grains[con.body_b].x).cross(on_b);
    if (con.body_a >= 0) {
      force[con.body_a] -= on_b;
      torque[con.body_a] -= (positions[c] - grains[con.body_a].x).cross(on_b);
    } else {
      const int w = -keys[c].first - 1;
      for (int d = 0; d < 3; d++) wall_forces_[3 * w + d] -= on_b[d];
    }
  }
  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < 6; k++) contact_force_[i][k] = 0.0;
  for (int k = 0; k < n; k++) {
    const int i = atom->map(grains[k].tag);
    if (i < 0 || i >= atom->nlocal) continue;
    for (int d = 0; d < 3; d++) {
      contact_force_[i][d] = force[k][d];
      contact_force_[i][3 + d] = torque[k][d];
    }
    for (int d = 0; d < 3; d++) {
      step_start_velocity_[i][d] = atom->v[i][d];
      step_start_velocity_[i][3 + d] = atom->angmom[i][d];
      atom->v[i][d] = result.velocities[k][d];
      atom->omega[i][d] = result.angular_velocities[k][d];
    }
    grains_->angmom_from_omega(i);
  }

  const wiregrain::NscdReport &report = result.contacts.report;
  stats_[0] = report.iterations;
  stats_[1] = report.residual;
  stats_[2] = ncontacts;
  stats_[3] = result.max_overlap;
  largest_overlap_ = std::max(largest_overlap_, result.max_overlap);
  stats_[4] = result.max_predicted_penetration;
  if (report.hit_iteration_cap) {
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
               id, update->ntimestep, max_iterations_, report.residual, tolerance_);
      error->warning(FLERR, line, 0);
    }
  }
  // the wall positions for the next detection
  for (Wall &w : walls_)
    for (int d = 0; d < 3; d++) w.point[d] += w.velocity[d] * h;
}

// The reduced problem (W, q, μ) of this step as a text file (core/reduced_problem_io.h);
// bench/fclib_nscd turns it into an FCLib file and solves it with Siconos and with ours.
void FixNSCDPolyhedra::write_problem(const wiregrain::NscdStep &step, const wiregrain::NscdOptions &options) {
  std::string path = problem_file_;
  path.replace(path.find('*'), 1, std::to_string(update->ntimestep));
  std::ofstream out(path);
  if (!out)  // rank 0 alone writes: error->one, not style_error's error->all
    error->one(FLERR, ("fix nscd/polyhedra (id " + std::string(id) + "): cannot open '" + path + "' for writing").c_str());
  char title[256];
  snprintf(title, sizeof(title), "fix nscd/polyhedra (id %s) step " BIGINT_FORMAT ": %d grains, %d contact points, h = %g",
           id, update->ntimestep, (int)step.bodies.size(), (int)step.contacts.size(), step.time_step);
  wiregrain::write_reduced_problem(out, wiregrain::assemble_reduced(step, options), title);
}

// fix_modify ID damping γ | overlap_recovery β | overlap_speed v | tolerance t | friction μ,
// e.g. to relax a deposit with damping and go on without it, keeping the warm start.
int FixNSCDPolyhedra::modify_param(int narg, char **arg) {
  if (narg < 1) return 0;
  const std::string key = arg[0];
  if (key != "damping" && key != "overlap_recovery" && key != "overlap_speed" && key != "tolerance" &&
      key != "friction")
    return 0;
  wiregrain_lmp::StyleArgs args(error, "fix_modify", "nscd/polyhedra", id, std::min(narg, 2), arg, 0);
  args.next_keyword();
  if (key == "damping") damping_ = args.value_nonnegative(key);
  else if (key == "overlap_recovery") overlap_recovery_ = args.value_in_range(key, 0.0, 1.0, "[0, 1]");
  else if (key == "overlap_speed") overlap_speed_ = args.value_nonnegative(key);
  else if (key == "tolerance") tolerance_ = args.value_positive(key);
  else friction_ = args.value_nonnegative(key);
  return 2;
}

double FixNSCDPolyhedra::compute_vector(int k) {
  if (k < 6) return stats_[k];
  if (k < 6 + (int)wall_forces_.size()) return wall_forces_[k - 6];
  if (k < 8 + (int)wall_forces_.size()) return timings_[k - 6 - (int)wall_forces_.size()];
  return largest_overlap_;
}

// restart: whether a solve happened, the wall positions and the warm-start impulses
void FixNSCDPolyhedra::write_restart(FILE *fp) {
  if (comm->me != 0) return;
  std::vector<double> data = {solved_once_ ? 1.0 : 0.0, double(walls_.size())};
  for (const Wall &w : walls_) data.insert(data.end(), w.point, w.point + 3);
  data.push_back(double(impulses_.size()));
  for (const auto &entry : impulses_) {
    data.push_back(entry.first.first);
    data.push_back(entry.first.second);
    data.push_back(double(entry.second.size()));
    for (const StoredImpulse &s : entry.second) {
      data.insert(data.end(), s.position, s.position + 3);
      data.insert(data.end(), s.impulse, s.impulse + 3);
    }
  }
  const int size = (int)(data.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(data.data(), sizeof(double), data.size(), fp);
}

void FixNSCDPolyhedra::restart(char *buf) {
  const double *d = reinterpret_cast<const double *>(buf);
  size_t k = 0;
  solved_once_ = d[k++] != 0.0;
  const size_t nwalls = (size_t)d[k++];
  for (size_t w = 0; w < nwalls; w++, k += 3)
    if (w < walls_.size())
      for (int c = 0; c < 3; c++) walls_[w].point[c] = d[k + c];
  const size_t entries = (size_t)d[k++];
  impulses_.clear();
  for (size_t e = 0; e < entries; e++) {
    const std::pair<int, int> key((int)d[k], (int)d[k + 1]);
    const size_t count = (size_t)d[k + 2];
    k += 3;
    std::vector<StoredImpulse> &list = impulses_[key];
    for (size_t c = 0; c < count; c++, k += 6) {
      StoredImpulse s;
      std::memcpy(s.position, d + k, 3 * sizeof(double));
      std::memcpy(s.impulse, d + k + 3, 3 * sizeof(double));
      list.push_back(s);
    }
  }
}
