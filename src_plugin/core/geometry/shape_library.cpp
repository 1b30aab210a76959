#include "core/geometry/shape_library.h"

#include <cmath>
#include <utility>

#include "core/common/errors.h"

namespace wiregrain {

void ShapeLibrary::append_body_frame(ConvexShape body, bool keep) {
  Entry e;
  const MassProperties m = body.mass_properties(1.0, model_);
  e.sweep_radius = body.sweep_radius();
  e.vertices = body.vertices();
  e.volume = m.volume;
  e.unit_inertia = m.inertia.diagonal();
  e.bounding_radius = body.bounding_radius();
  if (keep) e.built = std::make_shared<const GrainShape>(GrainShape{std::move(body), e.volume, e.unit_inertia,
                                                                    e.bounding_radius});
  entries_.push_back(std::move(e));
}

const GrainShape& ShapeLibrary::build(int index) const {
  const Entry& e = entries_[index];
  // kept as a copy made once the hull's temporaries are freed: the copy's storage is
  // packed, where the built shape's own lies among the temporaries' (for 10^4 shapes
  // 34 MiB more at the peak)
  const ConvexShape shape = ConvexShape::from_points(e.vertices, e.sweep_radius);
  e.built = std::make_shared<const GrainShape>(GrainShape{shape, e.volume, e.unit_inertia, e.bounding_radius});
  return *e.built;
}

int ShapeLibrary::built_count() const {
  int n = 0;
  for (const Entry& e : entries_) n += e.built ? 1 : 0;
  return n;
}

void ShapeLibrary::release_built_except(const std::vector<char>& needed) {
  for (std::size_t s = 0; s < entries_.size(); ++s)
    if (s >= needed.size() || !needed[s]) entries_[s].built.reset();
}

int ShapeLibrary::add(const ConvexShape& shape, Placement* placement) {
  const BodyFrameShape body = to_body_frame(shape, 1.0, model_);
  if (placement) {
    placement->rotation = body.rotation;
    placement->centroid = body.centroid;
  }
  append_body_frame(body.shape, true);
  return size() - 1;
}

std::vector<double> ShapeLibrary::serialize() const {
  std::vector<double> out{model_ == MassModel::dilated ? 1.0 : 0.0, double(entries_.size())};
  for (const Entry& e : entries_) {
    out.push_back(e.sweep_radius);
    out.push_back(double(e.vertices.size()));
    for (const Eigen::Vector3d& v : e.vertices) out.insert(out.end(), {v.x(), v.y(), v.z()});
  }
  return out;
}

ShapeLibrary ShapeLibrary::deserialize(const std::vector<double>& data) {
  const auto fail = [] { throw InvalidArgument("shape library", "shape library data is truncated or corrupt"); };
  if (data.size() < 2) fail();
  ShapeLibrary library(data[0] != 0.0 ? MassModel::dilated : MassModel::sharp_polyhedron);
  const long count = std::lround(data[1]);
  // the records first, then each shape built once for its mass properties and dropped: the
  // builds' memory is reused from one shape to the next instead of scattered among the
  // records
  std::vector<std::pair<double, std::vector<Eigen::Vector3d>>> records(count);
  std::size_t k = 2;
  for (long s = 0; s < count; ++s) {
    if (k + 2 > data.size()) fail();
    const double sweep = data[k++];
    const long n = std::lround(data[k++]);
    // one vertex (a sphere) or a hull of at least 4
    if ((n != 1 && n < 4) || k + 3 * std::size_t(n) > data.size()) fail();
    records[s].first = sweep;
    records[s].second.reserve(n);
    for (long v = 0; v < n; ++v, k += 3) records[s].second.emplace_back(data[k], data[k + 1], data[k + 2]);
  }
  library.entries_.resize(count);
  for (long s = 0; s < count; ++s) {
    const ConvexShape shape = ConvexShape::from_points(records[s].second, records[s].first);
    Entry& e = library.entries_[s];
    const MassProperties m = shape.mass_properties(1.0, library.model_);
    e.sweep_radius = shape.sweep_radius();
    e.vertices = std::move(records[s].second);
    if (e.vertices.size() != shape.vertices().size()) e.vertices = shape.vertices();  // points inside the hull dropped
    e.volume = m.volume;
    e.unit_inertia = m.inertia.diagonal();
    e.bounding_radius = shape.bounding_radius();
  }
  return library;
}

}  // namespace wiregrain
