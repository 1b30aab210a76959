#include "create_grains.h"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

#include "atom.h"
#include "atom_vec.h"
#include "atom_vec_polyhedron.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "region.h"

#include "core/common/constants.h"
#include "core/common/errors.h"
#include "core/common/validation.h"
#include "core/geometry/convex_shape.h"
#include "core/geometry/grain_generation.h"
#include "core/geometry/grain_placement.h"
#include "core/geometry/shape_library.h"
#include "core/geometry/superquadric.h"
#ifdef SUPERQUADRIC_ACTIVE_FLAG
#include "math_extra_liggghts_superquadric.h"
#endif
#include "atom_style_part.h"
#include "bead_chain_links.h"
#include "plugin_args.h"
#include "plugin_comm.h"
#include "plugin_create.h"

using namespace LAMMPS_NS;

namespace {

using wiregrain::kPi;
using wiregrain::PlacementObstacle;

// What the grains become: polyhedra of atom_style polyhedron or, without it, LIGGGHTS'
// superquadrics standing in for them or stock granular spheres of their volumes.
enum class GrainBodies { polyhedra, superquadrics, spheres };

// The command's arguments, checked (defaults: the paper's Table 1; docs/units.md).
struct GrainSettings {
  GrainBodies bodies = GrainBodies::polyhedra;
  int type = 0;
  int n = 0;  // grains to insert
  bool layer = false;
  std::string region_id;
  Region *region = nullptr;
  double z0 = 0.0;  // layer: height of the lower lattice
  std::uint64_t seed = 0;
  wiregrain::GrainShapeRecipe recipe;
  double rho = 1.5;
  double spacing = 0.0;  // layer: lattice spacing (default 2 a_max)
  long attempts = 1000;
  double blockiness[2] = {3.0, 3.0};  // superquadrics
  std::string shapes_file;            // write_shapes
};

// The atom style's grains and the positional arguments: type N layer|random region-ID [z0].
void parse_positional(LAMMPS *lmp, wiregrain_lmp::StyleArgs &args, int narg, GrainSettings &s) {
  Atom *atom = lmp->atom;
  Domain *domain = lmp->domain;
  if (domain->box_exist == 0) args.fail("create a simulation box first");
  const bool poly = AtomVecPolyhedron::of(atom) != NULL;
  const bool superquadrics = !poly && atom->superquadric_flag;
  const bool spheres = !poly && !superquadrics && atom->sphere_flag;
  if (!poly && !spheres && !superquadrics)
    args.fail("needs atom_style polyhedron, sphere (granular) or superquadric, plain or in a hybrid, not '" +
              std::string(atom->atom_style) + "'");
  s.bodies = poly ? GrainBodies::polyhedra : superquadrics ? GrainBodies::superquadrics : GrainBodies::spheres;
  if (domain->triclinic) args.fail("triclinic boxes are not supported");
  if (narg < 4) args.fail("expected: create_grains type N layer|random region-ID ...");

  const long type = args.value_int("type");
  if (type < 1 || type > atom->ntypes)
    args.fail("atom type " + std::to_string(type) + " is outside 1.." + std::to_string(atom->ntypes));
  s.type = static_cast<int>(type);
  s.n = static_cast<int>(args.value_int_in_range("N", 1, 100000000L));
  const std::string mode = args.next_word();
  if (mode != "layer" && mode != "random") args.fail("unknown mode '" + mode + "' (layer or random)");
  s.layer = mode == "layer";
  s.region_id = args.value_word("region-ID");
  const int iregion = domain->find_region(s.region_id.c_str());
  if (iregion < 0) args.fail("region '" + s.region_id + "' does not exist");
  s.region = domain->regions[iregion];
  s.z0 = s.layer ? args.value_double("z0") : 0.0;
}

// keyword shape: its kind and the kind's values
void parse_shape(wiregrain_lmp::StyleArgs &args, wiregrain::GrainShapeRecipe &recipe) {
  recipe.kind = args.value_word("shape");
  if (recipe.kind == "cube" || recipe.kind == "tetrahedron" || recipe.kind == "octahedron" || recipe.kind == "sphere") {
    recipe.size[0] = args.value_positive("shape " + recipe.kind);
  } else if (recipe.kind == "box") {
    for (int d = 0; d < 3; d++) recipe.size[d] = args.value_positive("shape box");
  } else if (recipe.kind == "file") {
    recipe.path = args.value_word("shape file");
  } else if (recipe.kind != "ellipsoid") {
    args.fail("unknown shape '" + recipe.kind + "' (ellipsoid, cube, box, tetrahedron, octahedron, sphere or file)");
  }
}

// The keywords, then their checks against each other and the atom style.
void parse_keywords(wiregrain_lmp::StyleArgs &args, GrainSettings &s) {
  wiregrain::GrainShapeRecipe &r = s.recipe;
  bool have_seed = false, have_sweep = false, have_blockiness = false;
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "seed") {
      const long seed = args.value_int(key);
      if (seed < 1) args.fail("value of 'seed' must be a positive integer, got " + std::to_string(seed));
      s.seed = static_cast<std::uint64_t>(seed);
      have_seed = true;
    } else if (key == "a_min") {
      r.a_min = args.value_positive(key);
    } else if (key == "a_max") {
      r.a_max = args.value_positive(key);
    } else if (key == "b_over_a") {
      r.b_over_a = args.value_double(key);
      if (!(r.b_over_a > 0.0 && r.b_over_a <= 1.0))
        args.fail("value of 'b_over_a' must be in (0, 1], got " + wiregrain::format_number(r.b_over_a));
    } else if (key == "c_over_a") {
      r.c_over_a = args.value_double(key);
    } else if (key == "vertices") {
      r.n_vertices = static_cast<int>(args.value_int_in_range(key, 4, 1000000L));
    } else if (key == "sweep") {
      r.sweep = args.value_nonnegative(key);
      have_sweep = true;
    } else if (key == "density") {
      s.rho = args.value_positive(key);
    } else if (key == "spacing") {
      if (!s.layer) args.fail("keyword 'spacing' applies to 'layer' only");
      s.spacing = args.value_positive(key);
    } else if (key == "attempts") {
      s.attempts = args.value_int_in_range(key, 1, LONG_MAX);
    } else if (key == "blockiness") {
      for (int k = 0; k < 2; k++) {
        s.blockiness[k] = args.value_double(key);
        if (!(s.blockiness[k] >= 2.0) || !std::isfinite(s.blockiness[k]))
          args.fail("value of 'blockiness' must be a finite number >= 2, got " +
                    wiregrain::format_number(s.blockiness[k]));
      }
      have_blockiness = true;
    } else if (key == "write_shapes") {
      s.shapes_file = args.value_word(key);
    } else if (key == "shape") {
      parse_shape(args, r);
    } else {
      args.unknown_keyword(key);
    }
  }
  if (!have_seed) args.fail("missing keyword 'seed' (a positive integer for the random numbers)");
  if (s.bodies == GrainBodies::spheres && !s.shapes_file.empty())
    args.fail("keyword 'write_shapes' applies to polyhedra (atom_style polyhedron), not to spheres");
  if (s.bodies == GrainBodies::superquadrics && !s.shapes_file.empty())
    args.fail("keyword 'write_shapes' applies to polyhedra (atom_style polyhedron), not to superquadrics");
  if (have_blockiness && s.bodies != GrainBodies::superquadrics)
    args.fail("keyword 'blockiness' applies to superquadrics (atom_style superquadric) only");
  // a sphere is the one-vertex grain whose sweep radius is its radius R
  if (r.kind == "sphere" && have_sweep)
    args.fail("keyword 'sweep' does not apply to 'shape sphere' (its radius is the sweep radius)");
  if (r.a_min > r.a_max)
    args.fail("a_min (" + wiregrain::format_number(r.a_min) + ") must not exceed a_max (" +
              wiregrain::format_number(r.a_max) + ")");
  if (!(r.c_over_a > 0.0 && r.c_over_a <= r.b_over_a))
    args.fail("value of 'c_over_a' must be in (0, b_over_a] = (0, " + wiregrain::format_number(r.b_over_a) +
              "], got " + wiregrain::format_number(r.c_over_a));
  if (s.spacing == 0.0) s.spacing = 2.0 * r.a_max;
}

