#include "create_grains.h"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

#include "atom.h"
#include "atom_vec.h"
#include "atom_vec_polyhedron.h"
#include "atom_vec_wire.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "modify.h"
#include "region.h"

#include "core/geometry/broad_phase.h"
#include "core/geometry/core_distance.h"
#include "core/geometry/posed_shape.h"
#include "core/geometry/segment_contact.h"
#include "core/geometry/convex_shape.h"
#include "core/common/errors.h"
#include "core/geometry/shape_library.h"
#include "core/geometry/superquadric.h"
#include "core/common/validation.h"
#ifdef SUPERQUADRIC_ACTIVE_FLAG
#include "math_extra_liggghts_superquadric.h"
#endif
#include "plugin_args.h"
#include "plugin_comm.h"
#include "plugin_create.h"

using namespace LAMMPS_NS;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Uniform double in [0, 1) from the top 53 bits of one engine output (platform-independent,
// unlike std::uniform_real_distribution; the same rule as core/convex_shape.cpp).
double uniform01(std::mt19937_64 &rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// Uniformly distributed unit quaternion (Shoemake, Graphics Gems III, 1992).
Eigen::Quaterniond random_orientation(std::mt19937_64 &rng) {
  const double u1 = uniform01(rng), u2 = uniform01(rng), u3 = uniform01(rng);
  const double s1 = std::sqrt(1.0 - u1), s2 = std::sqrt(u1);
  const double t1 = 2.0 * kPi * u2, t2 = 2.0 * kPi * u3;
  return Eigen::Quaterniond(s2 * std::cos(t2), s1 * std::sin(t1), s1 * std::cos(t1), s2 * std::sin(t2));
}

// Something a new grain must not overlap: a grain (library shape, posed), a sphere (an
// atom of another style in atom_style hybrid, e.g. a wire bead) or a wire segment (the
// spherocylinder between a bead and its next bead).
constexpr int kSphere = -1, kSegment = -2;
struct Body {
  Eigen::Vector3d x;   // centre of mass, sphere centre, segment midpoint
  double bound = 0.0;  // bounding radius about x
  double sweep = 0.0;  // sweep radius of a grain, radius of a sphere or segment
  int shape = kSphere; // library index, kSphere or kSegment
  Eigen::Vector3d half = Eigen::Vector3d::Zero();  // segment: x ± half are its ends
  std::unique_ptr<wiregrain::PosedShape> posed;
};

// Bodies binned on the broad-phase grid over the box (core/geometry/broad_phase.h) with
// cells at least as large as the largest bounding diameter, so a candidate only meets the
// bodies of its own and the adjacent cells. Periodic dimensions wrap (cells and
// minimum-image displacements, as Domain::minimum_image).
class Placer {
 public:
  Placer(Domain *domain, const wiregrain::ShapeLibrary &library, double max_bound)
      : library_(library),
        grid_(wiregrain::BroadPhaseGrid::box(
            Eigen::Vector3d(domain->boxlo[0], domain->boxlo[1], domain->boxlo[2]),
            Eigen::Vector3d(domain->boxhi[0], domain->boxhi[1], domain->boxhi[2]),
            {domain->periodicity[0] != 0, domain->periodicity[1] != 0, domain->periodicity[2] != 0},
            2.0 * max_bound)) {}

  void add(Body body) {
    grid_.insert(body.x);
    bodies_.push_back(std::move(body));
  }

  // True if the grain `c` (bounding radius `bound`) overlaps a body: exact, the signed
  // core distance ≤ r_A + r_B (touching counts). Otherwise `min_gap` receives the
  // smallest gap of the pairs whose bounding spheres meet (+inf if none) and `pairs`
  // their number.
  bool overlaps(const wiregrain::PosedShape &c, double bound, double &min_gap, long &pairs) const {
    min_gap = std::numeric_limits<double>::infinity();
    pairs = 0;
    bool overlapping = false;
    grid_.for_each_near(c.position(), [&](int b, const Eigen::Vector3d &shift) {
      if (overlapping) return;
      const Body &body = bodies_[b];
      const Eigen::Vector3d d = (body.x - c.position()) + shift;  // minimum image
      const bool shifted_image = shift != Eigen::Vector3d::Zero();
      const Eigen::Vector3d image = c.position() + d;
      const double reach = bound + body.bound;
      if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > reach * reach) return;
      double gap;
      if (body.shape == kSegment) {
        gap = wiregrain::segment_contact(c, image - body.half, image + body.half, body.sweep).gap;
      } else if (body.shape < 0) {
        gap = wiregrain::segment_contact(c, image, image, body.sweep).gap;
      } else if (!shifted_image) {
        gap = wiregrain::core_distance(c, *body.posed).distance - c.sweep_radius() - body.sweep;
      } else {
        const wiregrain::PosedShape shifted(library_[body.shape].shape, image, body.posed->orientation());
        gap = wiregrain::core_distance(c, shifted).distance - c.sweep_radius() - body.sweep;
      }
      if (gap <= 0.0) {
        overlapping = true;
        return;
      }
      min_gap = std::min(min_gap, gap);
      pairs++;
    });
    return overlapping;
  }

 private:
  const wiregrain::ShapeLibrary &library_;
  wiregrain::BroadPhaseGrid grid_;
  std::vector<Body> bodies_;
};

// The superquadric standing in for a generated grain (sq: superquadric_standing_in,
// core/geometry/superquadric.h) on atom i (atom_style superquadric), with the grain's
// orientation q (its principal axes), then what LIGGGHTS' `set ... shape ... blockiness
// ... density ... quat_direct` derives: bounding radius, volume, area, mass, inertia
// (LIGGGHTS' own functions).
void place_superquadric(Atom *atom, int i, const wiregrain::Superquadric &sq, double rho,
                        const Eigen::Quaterniond &q) {
#ifdef SUPERQUADRIC_ACTIVE_FLAG
  for (int d = 0; d < 3; d++) {
    atom->shape[i][d] = sq.half_axes[d];
    atom->angmom[i][d] = 0.0;
  }
  atom->blockiness[i][0] = sq.n1;
  atom->blockiness[i][1] = sq.n2;
  const Eigen::Quaterniond unit = q.normalized();
  atom->quaternion[i][0] = unit.w();
  atom->quaternion[i][1] = unit.x();
  atom->quaternion[i][2] = unit.y();
  atom->quaternion[i][3] = unit.z();
  atom->density[i] = rho;
  MathExtraLiggghtsNonspherical::bounding_sphere_radius_superquadric(atom->shape[i], atom->blockiness[i],
                                                                     atom->radius + i);
  MathExtraLiggghtsNonspherical::volume_superquadric(atom->shape[i], atom->blockiness[i], atom->volume + i);
  MathExtraLiggghtsNonspherical::area_superquadric(atom->shape[i], atom->blockiness[i], atom->area + i);
  atom->rmass[i] = rho * atom->volume[i];
  MathExtraLiggghtsNonspherical::inertia_superquadric(atom->shape[i], atom->blockiness[i], rho, atom->inertia[i]);
#else
  (void)atom, (void)i, (void)sq, (void)rho, (void)q;
#endif
}

struct ShapeChoice {
  std::string kind = "ellipsoid";  // ellipsoid cube box tetrahedron octahedron sphere file
  double size[3] = {0.0, 0.0, 0.0};
  std::string path;
};

}  // namespace

