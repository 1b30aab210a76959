#include "fix_nve_polyhedron.h"

#include <mpi.h>

#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include "atom.h"
#include "atom_vec_polyhedron.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "update.h"

#include "core/nscd/rigid_body.h"
#include "atom_kinds.h"
#include "plugin_args.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixNVEPolyhedron::FixNVEPolyhedron(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg), fourth_order_(false), grains_(NULL) {
  wiregrain_lmp::StyleArgs args(error, "fix", "nve/polyhedron", id, narg, arg, 3, {"rotation"});
  grains_ = AtomVecPolyhedron::of(atom);
  if (!grains_)
    args.fail("needs atom_style polyhedron (or hybrid with polyhedron), not '" + std::string(atom->atom_style) + "'");
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "rotation") {
      const std::string v = args.value_word(key);
      if (v == "splitting2") fourth_order_ = false;
      else if (v == "splitting4") fourth_order_ = true;
      else args.fail("value of 'rotation' must be splitting2 or splitting4, got '" + v + "'");
    } else {
      args.unknown_keyword(key);
    }
  }
  time_integrate = 1;
}

int FixNVEPolyhedron::setmask() { return INITIAL_INTEGRATE | FINAL_INTEGRATE; }

void FixNVEPolyhedron::init() {
  wiregrain_lmp::require_no_beads(lmp, igroup, "fix", "nve/polyhedron", id);
  wiregrain_lmp::ensure_sole_integrator(lmp, this, "fix", "nve/polyhedron", "grains");
  const int missing = grains_->count_without_shape(groupbit);
  if (missing)
    wiregrain_lmp::style_error(error, "fix", "nve/polyhedron", id,
                               std::to_string(missing) + " grains have no shape (made by create_atoms?"
                               " use create_grains)");
}

// start consistent: the angular velocity of each grain from its angular momentum,
// ω = R I⁻¹ Rᵀ L (L is the state the integration advances)
void FixNVEPolyhedron::setup(int /*vflag*/) {
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) grains_->omega_from_angmom(i);
}

void FixNVEPolyhedron::initial_integrate(int /*vflag*/) {
  const double dt = update->dt;
  const auto scheme = fourth_order_ ? wiregrain::FreeRotationScheme::splitting4
                                    : wiregrain::FreeRotationScheme::splitting2;
  double **x = atom->x, **v = atom->v, **f = atom->f, **torque = atom->torque;
  double **angmom = atom->angmom, **quat = atom->quaternion, **inertia = atom->inertia;
  const double *rmass = atom->rmass;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double half = 0.5 * dt * force->ftm2v / rmass[i];
    for (int d = 0; d < 3; d++) {
      v[i][d] += half * f[i][d];
      x[i][d] += dt * v[i][d];
    }
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
    Eigen::Vector3d l = Eigen::Vector3d::Zero();
    try {  // the core refuses non-finite inertia, orientation or time step: an ERROR, not std::terminate
      wiregrain::RigidRotation body(Eigen::Vector3d(inertia[i][0], inertia[i][1], inertia[i][2]),
                                    Eigen::Quaterniond(quat[i][0], quat[i][1], quat[i][2], quat[i][3]),
                                    Eigen::Vector3d(angmom[i][0], angmom[i][1], angmom[i][2]));
      body.kick(Eigen::Vector3d(torque[i][0], torque[i][1], torque[i][2]), 0.5 * dt * force->ftm2v);
      body.rotate_free(dt, scheme);
      q = body.orientation();
      l = body.angular_momentum();
    } catch (const std::exception &e) {
      error->one(FLERR, ("fix nve/polyhedron (id " + std::string(id) + "): grain " + std::to_string(atom->tag[i]) +
                         " at step " + std::to_string(update->ntimestep) + ": " + e.what())
                            .c_str());
    }
    quat[i][0] = q.w();
    quat[i][1] = q.x();
    quat[i][2] = q.y();
    quat[i][3] = q.z();
    for (int d = 0; d < 3; d++) angmom[i][d] = l[d];
    grains_->omega_from_angmom(i);
  }
}

void FixNVEPolyhedron::final_integrate() {
  const double dt = update->dt;
  double **v = atom->v, **f = atom->f, **torque = atom->torque, **angmom = atom->angmom;
  const double *rmass = atom->rmass;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double half = 0.5 * dt * force->ftm2v / rmass[i];
    for (int d = 0; d < 3; d++) {
      v[i][d] += half * f[i][d];
      angmom[i][d] += 0.5 * dt * force->ftm2v * torque[i][d];
    }
    grains_->omega_from_angmom(i);
  }
}