// Where centres may go: the region's bounding box within the simulation box, [lo, hi).
void region_bounds(Domain *domain, const GrainSettings &s, const wiregrain_lmp::StyleArgs &args,
                   Eigen::Vector3d &lo, Eigen::Vector3d &hi) {
  Region *region = s.region;
  region->init();
  region->prematch();
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
  if (!(lo[0] < hi[0] && lo[1] < hi[1] && (s.layer || lo[2] < hi[2])))
    args.fail("region '" + s.region_id + "' does not overlap the simulation box");
}

// Layer: the sites of the two lattices inside the region (core/geometry/grain_placement.h),
// centred in the bounding box in x and y, lattice B 2 a_max higher.
std::vector<Eigen::Vector3d> layer_sites(const GrainSettings &s, const wiregrain_lmp::StyleArgs &args,
                                         const Eigen::Vector3d &lo, const Eigen::Vector3d &hi) {
  const wiregrain::LayerLattice lattice(lo[0], hi[0], lo[1], hi[1], s.spacing);
  if (lattice.cells() > 1e8)
    args.fail("more than 1e8 lattice sites per layer: 'spacing' " + wiregrain::format_number(s.spacing) +
              " is too small for region '" + s.region_id + "'");
  Region *region = s.region;
  const std::vector<Eigen::Vector3d> sites = lattice.sites(
      s.z0, 2.0 * s.recipe.a_max, [region](const Eigen::Vector3d &p) { return region->match(p[0], p[1], p[2]) != 0; });
  if (static_cast<long>(sites.size()) < s.n)
    args.fail("region too small for the layer: " + std::to_string(s.n) + " grains asked, " +
              std::to_string(sites.size()) + " sites");
  return sites;
}

