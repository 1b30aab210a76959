#include "grain_atoms.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "atom.h"
#include "atom_style_part.h"
#include "bead_chain_links.h"
#include "grain_shape_source.h"

#include "core/column/observables.h"
#include "core/geometry/shape_library.h"
#include "core/geometry/superquadric.h"

namespace wiregrain_lmp {

GrainAtoms::GrainAtoms(LAMMPS_NS::Atom *atom)
    : atom_(atom),
      polyhedra_(atom_style_part<const GrainShapeSource>(atom)),
      chains_(atom_style_part<const BeadChainLinks>(atom)) {}

bool GrainAtoms::available(std::string &why) const {
  if (polyhedra_ || atom_->sphere_flag || atom_->superquadric_flag) return true;
  why = "needs atom_style polyhedron, sphere (granular) or superquadric, plain or in a hybrid, not '" +
        std::string(atom_->atom_style) + "'";
  return false;
}

bool GrainAtoms::is_grain(int i) const {
  if (polyhedra_) return atom_->shapetype[i] >= 0;
  return !(chains_ && (chains_->previous_bead_tag(i) || chains_->next_bead_tag(i)));
}

bool GrainAtoms::is_polyhedron(int i) const { return polyhedra_ && atom_->shapetype[i] >= 0; }

double GrainAtoms::top(int i) const {
  const double *x = atom_->x[i];
  if (!polyhedra_ && atom_->superquadric_flag) {  // its support point along +z
    wiregrain::Superquadric shape;
    shape.half_axes = Eigen::Vector3d(atom_->shape[i][0], atom_->shape[i][1], atom_->shape[i][2]);
    shape.n1 = atom_->blockiness[i][0];
    shape.n2 = atom_->blockiness[i][1];
    const double *q = atom_->quaternion[i];
    return wiregrain::PosedSuperquadric(shape, Eigen::Vector3d(x[0], x[1], x[2]),
                                        Eigen::Quaterniond(q[0], q[1], q[2], q[3]))
        .support(Eigen::Vector3d::UnitZ())
        .z();
  }
  if (!polyhedra_) return x[2] + atom_->radius[i];
  const double *q = atom_->quaternion[i];
  const wiregrain::PosedShape grain(polyhedra_->shapes()[atom_->shapetype[i]].shape, Eigen::Vector3d(x[0], x[1], x[2]),
                                    Eigen::Quaterniond(q[0], q[1], q[2], q[3]));
  return wiregrain::grain_top(grain);
}

}  // namespace wiregrain_lmp
