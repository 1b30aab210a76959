// Placing new grains without overlaps. See grain_placement.h.
#include "core/geometry/grain_placement.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/grain_generation.h"

namespace wiregrain {

PlacementObstacle PlacementObstacle::grain(const ShapeLibrary& library, int shape, const Eigen::Vector3d& x,
                                           const Eigen::Quaterniond& q) {
  PlacementObstacle b;
  b.x = x;
  b.shape = shape;
  b.bound = library[shape].bounding_radius;
  b.sweep = library[shape].shape.sweep_radius();
  b.posed.reset(new PosedShape(library[shape].shape, x, q));
  return b;
}

PlacementObstacle PlacementObstacle::sphere(const Eigen::Vector3d& centre, double radius) {
  PlacementObstacle b;
  b.x = centre;
  b.shape = kSphere;
  b.bound = b.sweep = radius;
  return b;
}

PlacementObstacle PlacementObstacle::segment(const Eigen::Vector3d& start, const Eigen::Vector3d& to_end,
                                             double radius) {
  PlacementObstacle b;
  b.shape = kSegment;
  b.half = 0.5 * to_end;
  b.x = start + b.half;
  b.sweep = radius;
  b.bound = b.half.norm() + b.sweep;
  return b;
}

PlacementGrid::PlacementGrid(const ShapeLibrary& library, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                             const std::array<bool, 3>& periodic, double max_bound)
    : library_(library), grid_(BroadPhaseGrid::box(lo, hi, periodic, 2.0 * max_bound)) {}

void PlacementGrid::add(PlacementObstacle body) {
  grid_.insert(body.x);
  bodies_.push_back(std::move(body));
}

bool PlacementGrid::overlaps(const PosedShape& c, double bound, double& min_gap, long& pairs) const {
  min_gap = std::numeric_limits<double>::infinity();
  pairs = 0;
  bool overlapping = false;
  grid_.for_each_near(c.position(), [&](int b, const Eigen::Vector3d& shift) {
    if (overlapping) return;
    const PlacementObstacle& body = bodies_[b];
    const Eigen::Vector3d d = (body.x - c.position()) + shift;  // minimum image
    const bool shifted_image = shift != Eigen::Vector3d::Zero();
    const Eigen::Vector3d image = c.position() + d;
    const double reach = bound + body.bound;
    if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > reach * reach) return;
    double gap;
    if (body.shape == PlacementObstacle::kSegment) {
      gap = segment_contact(c, image - body.half, image + body.half, body.sweep).gap;
    } else if (body.shape < 0) {
      gap = segment_contact(c, image, image, body.sweep).gap;
    } else if (!shifted_image) {
      gap = core_distance(c, *body.posed).distance - c.sweep_radius() - body.sweep;
    } else {
      const PosedShape shifted(library_[body.shape].shape, image, body.posed->orientation());
      gap = core_distance(c, shifted).distance - c.sweep_radius() - body.sweep;
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

LayerLattice::LayerLattice(double x_lo, double x_hi, double y_lo, double y_hi, double spacing)
    : lo_{x_lo, y_lo}, spacing_(spacing) {
  const double hi[2] = {x_hi, y_hi};
  for (int d = 0; d < 2; d++) {
    const double length = hi[d] - lo_[d];
    cells_[d] = static_cast<long>(std::floor(length / spacing + 1e-9));
    margin_[d] = 0.5 * (length - cells_[d] * spacing);
  }
}

std::vector<Eigen::Vector3d> LayerLattice::sites(double z0, double rise,
                                                 const std::function<bool(const Eigen::Vector3d&)>& inside) const {
  std::vector<Eigen::Vector3d> sites;
  for (int lattice = 0; lattice < 2; lattice++) {
    const double z = lattice == 0 ? z0 : z0 + rise;
    const double shift = lattice == 0 ? 0.5 * spacing_ : spacing_;
    for (long j = 0; j < cells_[1] - lattice; j++) {
      const double y = lo_[1] + (margin_[1] + shift) + j * spacing_;
      for (long i = 0; i < cells_[0] - lattice; i++) {
        const double x = lo_[0] + (margin_[0] + shift) + i * spacing_;
        const Eigen::Vector3d site(x, y, z);
        if (inside(site)) sites.push_back(site);
      }
    }
  }
  return sites;
}

GrainPlacement place_grains(PlacementGrid& grid, const std::vector<int>& shape_of,
                            const std::vector<Eigen::Quaterniond>& body_to_input, const GrainSites& where,
                            long attempts, std::mt19937_64& rng) {
  const int n = static_cast<int>(shape_of.size());
  GrainPlacement out;
  out.position.resize(n);
  out.orientation.resize(n);
  out.min_gap = std::numeric_limits<double>::infinity();
  for (int k = 0; k < n; k++) {
    const GrainShape& g = grid.library()[shape_of[k]];
    bool placed = false;
    for (long attempt = 0; attempt < attempts && !placed; attempt++) {
      out.tries++;
      Eigen::Vector3d p;
      if (where.layer) {
        p = where.sites[k];
      } else {
        for (int d = 0; d < 3; d++) p[d] = where.lo[d] + (where.hi[d] - where.lo[d]) * uniform01(rng);
      }
      const Eigen::Quaterniond q = (random_orientation(rng) * body_to_input[k]).normalized();
      if (!where.layer && !where.inside(p)) continue;
      const PosedShape candidate(g.shape, p, q);
      double gap;
      long pairs;
      if (grid.overlaps(candidate, g.bounding_radius, gap, pairs)) continue;
      placed = true;
      out.min_gap = std::min(out.min_gap, gap);
      out.close_pairs += pairs;
      out.position[k] = p;
      out.orientation[k] = candidate.orientation();
      grid.add(PlacementObstacle::grain(grid.library(), shape_of[k], p, q));
    }
    if (!placed) {
      out.unplaced = k;
      return out;
    }
  }
  return out;
}

}  // namespace wiregrain