// Shapes, generated identically on every rank and added to every rank's library in the
// same order (without atom_style polyhedron: to `own_library`, of this command only;
// spheres: then replaced by the spheres of their volumes).
wiregrain::GrainShapeDraw draw_shapes(std::mt19937_64 &rng, const GrainSettings &s, AtomVecPolyhedron *poly,
                                      wiregrain::ShapeLibrary &own_library, const wiregrain_lmp::StyleArgs &args) {
  const auto add_shape = [&](const wiregrain::ConvexShape &shape, Eigen::Quaterniond &body_to_input) {
    if (poly) {
      double q[4];
      const int index = poly->add_shape(shape, q, NULL);
      body_to_input = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
      return index;
    }
    wiregrain::ShapeLibrary::Placement placement;
    const int index = own_library.add(shape, &placement);
    body_to_input = placement.rotation;
    return index;
  };
  wiregrain::GrainShapeDraw draw;
  const std::string &kind = s.recipe.kind;
  try {
    draw = wiregrain::draw_grain_shapes(rng, s.recipe, s.n, add_shape);
  } catch (const wiregrain::InvalidArgument &e) {
    const std::string keyword = kind == "file" ? "shape file" : "shape " + kind;
    args.fail("'" + keyword + "': " + e.what());
  } catch (const wiregrain::NumericalFailure &e) {
    args.fail("'shape " + kind + "': " + e.what());
  }
  if (s.bodies == GrainBodies::spheres) wiregrain::replace_by_spheres_of_volume(own_library, draw.shape_of);
  return draw;
}