CreateGrains::CreateGrains(LAMMPS *lmp) : Pointers(lmp) {}

void CreateGrains::command(int narg, char **arg) {
  const std::string id = "-";
  wiregrain_lmp::StyleArgs args(error, "command", "create_grains", id, narg, arg, 0,
                                {"seed", "a_min", "a_max", "b_over_a", "c_over_a", "vertices", "sweep", "density", "spacing",
                                 "attempts", "blockiness", "write_shapes", "shape"});
  if (domain->box_exist == 0) args.fail("create a simulation box first");
  AtomVecPolyhedron *poly = AtomVecPolyhedron::of(atom);
  // without atom_style polyhedron: LIGGGHTS' superquadrics standing in for the grains, or
  // stock granular spheres of the grains' volumes
  const bool superquadrics = !poly && atom->superquadric_flag;
  const bool spheres = !poly && !superquadrics && atom->sphere_flag;
  if (!poly && !spheres && !superquadrics)
    args.fail("needs atom_style polyhedron, sphere (granular) or superquadric, plain or in a hybrid, not '" +
              std::string(atom->atom_style) + "'");
  if (domain->triclinic) args.fail("triclinic boxes are not supported");
  if (narg < 4) args.fail("expected: create_grains type N layer|random region-ID ...");

  const long type = args.value_int("type");
  if (type < 1 || type > atom->ntypes)
    args.fail("atom type " + std::to_string(type) + " is outside 1.." + std::to_string(atom->ntypes));
  const long n_grains = args.value_int_in_range("N", 1, 100000000L);
  const std::string mode = args.next_word();
  if (mode != "layer" && mode != "random") args.fail("unknown mode '" + mode + "' (layer or random)");
  const bool layer = mode == "layer";
  const std::string region_id = args.value_word("region-ID");
  const int iregion = domain->find_region(region_id.c_str());
  if (iregion < 0) args.fail("region '" + region_id + "' does not exist");
  Region *region = domain->regions[iregion];
  const double z0 = layer ? args.value_double("z0") : 0.0;

  // keywords (defaults: the paper's Table 1; docs/units.md)
  bool have_seed = false;
  std::uint64_t seed = 0;
  double a_min = 0.8, a_max = 1.0, b_over_a = 0.8, c_over_a = 0.6, sweep = 0.1, rho = 1.5;
  double spacing = 0.0, blockiness[2] = {3.0, 3.0};
  bool have_sweep = false, have_blockiness = false;
  long n_vertices = 20, attempts = 1000;
  ShapeChoice choice;
  std::string shapes_file;
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "seed") {
      const long s = args.value_int(key);
      if (s < 1) args.fail("value of 'seed' must be a positive integer, got " + std::to_string(s));
      seed = static_cast<std::uint64_t>(s);
      have_seed = true;
    } else if (key == "a_min") {
      a_min = args.value_positive(key);
    } else if (key == "a_max") {
      a_max = args.value_positive(key);
    } else if (key == "b_over_a") {
      b_over_a = args.value_double(key);
      if (!(b_over_a > 0.0 && b_over_a <= 1.0))
        args.fail("value of 'b_over_a' must be in (0, 1], got " + wiregrain::format_number(b_over_a));
    } else if (key == "c_over_a") {
      c_over_a = args.value_double(key);
    } else if (key == "vertices") {
      n_vertices = args.value_int_in_range(key, 4, 1000000L);
    } else if (key == "sweep") {
      sweep = args.value_nonnegative(key);
      have_sweep = true;
    } else if (key == "density") {
      rho = args.value_positive(key);
    } else if (key == "spacing") {
      if (!layer) args.fail("keyword 'spacing' applies to 'layer' only");
      spacing = args.value_positive(key);
    } else if (key == "attempts") {
      attempts = args.value_int_in_range(key, 1, LONG_MAX);
    } else if (key == "blockiness") {
      for (int k = 0; k < 2; k++) {
        blockiness[k] = args.value_double(key);
        if (!(blockiness[k] >= 2.0) || !std::isfinite(blockiness[k]))
          args.fail("value of 'blockiness' must be a finite number >= 2, got " + wiregrain::format_number(blockiness[k]));
      }
      have_blockiness = true;
    } else if (key == "write_shapes") {
      shapes_file = args.value_word(key);
    } else if (key == "shape") {
      choice.kind = args.value_word(key);
      if (choice.kind == "cube" || choice.kind == "tetrahedron" || choice.kind == "octahedron" ||
          choice.kind == "sphere") {
        choice.size[0] = args.value_positive("shape " + choice.kind);
      } else if (choice.kind == "box") {
        for (int d = 0; d < 3; d++) choice.size[d] = args.value_positive("shape box");
      } else if (choice.kind == "file") {
        choice.path = args.value_word("shape file");
      } else if (choice.kind != "ellipsoid") {
        args.fail("unknown shape '" + choice.kind +
                  "' (ellipsoid, cube, box, tetrahedron, octahedron, sphere or file)");
      }
    } else {
      args.unknown_keyword(key);
    }
  }
  if (!have_seed) args.fail("missing keyword 'seed' (a positive integer for the random numbers)");
  if (spheres && !shapes_file.empty())
    args.fail("keyword 'write_shapes' applies to polyhedra (atom_style polyhedron), not to spheres");
  if (superquadrics && !shapes_file.empty())
    args.fail("keyword 'write_shapes' applies to polyhedra (atom_style polyhedron), not to superquadrics");
  if (have_blockiness && !superquadrics)
    args.fail("keyword 'blockiness' applies to superquadrics (atom_style superquadric) only");
  // a sphere is the one-vertex grain whose sweep radius is its radius R
  if (choice.kind == "sphere" && have_sweep)
    args.fail("keyword 'sweep' does not apply to 'shape sphere' (its radius is the sweep radius)");
  if (a_min > a_max)
    args.fail("a_min (" + wiregrain::format_number(a_min) + ") must not exceed a_max (" +
              wiregrain::format_number(a_max) + ")");
  if (!(c_over_a > 0.0 && c_over_a <= b_over_a))
    args.fail("value of 'c_over_a' must be in (0, b_over_a] = (0, " + wiregrain::format_number(b_over_a) +
              "], got " + wiregrain::format_number(c_over_a));
  if (spacing == 0.0) spacing = 2.0 * a_max;

  // Where centres may go: the region's bounding box within the simulation box.
  region->init();
  region->prematch();
  double lo[3], hi[3];
  for (int d = 0; d < 3; d++) {
    lo[d] = domain->boxlo[d];
    hi[d] = domain->boxhi[d];
  }
  if (region->bboxflag) {
    lo[0] = std::max(lo[0], region->extent_xlo);
    hi[0] = std::min(hi[0], region->extent_xhi);
    lo[1] = std::max(lo[1], region->extent_ylo);
    hi[1] = std::min(hi[1], region->extent_yhi);
    lo[2] = std::max(lo[2], region->extent_zlo);
    hi[2] = std::min(hi[2], region->extent_zhi);
  }
  if (!(lo[0] < hi[0] && lo[1] < hi[1] && (layer || lo[2] < hi[2])))
    args.fail("region '" + region_id + "' does not overlap the simulation box");

  // Layer: lattice sites, centred in the bounding box in x and y: lattice A has n cells of
  // the spacing per row (sites at the cell centres), lattice B sits at the inner cell
  // corners 2 a_max higher; the lower lattice first, rows along x, then y.
  std::vector<Eigen::Vector3d> sites;
  if (layer) {
    long cells[2];
    double margin[2];
    for (int d = 0; d < 2; d++) {
      const double length = hi[d] - lo[d];
      cells[d] = static_cast<long>(std::floor(length / spacing + 1e-9));
      margin[d] = 0.5 * (length - cells[d] * spacing);
    }
    if (static_cast<double>(cells[0]) * static_cast<double>(cells[1]) > 1e8)
      args.fail("more than 1e8 lattice sites per layer: 'spacing' " + wiregrain::format_number(spacing) +
                " is too small for region '" + region_id + "'");
    for (int lattice = 0; lattice < 2; lattice++) {
      const double z = lattice == 0 ? z0 : z0 + 2.0 * a_max;
      const double shift = lattice == 0 ? 0.5 * spacing : spacing;
      for (long j = 0; j < cells[1] - lattice; j++) {
        const double y = lo[1] + (margin[1] + shift) + j * spacing;
        for (long i = 0; i < cells[0] - lattice; i++) {
          const double x = lo[0] + (margin[0] + shift) + i * spacing;
          if (region->match(x, y, z)) sites.emplace_back(x, y, z);
        }
      }
    }
    if (static_cast<long>(sites.size()) < n_grains)
      args.fail("region too small for the layer: " + std::to_string(n_grains) + " grains asked, " +
                std::to_string(sites.size()) + " sites");
  }

  // Shapes, generated identically on every rank and added to every rank's library in the
  // same order (spheres: to a library of this command only).
  std::mt19937_64 rng(seed);
  const int n = static_cast<int>(n_grains);
  std::vector<int> shape_of(n);
  std::vector<Eigen::Quaterniond> body_to_input(n);
  wiregrain::ShapeLibrary own_library;
  const auto add_shape = [&](const wiregrain::ConvexShape &shape, double q[4]) {
    if (poly) return poly->add_shape(shape, q, NULL);
    wiregrain::ShapeLibrary::Placement placement;
    const int index = own_library.add(shape, &placement);
    q[0] = placement.rotation.w();
    q[1] = placement.rotation.x();
    q[2] = placement.rotation.y();
    q[3] = placement.rotation.z();
    return index;
  };
  const int library_before = poly ? poly->shapes().size() : 0;
  try {
    if (choice.kind == "ellipsoid") {
      for (int k = 0; k < n; k++) {
        const double a = a_min + (a_max - a_min) * uniform01(rng);
        const wiregrain::ConvexShape s = wiregrain::ConvexShape::random_ellipsoid(
            rng, static_cast<int>(n_vertices), a, b_over_a, c_over_a, sweep);
        double q[4];
        shape_of[k] = add_shape(s, q);
        body_to_input[k] = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
      }
    } else {
      std::unique_ptr<wiregrain::ConvexShape> s;
      const double *L = choice.size;
      if (choice.kind == "cube") s.reset(new wiregrain::ConvexShape(wiregrain::ConvexShape::cube(L[0], sweep)));
      else if (choice.kind == "box")
        s.reset(new wiregrain::ConvexShape(wiregrain::ConvexShape::box(L[0], L[1], L[2], sweep)));
      else if (choice.kind == "tetrahedron")
        s.reset(new wiregrain::ConvexShape(wiregrain::ConvexShape::regular_tetrahedron(L[0], sweep)));
      else if (choice.kind == "octahedron")
        s.reset(new wiregrain::ConvexShape(wiregrain::ConvexShape::regular_octahedron(L[0], sweep)));
      else if (choice.kind == "sphere")
        s.reset(new wiregrain::ConvexShape(wiregrain::ConvexShape::sphere(L[0])));
      else
        s.reset(new wiregrain::ConvexShape(wiregrain::ConvexShape::from_vertex_file(choice.path, sweep)));
      double q[4];
      const int index = add_shape(*s, q);
      for (int k = 0; k < n; k++) {
        shape_of[k] = index;
        body_to_input[k] = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
      }
    }
  } catch (const wiregrain::InvalidArgument &e) {
    const std::string keyword = choice.kind == "file" ? "shape file" : "shape " + choice.kind;
    args.fail("'" + keyword + "': " + e.what());
  } catch (const wiregrain::NumericalFailure &e) {
    args.fail("'shape " + choice.kind + "': " + e.what());
  }
  // spheres: each grain becomes the sphere of its volume (the swept one), placed in its stead
  if (spheres) {
    const int generated = own_library.size();
    std::vector<int> sphere_of(generated);
    for (int s = 0; s < generated; s++) {
      const double radius = std::cbrt(3.0 * own_library[s].volume / (4.0 * kPi));
      sphere_of[s] = own_library.add(wiregrain::ConvexShape::sphere(radius));
    }
    for (int k = 0; k < n; k++) shape_of[k] = sphere_of[shape_of[k]];
  }
  const wiregrain::ShapeLibrary &library = poly ? poly->shapes() : own_library;

  // Existing atoms, gathered on every rank: x, quaternion, shape, radius, tag, next bead.
  constexpr int kValues = 11;
  AtomVecWire *wire = AtomVecWire::of(atom);
  std::vector<double> mine;
  for (int i = 0; i < atom->nlocal; i++) {
    for (int d = 0; d < 3; d++) mine.push_back(atom->x[i][d]);
    for (int d = 0; d < 4; d++) mine.push_back(poly ? atom->quaternion[i][d] : double(d == 0));
    mine.push_back(poly ? atom->shapetype[i] : -1);
    mine.push_back(atom->radius[i]);
    mine.push_back(atom->tag[i]);
    mine.push_back(wire ? wire->wire_next[i] : 0);
  }
  const std::vector<double> existing = wiregrain_lmp::all_gather_records(world, mine);
  const int n_existing = static_cast<int>(existing.size()) / kValues;

  // wire segments: a bead and its next bead (ends placed by minimum image)
  std::unordered_map<long, int> index_of_tag;
  for (int e = 0; e < n_existing; e++) index_of_tag[std::lround(existing[kValues * e + 9])] = e;
  std::vector<Body> segments;
  for (int e = 0; e < n_existing; e++) {
    const double *v = &existing[kValues * e];
    const auto next = index_of_tag.find(std::lround(v[10]));
    if (v[10] <= 0.0 || next == index_of_tag.end()) continue;
    const double *w = &existing[kValues * next->second];
    double d[3] = {w[0] - v[0], w[1] - v[1], w[2] - v[2]};
    domain->minimum_image(d);
    Body b;
    b.shape = kSegment;
    b.half = 0.5 * Eigen::Vector3d(d[0], d[1], d[2]);
    b.x = Eigen::Vector3d(v[0], v[1], v[2]) + b.half;
    b.sweep = v[8];
    b.bound = b.half.norm() + b.sweep;
    segments.push_back(std::move(b));
  }

  double max_bound = 0.0;
  for (int k = 0; k < n; k++) max_bound = std::max(max_bound, library[shape_of[k]].bounding_radius);
  for (int e = 0; e < n_existing; e++) {
    const int s = static_cast<int>(existing[kValues * e + 7]);
    max_bound = std::max(max_bound, s >= 0 ? library[s].bounding_radius : existing[kValues * e + 8]);
  }
  for (const Body &b : segments) max_bound = std::max(max_bound, b.bound);
  Placer placer(domain, library, max_bound);
  for (Body &b : segments) placer.add(std::move(b));
  for (int e = 0; e < n_existing; e++) {
    const double *v = &existing[kValues * e];
    Body b;
    b.x = Eigen::Vector3d(v[0], v[1], v[2]);
    b.shape = std::max(kSphere, static_cast<int>(v[7]));
    if (b.shape >= 0) {
      b.bound = library[b.shape].bounding_radius;
      b.sweep = library[b.shape].shape.sweep_radius();
      b.posed.reset(new wiregrain::PosedShape(library[b.shape].shape, b.x,
                                              Eigen::Quaterniond(v[3], v[4], v[5], v[6])));
    } else {
      b.bound = b.sweep = v[8];
    }
    placer.add(std::move(b));
  }

  // Placement: a fresh random orientation (and, for random, position) per attempt until
  // the grain overlaps nothing.
  std::vector<Eigen::Vector3d> position(n);
  std::vector<Eigen::Quaterniond> orientation(n);
  double min_gap = std::numeric_limits<double>::infinity();
  long close_pairs = 0, tries = 0;
  for (int k = 0; k < n; k++) {
    const wiregrain::GrainShape &g = library[shape_of[k]];
    bool placed = false;
    for (long attempt = 0; attempt < attempts && !placed; attempt++) {
      tries++;
      Eigen::Vector3d p;
      if (layer) {
        p = sites[k];
      } else {
        for (int d = 0; d < 3; d++) p[d] = lo[d] + (hi[d] - lo[d]) * uniform01(rng);
      }
      const Eigen::Quaterniond q = (random_orientation(rng) * body_to_input[k]).normalized();
      if (!layer && !region->match(p[0], p[1], p[2])) continue;
      const wiregrain::PosedShape candidate(g.shape, p, q);
      double gap;
      long pairs;
      if (placer.overlaps(candidate, g.bounding_radius, gap, pairs)) continue;
      placed = true;
      min_gap = std::min(min_gap, gap);
      close_pairs += pairs;
      position[k] = p;
      orientation[k] = candidate.orientation();
      Body b;
      b.x = p;
      b.bound = g.bounding_radius;
      b.sweep = g.shape.sweep_radius();
      b.shape = shape_of[k];
      b.posed.reset(new wiregrain::PosedShape(g.shape, p, q));
      placer.add(std::move(b));
    }
    if (!placed) {
      if (layer) {
        const Eigen::Vector3d &p = sites[k];
        args.fail("grain " + std::to_string(k + 1) + " of " + std::to_string(n) + " at the lattice site (" +
                  wiregrain::format_number(p[0]) + ", " + wiregrain::format_number(p[1]) + ", " +
                  wiregrain::format_number(p[2]) + ") overlaps other grains in all " + std::to_string(attempts) +
                  " orientations tried (increase 'spacing' or 'attempts')");
      }
      args.fail("could only place " + std::to_string(k) + " of " + std::to_string(n) + " grains in region '" +
                region_id + "' (" + std::to_string(attempts) + " attempts for grain " + std::to_string(k + 1) +
                ")");
    }
  }

  // Centres must lie in the box along non-periodic dimensions.
  for (int k = 0; k < n; k++)
    for (int d = 0; d < 3; d++)
      if (!domain->periodicity[d] && (position[k][d] < domain->boxlo[d] || position[k][d] >= domain->boxhi[d]))
        args.fail("grain " + std::to_string(k + 1) + " at (" + wiregrain::format_number(position[k][0]) + ", " +
                  wiregrain::format_number(position[k][1]) + ", " + wiregrain::format_number(position[k][2]) +
                  ") lies outside the simulation box");

  const int maxtag = wiregrain_lmp::max_atom_tag(lmp);
  if (static_cast<long>(maxtag) + n > MAXSMALLINT) args.fail("too many atoms: atom IDs would exceed the int range");

  // superquadrics: the stand-in of every shape in use, on every rank (the same library
  // everywhere, so a shape without one stops all ranks alike)
  std::vector<wiregrain::Superquadric> stand_in(superquadrics ? library.size() : 0);
  if (superquadrics)
    for (int k = 0; k < n; k++) {
      const wiregrain::GrainShape &g = library[shape_of[k]];
      try {
        stand_in[shape_of[k]] = wiregrain::superquadric_standing_in(g.volume, g.unit_inertia, blockiness[0], blockiness[1]);
      } catch (const wiregrain::InvalidArgument &e) {
        args.fail(std::string("cannot make the superquadric of grain ") + std::to_string(k + 1) + ": " + e.what());
      }
    }

  const int nlocal_before = atom->nlocal;
  for (int k = 0; k < n; k++) {
    double x[3] = {position[k][0], position[k][1], position[k][2]};
    tagint image = ((tagint)IMGMAX << IMG2BITS) | ((tagint)IMGMAX << IMGBITS) | IMGMAX;
    domain->remap(x, image);
    if (x[0] < domain->sublo[0] || x[0] >= domain->subhi[0] || x[1] < domain->sublo[1] ||
        x[1] >= domain->subhi[1] || x[2] < domain->sublo[2] || x[2] >= domain->subhi[2])
      continue;
    atom->avec->create_atom(static_cast<int>(type), x);
    const int i = atom->nlocal - 1;
    atom->tag[i] = maxtag + 1 + k;
    atom->image[i] = image;
    for (int d = 0; d < 3; d++) atom->v[i][d] = atom->omega[i][d] = 0.0;
    if (superquadrics) {  // the grain's stand-in, as LIGGGHTS' `set ... shape blockiness density quat` makes it
      place_superquadric(atom, i, stand_in[shape_of[k]], rho, orientation[k]);
      continue;
    }
    if (spheres) {  // as LIGGGHTS' `set ... diameter D density rho` makes it
      const double r = library[shape_of[k]].shape.sweep_radius();
      atom->radius[i] = r;
      atom->rmass[i] = rho * 4.0 * kPi / 3.0 * r * r * r;
      if (atom->density_flag) atom->density[i] = rho;
      continue;
    }
    const Eigen::Quaterniond &q = orientation[k];
    atom->quaternion[i][0] = q.w();
    atom->quaternion[i][1] = q.x();
    atom->quaternion[i][2] = q.y();
    atom->quaternion[i][3] = q.z();
    for (int d = 0; d < 3; d++) atom->angmom[i][d] = 0.0;
    poly->assign_shape(i, shape_of[k], rho);
  }

  const bigint created = wiregrain_lmp::finish_created_atoms(lmp, nlocal_before);
  if (created != n)
    args.fail(std::to_string(n - created) + " of " + std::to_string(n) +
              " grains were not created by any rank (outside every subdomain)");

  // write_shapes: every created grain with its body-frame geometry (rank 0 knows them all)
  if (!shapes_file.empty()) {
    int ok = 1;
    if (comm->me == 0) {
      FILE *fp = fopen(shapes_file.c_str(), "w");
      if (!fp) {
        ok = 0;
      } else {
        fprintf(fp, "# create_grains shapes: %d grains; x_world = R(q) x_body + position, q = (qw qi qj qk) body -> space\n", n);
        fprintf(fp, "# grain tag shape sweep volume density x y z qw qi qj qk n_vertices n_faces\n");
        fprintf(fp, "# then n_vertices lines 'x y z' (body frame), n_faces lines 'k i_1 .. i_k' "
                    "(vertex indices from 0, counter-clockwise seen from outside)\n");
        for (int k = 0; k < n; k++) {
          const wiregrain::GrainShape &g = library[shape_of[k]];
          const Eigen::Quaterniond &q = orientation[k];
          fprintf(fp, "grain %d %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %d %d\n",
                  maxtag + 1 + k, shape_of[k], g.shape.sweep_radius(), g.volume, rho, position[k][0],
                  position[k][1], position[k][2], q.w(), q.x(), q.y(), q.z(),
                  static_cast<int>(g.shape.vertices().size()), static_cast<int>(g.shape.faces().size()));
          for (const Eigen::Vector3d &v : g.shape.vertices()) fprintf(fp, "%.17g %.17g %.17g\n", v[0], v[1], v[2]);
          for (const auto &f : g.shape.faces()) {
            fprintf(fp, "%d", static_cast<int>(f.vertices.size()));
            for (int v : f.vertices) fprintf(fp, " %d", v);
            fprintf(fp, "\n");
          }
        }
        ok = fclose(fp) == 0;
      }
    }
    MPI_Bcast(&ok, 1, MPI_INT, 0, world);
    if (!ok) args.fail("cannot write the 'write_shapes' file '" + shapes_file + "'");
  }

  if (comm->me == 0) {
    char line[512];
    std::string msg = "create_grains: " + std::to_string(n) +
                      (spheres ? " spheres of the grains' volumes ("
                               : superquadrics ? " superquadrics standing in for the grains (" : " grains (") +
                      (layer ? "layer of " + std::to_string(sites.size()) + " lattice sites" : std::string("random")) +
                      " in region " + region_id + "), atom IDs " + std::to_string(maxtag + 1) + ".." +
                      std::to_string(maxtag + n) +
                      (spheres || superquadrics ? std::string("\n")
                               : ", library shapes " + std::to_string(library_before) + ".." +
                                     std::to_string(library.size() - 1) + "\n");
    if (close_pairs > 0)
      snprintf(line, sizeof line,
               "create_grains: minimum gap %.17g over %ld close pairs (bounding spheres meet), %ld attempts\n",
               min_gap, close_pairs, tries);
    else
      snprintf(line, sizeof line, "create_grains: no close pairs (bounding spheres apart), %ld attempts\n", tries);
    msg += line;
    if (screen) fputs(msg.c_str(), screen);
    if (logfile) fputs(msg.c_str(), logfile);
  }
}
