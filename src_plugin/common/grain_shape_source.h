/* An atom style whose atoms are grains of a shape library (atom_style polyhedron): atom i
   is a grain of shape shapes()[atom->shapetype[i]] when atom->shapetype[i] >= 0 (a
   negative index: an atom without a shape). common/grain_atoms reads the grains through
   this interface (found with atom_style_part.h), not through the style's class. */

#ifndef WIREGRAIN_GRAIN_SHAPE_SOURCE_H
#define WIREGRAIN_GRAIN_SHAPE_SOURCE_H

// declared in core/geometry/shape_library.h (not included: style headers need no Eigen)
namespace wiregrain {
class ShapeLibrary;
}

namespace wiregrain_lmp {

class GrainShapeSource {
 public:
  virtual ~GrainShapeSource() = default;
  // the shape library, identical on every rank
  virtual const wiregrain::ShapeLibrary &shapes() const = 0;
};

}  // namespace wiregrain_lmp

#endif