// The atoms already in the box that a grain placed with its centre in [lo, hi] can reach,
// gathered on every rank, kExistingValues per atom: x, quaternion, shape (−1: none),
// radius, tag, next bead (0: none). An atom is left out when its centre lies farther from
// [lo, hi] along a non-periodic axis than its radius (a grain's bounding radius) plus
// new_bound (the largest bounding radius of the new grains) plus, for a bead of a chain,
// the longest segment over all ranks: every segment a new grain can touch then has both
// its beads gathered. (A bead whose next bead is neither owned nor a ghost here, or a
// system without an atom map, makes the longest segment unknown: then every bead is
// gathered.) Collective.
constexpr int kExistingValues = 11;
std::vector<double> gather_atoms_within_reach(LAMMPS *lmp, bool polyhedra, const Eigen::Vector3d &lo,
                                              const Eigen::Vector3d &hi, double new_bound) {
  Atom *atom = lmp->atom;
  Domain *domain = lmp->domain;
  const wiregrain_lmp::BeadChainLinks *chains = wiregrain_lmp::atom_style_part<const wiregrain_lmp::BeadChainLinks>(atom);
  const auto in_chain = [&](int i) { return chains && (chains->next_bead_tag(i) > 0 || chains->previous_bead_tag(i) > 0); };
  double longest = 0.0;
  for (int i = 0; chains && i < atom->nlocal; i++) {
    const int next = chains->next_bead_tag(i);
    if (next <= 0) continue;
    const int j = atom->map_style ? atom->map(next) : -1;
    if (j < 0) {
      longest = HUGE_VAL;
      break;
    }
    double d[3] = {atom->x[j][0] - atom->x[i][0], atom->x[j][1] - atom->x[i][1], atom->x[j][2] - atom->x[i][2]};
    domain->minimum_image(d);
    longest = std::max(longest, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
  }
  double longest_all = longest;
  MPI_Allreduce(&longest, &longest_all, 1, MPI_DOUBLE, MPI_MAX, lmp->world);
  std::vector<double> mine;
  for (int i = 0; i < atom->nlocal; i++) {
    const double margin = atom->radius[i] + new_bound + (in_chain(i) ? longest_all : 0.0);
    bool reach = true;
    for (int d = 0; d < 3; d++)
      if (!domain->periodicity[d] && (atom->x[i][d] < lo[d] - margin || atom->x[i][d] > hi[d] + margin)) reach = false;
    if (!reach) continue;
    for (int d = 0; d < 3; d++) mine.push_back(atom->x[i][d]);
    for (int d = 0; d < 4; d++) mine.push_back(polyhedra ? atom->quaternion[i][d] : double(d == 0));
    mine.push_back(polyhedra ? atom->shapetype[i] : -1);
    mine.push_back(atom->radius[i]);
    mine.push_back(atom->tag[i]);
    mine.push_back(chains ? chains->next_bead_tag(i) : 0);
  }
  return wiregrain_lmp::all_gather_records(lmp->world, mine);
}

// The chain segments among them: a bead and its next bead (ends placed by minimum image).
std::vector<PlacementObstacle> chain_segments(Domain *domain, const std::vector<double> &existing) {
  const int n_existing = static_cast<int>(existing.size()) / kExistingValues;
  std::unordered_map<long, int> index_of_tag;
  for (int e = 0; e < n_existing; e++) index_of_tag[std::lround(existing[kExistingValues * e + 9])] = e;
  std::vector<PlacementObstacle> segments;
  for (int e = 0; e < n_existing; e++) {
    const double *v = &existing[kExistingValues * e];
    const auto next = index_of_tag.find(std::lround(v[10]));
    if (v[10] <= 0.0 || next == index_of_tag.end()) continue;
    const double *w = &existing[kExistingValues * next->second];
    double d[3] = {w[0] - v[0], w[1] - v[1], w[2] - v[2]};
    domain->minimum_image(d);
    segments.push_back(
        PlacementObstacle::segment(Eigen::Vector3d(v[0], v[1], v[2]), Eigen::Vector3d(d[0], d[1], d[2]), v[8]));
  }
  return segments;
}

// The grid of everything the new grains must not overlap: the chain segments, then every
// existing atom a new grain can reach (a grain of the library, else a sphere of its
// radius). A new grain's centre lies in [lo, hi] (the region's bounds, or those of a
// layer's sites), so an atom whose centre is farther from them along a non-periodic axis
// than its radius (a grain's bounding radius) plus the largest new bounding radius touches
// none and is left out, neither gathered (gathered: how many were) nor built: a column
// laid layer by layer places each layer among the grains of the layers next to it only.
wiregrain::PlacementGrid obstacle_grid(LAMMPS *lmp, const wiregrain::ShapeLibrary &library,
                                       const std::vector<int> &shape_of, bool polyhedra, const Eigen::Vector3d &lo,
                                       const Eigen::Vector3d &hi, long &gathered) {
  Domain *domain = lmp->domain;
  double max_bound = 0.0;
  for (int shape : shape_of) max_bound = std::max(max_bound, library[shape].bounding_radius);
  const double new_bound = max_bound;
  const std::vector<double> all = gather_atoms_within_reach(lmp, polyhedra, lo, hi, new_bound);
  gathered = static_cast<long>(all.size() / kExistingValues);
  std::vector<PlacementObstacle> segments = chain_segments(domain, all);

  std::vector<double> existing;
  for (std::size_t e = 0; e < all.size() / kExistingValues; e++) {
    const double *v = &all[kExistingValues * e];
    bool reach = true;
    for (int d = 0; d < 3; d++)
      if (!domain->periodicity[d] && (v[d] < lo[d] - v[8] - new_bound || v[d] > hi[d] + v[8] + new_bound)) reach = false;
    if (reach) existing.insert(existing.end(), v, v + kExistingValues);
  }
  const int n_existing = static_cast<int>(existing.size()) / kExistingValues;
  for (int e = 0; e < n_existing; e++) max_bound = std::max(max_bound, existing[kExistingValues * e + 8]);
  for (const PlacementObstacle &b : segments) max_bound = std::max(max_bound, b.bound);
  wiregrain::PlacementGrid grid(
      library, Eigen::Vector3d(domain->boxlo[0], domain->boxlo[1], domain->boxlo[2]),
      Eigen::Vector3d(domain->boxhi[0], domain->boxhi[1], domain->boxhi[2]),
      {domain->periodicity[0] != 0, domain->periodicity[1] != 0, domain->periodicity[2] != 0}, max_bound);
  for (PlacementObstacle &b : segments) grid.add(std::move(b));
  for (int e = 0; e < n_existing; e++) {
    const double *v = &existing[kExistingValues * e];
    const Eigen::Vector3d x(v[0], v[1], v[2]);
    const int shape = std::max(PlacementObstacle::kSphere, static_cast<int>(v[7]));
    if (shape >= 0)
      grid.add(PlacementObstacle::grain(library, shape, x, Eigen::Quaterniond(v[3], v[4], v[5], v[6])));
    else
      grid.add(PlacementObstacle::sphere(x, v[8]));
  }
  return grid;
}

// Placement (core/geometry/grain_placement.h); stops when a grain finds no place.
wiregrain::GrainPlacement place(wiregrain::PlacementGrid &grid, const wiregrain::GrainShapeDraw &draw,
                                const GrainSettings &s, const std::vector<Eigen::Vector3d> &sites,
                                const Eigen::Vector3d &lo, const Eigen::Vector3d &hi, std::mt19937_64 &rng,
                                const wiregrain_lmp::StyleArgs &args) {
  wiregrain::GrainSites where;
  where.layer = s.layer;
  where.sites = sites;
  where.lo = lo;
  where.hi = hi;
  Region *region = s.region;
  where.inside = [region](const Eigen::Vector3d &p) { return region->match(p[0], p[1], p[2]) != 0; };
  wiregrain::GrainPlacement placed = wiregrain::place_grains(grid, draw.shape_of, draw.body_to_input, where, s.attempts, rng);
  const int k = placed.unplaced;
  if (k >= 0) {
    if (s.layer) {
      const Eigen::Vector3d &p = sites[k];
      args.fail("grain " + std::to_string(k + 1) + " of " + std::to_string(s.n) + " at the lattice site (" +
                wiregrain::format_number(p[0]) + ", " + wiregrain::format_number(p[1]) + ", " +
                wiregrain::format_number(p[2]) + ") overlaps other grains in all " + std::to_string(s.attempts) +
                " orientations tried (increase 'spacing' or 'attempts')");
    }
    args.fail("could only place " + std::to_string(k) + " of " + std::to_string(s.n) + " grains in region '" +
              s.region_id + "' (" + std::to_string(s.attempts) + " attempts for grain " + std::to_string(k + 1) +
              ")");
  }
  return placed;
}

// Centres must lie in the box along non-periodic dimensions.
void check_in_box(Domain *domain, const std::vector<Eigen::Vector3d> &position, const wiregrain_lmp::StyleArgs &args) {
  for (size_t k = 0; k < position.size(); k++)
    for (int d = 0; d < 3; d++)
      if (!domain->periodicity[d] && (position[k][d] < domain->boxlo[d] || position[k][d] >= domain->boxhi[d]))
        args.fail("grain " + std::to_string(k + 1) + " at (" + wiregrain::format_number(position[k][0]) + ", " +
                  wiregrain::format_number(position[k][1]) + ", " + wiregrain::format_number(position[k][2]) +
                  ") lies outside the simulation box");
}

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

// Superquadrics: the stand-in of every shape in use, on every rank (the same library
// everywhere, so a shape without one stops all ranks alike).
std::vector<wiregrain::Superquadric> superquadric_stand_ins(const wiregrain::ShapeLibrary &library,
                                                            const std::vector<int> &shape_of, const GrainSettings &s,
                                                            const wiregrain_lmp::StyleArgs &args) {
  std::vector<wiregrain::Superquadric> stand_in(library.size());
  for (size_t k = 0; k < shape_of.size(); k++) {
    const wiregrain::GrainShape &g = library[shape_of[k]];
    try {
      stand_in[shape_of[k]] = wiregrain::superquadric_standing_in(g.volume, g.unit_inertia, s.blockiness[0], s.blockiness[1]);
    } catch (const wiregrain::InvalidArgument &e) {
      args.fail(std::string("cannot make the superquadric of grain ") + std::to_string(k + 1) + ": " + e.what());
    }
  }
  return stand_in;
}

// Each rank creates the grains in its subdomain, atom IDs maxtag + 1 + k; returns how many
// all ranks created together.
bigint create_grain_atoms(LAMMPS *lmp, const GrainSettings &s, const wiregrain::ShapeLibrary &library,
                          const std::vector<int> &shape_of, const wiregrain::GrainPlacement &placed,
                          const std::vector<wiregrain::Superquadric> &stand_in, int maxtag) {
  Atom *atom = lmp->atom;
  Domain *domain = lmp->domain;
  AtomVecPolyhedron *poly = AtomVecPolyhedron::of(atom);
  const int nlocal_before = atom->nlocal;
  for (int k = 0; k < s.n; k++) {
    double x[3] = {placed.position[k][0], placed.position[k][1], placed.position[k][2]};
    tagint image = ((tagint)IMGMAX << IMG2BITS) | ((tagint)IMGMAX << IMGBITS) | IMGMAX;
    domain->remap(x, image);
    if (x[0] < domain->sublo[0] || x[0] >= domain->subhi[0] || x[1] < domain->sublo[1] ||
        x[1] >= domain->subhi[1] || x[2] < domain->sublo[2] || x[2] >= domain->subhi[2])
      continue;
    atom->avec->create_atom(s.type, x);
    const int i = atom->nlocal - 1;
    atom->tag[i] = maxtag + 1 + k;
    atom->image[i] = image;
    for (int d = 0; d < 3; d++) atom->v[i][d] = atom->omega[i][d] = 0.0;
    if (s.bodies == GrainBodies::superquadrics) {  // as LIGGGHTS' `set ... shape blockiness density quat` makes it
      place_superquadric(atom, i, stand_in[shape_of[k]], s.rho, placed.orientation[k]);
      continue;
    }
    if (s.bodies == GrainBodies::spheres) {  // as LIGGGHTS' `set ... diameter D density rho` makes it
      const double r = library[shape_of[k]].shape.sweep_radius();
      atom->radius[i] = r;
      atom->rmass[i] = s.rho * 4.0 * kPi / 3.0 * r * r * r;
      if (atom->density_flag) atom->density[i] = s.rho;
      continue;
    }
    const Eigen::Quaterniond &q = placed.orientation[k];
    atom->quaternion[i][0] = q.w();
    atom->quaternion[i][1] = q.x();
    atom->quaternion[i][2] = q.y();
    atom->quaternion[i][3] = q.z();
    for (int d = 0; d < 3; d++) atom->angmom[i][d] = 0.0;
    poly->assign_shape(i, shape_of[k], s.rho);
  }
  return wiregrain_lmp::finish_created_atoms(lmp, nlocal_before);
}

// write_shapes: every created grain with its body-frame geometry (rank 0 knows them all).
void write_shapes(LAMMPS *lmp, const GrainSettings &s, const wiregrain::ShapeLibrary &library,
                  const std::vector<int> &shape_of, const wiregrain::GrainPlacement &placed, int maxtag,
                  const wiregrain_lmp::StyleArgs &args) {
  int ok = 1;
  if (lmp->comm->me == 0) {
    FILE *fp = fopen(s.shapes_file.c_str(), "w");
    if (!fp) {
      ok = 0;
    } else {
      fprintf(fp, "# create_grains shapes: %d grains; x_world = R(q) x_body + position, q = (qw qi qj qk) body -> space\n", s.n);
      fprintf(fp, "# grain tag shape sweep volume density x y z qw qi qj qk n_vertices n_faces\n");
      fprintf(fp, "# then n_vertices lines 'x y z' (body frame), n_faces lines 'k i_1 .. i_k' "
                  "(vertex indices from 0, counter-clockwise seen from outside)\n");
      for (int k = 0; k < s.n; k++) {
        const wiregrain::GrainShape &g = library[shape_of[k]];
        const Eigen::Vector3d &p = placed.position[k];
        const Eigen::Quaterniond &q = placed.orientation[k];
        fprintf(fp, "grain %d %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %d %d\n",
                maxtag + 1 + k, shape_of[k], g.shape.sweep_radius(), g.volume, s.rho, p[0], p[1], p[2], q.w(), q.x(),
                q.y(), q.z(), static_cast<int>(g.shape.vertices().size()), static_cast<int>(g.shape.faces().size()));
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
  MPI_Bcast(&ok, 1, MPI_INT, 0, lmp->world);
  if (!ok) args.fail("cannot write the 'write_shapes' file '" + s.shapes_file + "'");
}

// What was made, on screen and in the log (rank 0).
void report(LAMMPS *lmp, const GrainSettings &s, size_t n_sites, const wiregrain::GrainPlacement &placed, int maxtag,
            int library_before, int library_size, long gathered, bigint existing) {
  const bool spheres = s.bodies == GrainBodies::spheres, superquadrics = s.bodies == GrainBodies::superquadrics;
  const int n = s.n;
  char line[512];
  std::string msg = "create_grains: " + std::to_string(n) +
                    (spheres ? " spheres of the grains' volumes ("
                             : superquadrics ? " superquadrics standing in for the grains (" : " grains (") +
                    (s.layer ? "layer of " + std::to_string(n_sites) + " lattice sites" : std::string("random")) +
                    " in region " + s.region_id + "), atom IDs " + std::to_string(maxtag + 1) + ".." +
                    std::to_string(maxtag + n) +
                    (spheres || superquadrics ? std::string("\n")
                                              : ", library shapes " + std::to_string(library_before) + ".." +
                                                    std::to_string(library_size - 1) + "\n");
  if (placed.close_pairs > 0)
    snprintf(line, sizeof line,
             "create_grains: minimum gap %.17g over %ld close pairs (bounding spheres meet), %ld attempts\n",
             placed.min_gap, placed.close_pairs, placed.tries);
  else
    snprintf(line, sizeof line, "create_grains: no close pairs (bounding spheres apart), %ld attempts\n", placed.tries);
  msg += line;
  if (existing > 0) {
    snprintf(line, sizeof line, "create_grains: %ld of the %lld atoms already in the box within reach of the region\n",
             gathered, static_cast<long long>(existing));
    msg += line;
  }
  if (lmp->screen) fputs(msg.c_str(), lmp->screen);
  if (lmp->logfile) fputs(msg.c_str(), lmp->logfile);
}

}  // namespace

CreateGrains::CreateGrains(LAMMPS *lmp) : Pointers(lmp) {}

// parse → sites → shapes → placement → atoms (docs/commands/create_grains.md)
void CreateGrains::command(int narg, char **arg) {
  wiregrain_lmp::StyleArgs args(error, "command", "create_grains", "-", narg, arg, 0,
                                {"seed", "a_min", "a_max", "b_over_a", "c_over_a", "vertices", "sweep", "density", "spacing",
                                 "attempts", "blockiness", "write_shapes", "shape"});
  GrainSettings s;
  parse_positional(lmp, args, narg, s);
  parse_keywords(args, s);

  Eigen::Vector3d lo, hi;
  region_bounds(domain, s, args, lo, hi);
  std::vector<Eigen::Vector3d> sites;
  if (s.layer) sites = layer_sites(s, args, lo, hi);

  AtomVecPolyhedron *poly = AtomVecPolyhedron::of(atom);
  std::mt19937_64 rng(s.seed);
  wiregrain::ShapeLibrary own_library;
  const int library_before = poly ? poly->shapes().size() : 0;
  const wiregrain::GrainShapeDraw draw = draw_shapes(rng, s, poly, own_library, args);
  const wiregrain::ShapeLibrary &library = poly ? poly->shapes() : own_library;

  // the box of the centres to come: the region's, or a layer's sites
  Eigen::Vector3d reach_lo = lo, reach_hi = hi;
  if (s.layer && !sites.empty()) {
    reach_lo = reach_hi = sites.front();
    for (const Eigen::Vector3d &site : sites) {
      reach_lo = reach_lo.cwiseMin(site);
      reach_hi = reach_hi.cwiseMax(site);
    }
  }
  const bigint existing = atom->natoms;
  long gathered = 0;
  wiregrain::PlacementGrid grid =
      obstacle_grid(lmp, library, draw.shape_of, poly != NULL, reach_lo, reach_hi, gathered);
  const wiregrain::GrainPlacement placed = place(grid, draw, s, sites, lo, hi, rng, args);
  check_in_box(domain, placed.position, args);

  const int maxtag = wiregrain_lmp::max_atom_tag(lmp);
  if (static_cast<long>(maxtag) + s.n > MAXSMALLINT) args.fail("too many atoms: atom IDs would exceed the int range");
  std::vector<wiregrain::Superquadric> stand_in;
  if (s.bodies == GrainBodies::superquadrics) stand_in = superquadric_stand_ins(library, draw.shape_of, s, args);
  const bigint created = create_grain_atoms(lmp, s, library, draw.shape_of, placed, stand_in, maxtag);
  if (created != s.n)
    args.fail(std::to_string(s.n - created) + " of " + std::to_string(s.n) +
              " grains were not created by any rank (outside every subdomain)");
  if (!s.shapes_file.empty()) write_shapes(lmp, s, library, draw.shape_of, placed, maxtag, args);
  if (comm->me == 0) report(lmp, s, sites.size(), placed, maxtag, library_before, library.size(), gathered, existing);
}
