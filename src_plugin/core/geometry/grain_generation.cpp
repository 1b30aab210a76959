// New grains' shapes and orientations from a seeded stream. See grain_generation.h.
#include "core/geometry/grain_generation.h"

#include <cmath>

#include "core/common/constants.h"

namespace wiregrain {

Eigen::Quaterniond random_orientation(std::mt19937_64& rng) {
  const double u1 = uniform01(rng), u2 = uniform01(rng), u3 = uniform01(rng);
  const double s1 = std::sqrt(1.0 - u1), s2 = std::sqrt(u1);
  const double t1 = 2.0 * kPi * u2, t2 = 2.0 * kPi * u3;
  return Eigen::Quaterniond(s2 * std::cos(t2), s1 * std::sin(t1), s1 * std::cos(t1), s2 * std::sin(t2));
}

namespace {

// the one shape of a kind other than ellipsoid
ConvexShape given_shape(const GrainShapeRecipe& recipe) {
  const double* L = recipe.size;
  const double sweep = recipe.sweep;
  if (recipe.kind == "cube") return ConvexShape::cube(L[0], sweep);
  if (recipe.kind == "box") return ConvexShape::box(L[0], L[1], L[2], sweep);
  if (recipe.kind == "tetrahedron") return ConvexShape::regular_tetrahedron(L[0], sweep);
  if (recipe.kind == "octahedron") return ConvexShape::regular_octahedron(L[0], sweep);
  if (recipe.kind == "sphere") return ConvexShape::sphere(L[0]);
  return ConvexShape::from_vertex_file(recipe.path, sweep);
}

}  // namespace

GrainShapeDraw draw_grain_shapes(std::mt19937_64& rng, const GrainShapeRecipe& recipe, int n,
                                 const AddGrainShape& add) {
  GrainShapeDraw draw;
  draw.shape_of.resize(n);
  draw.body_to_input.resize(n);
  if (recipe.kind == "ellipsoid") {
    for (int k = 0; k < n; k++) {
      const double a = recipe.a_min + (recipe.a_max - recipe.a_min) * uniform01(rng);
      const ConvexShape s =
          ConvexShape::random_ellipsoid(rng, recipe.n_vertices, a, recipe.b_over_a, recipe.c_over_a, recipe.sweep);
      draw.shape_of[k] = add(s, draw.body_to_input[k]);
    }
    return draw;
  }
  Eigen::Quaterniond q;
  const int index = add(given_shape(recipe), q);
  for (int k = 0; k < n; k++) {
    draw.shape_of[k] = index;
    draw.body_to_input[k] = q;
  }
  return draw;
}

void replace_by_spheres_of_volume(ShapeLibrary& library, std::vector<int>& shape_of) {
  const int generated = library.size();
  std::vector<int> sphere_of(generated);
  for (int s = 0; s < generated; s++) {
    const double radius = std::cbrt(3.0 * library[s].volume / (4.0 * kPi));
    sphere_of[s] = library.add(ConvexShape::sphere(radius));
  }
  for (int& shape : shape_of) shape = sphere_of[shape];
}

}  // namespace wiregrain
