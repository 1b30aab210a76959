#include "atom_vec_polyhedron.h"

#include <mpi.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "atom.h"
#include "atom_vec_hybrid.h"
#include "comm.h"
#include "error.h"

#include "core/common/errors.h"
#include "core/geometry/shape_library.h"
#include "plugin_args.h"

using namespace LAMMPS_NS;

namespace {
Eigen::Quaterniond orientation(const double *q) { return Eigen::Quaterniond(q[0], q[1], q[2], q[3]); }
}  // namespace

// The per-grain arrays and the buffers they travel in (common/plugin_atom_vec.h). These
// lists fix the layout of restart records: a restart file is read with the lists it was
// written with.
AtomVecPolyhedron::AtomVecPolyhedron(LAMMPS *lmp)
    : PluginAtomVec(lmp, "polyhedron"), library_(new wiregrain::ShapeLibrary(wiregrain::MassModel::dilated)) {
  atom->radius_flag = atom->rmass_flag = atom->omega_flag = atom->torque_flag = atom->angmom_flag = 1;
  atom->density_flag = 1;
  radius = rmass = density = NULL;
  omega = angmom = torque = quat = inertia = NULL;
  shape = NULL;

  add_field("radius", &atom->radius, &radius);
  add_field("rmass", &atom->rmass, &rmass);
  add_field("density", &atom->density, &density);
  add_field("omega", &atom->omega, 3, &omega);
  add_field("angmom", &atom->angmom, 3, &angmom);
  add_per_thread_field("torque", &atom->torque, 3, &torque);
  add_field("quaternion", &atom->quaternion, 4, &quat);
  add_field("inertia", &atom->inertia, 3, &inertia);
  add_field("shapetype", &atom->shapetype, &shape);
  lists_.comm = fields({"quaternion"});
  lists_.comm_vel = fields({"omega"});
  lists_.reverse = fields({"torque"});
  lists_.border = fields({"radius", "rmass", "density", "shapetype", "quaternion", "inertia"});
  lists_.border_vel = fields({"omega"});
  lists_.record = fields({"omega", "angmom"});
  lists_.data_atom = fields({"shapetype", "density", "quaternion"});
  lists_.data_vel = fields({"omega"});
  fields_declared();
}

AtomVecPolyhedron::~AtomVecPolyhedron() {}

AtomVecPolyhedron *AtomVecPolyhedron::of(Atom *atom) {
  if (AtomVecPolyhedron *p = dynamic_cast<AtomVecPolyhedron *>(atom->avec)) return p;
  if (AtomVecHybrid *h = dynamic_cast<AtomVecHybrid *>(atom->avec))
    for (int k = 0; k < h->nstyles; k++)
      if (AtomVecPolyhedron *p = dynamic_cast<AtomVecPolyhedron *>(h->styles[k])) return p;
  return NULL;
}

void AtomVecPolyhedron::settings(int narg, char **arg) {
  wiregrain_lmp::StyleArgs args(error, "atom_style", "polyhedron", "", narg, arg, 0, {"mass"});
  while (!args.done()) {
    const std::string key = args.next_keyword();
    const std::string value = args.value_word(key);
    if (value == "dilated") library_.reset(new wiregrain::ShapeLibrary(wiregrain::MassModel::dilated));
    else if (value == "sharp")
      library_.reset(new wiregrain::ShapeLibrary(wiregrain::MassModel::sharp_polyhedron));
    else
      args.fail("value of 'mass' must be dilated or sharp, got '" + value + "'");
  }
  // fix nscd/polyhedra and fix wire/grain find grains by tag: the array map unless the user
  // chose one (atom_modify map hash). Called by read_restart too, which does not keep the
  // map style: a deck continuing a restart without atom_modify map would have no map, and
  // the fix would find none of its grains when it hands back their new velocities.
  if (atom->map_style == 0) atom->map_style = 1;
}

// The shape library goes to restart files with the atom style: its size, then the
// serialised doubles (core/shape_library.h).
void AtomVecPolyhedron::write_restart_settings(FILE *fp) {
  const std::vector<double> data = library_->serialize();
  const long n = static_cast<long>(data.size());
  fwrite(&n, sizeof(long), 1, fp);
  fwrite(data.data(), sizeof(double), data.size(), fp);
}

// Called on every rank with fp open on rank 0 only.
void AtomVecPolyhedron::read_restart_settings(FILE *fp) {
  long n = 0;
  if (comm->me == 0 && fread(&n, sizeof(long), 1, fp) != 1)
    error->one(FLERR, "atom_style polyhedron: restart file is truncated (shape library)");
  MPI_Bcast(&n, 1, MPI_LONG, 0, world);
  std::vector<double> data(n);
  if (comm->me == 0 && fread(data.data(), sizeof(double), n, fp) != (size_t)n)
    error->one(FLERR, "atom_style polyhedron: restart file is truncated (shape library)");
  MPI_Bcast(data.data(), (int)n, MPI_DOUBLE, 0, world);
  try {
    library_.reset(new wiregrain::ShapeLibrary(wiregrain::ShapeLibrary::deserialize(data)));
  } catch (const wiregrain::InvalidArgument &e) {
    error->all(FLERR, (std::string("atom_style polyhedron: ") + e.what()).c_str());
  }
}

// A grain made by create_atoms or a stock insertion fix has no shape yet (shape −1,
// unit mass and inertia); styles that need a shape stop on it.
void AtomVecPolyhedron::create_atom_defaults(int i) {
  for (int d = 0; d < 3; d++) inertia[i][d] = 1.0;
  quat[i][0] = 1.0;
  radius[i] = 0.5;
  rmass[i] = density[i] = 1.0;
  shape[i] = -1;
}

int AtomVecPolyhedron::add_shape(const wiregrain::ConvexShape &s, double body_to_input[4], double centroid[3]) {
  wiregrain::ShapeLibrary::Placement placement;
  const int index = library_->add(s, &placement);
  if (body_to_input) {
    body_to_input[0] = placement.rotation.w();
    body_to_input[1] = placement.rotation.x();
    body_to_input[2] = placement.rotation.y();
    body_to_input[3] = placement.rotation.z();
  }
  if (centroid)
    for (int d = 0; d < 3; d++) centroid[d] = placement.centroid[d];
  return index;
}

void AtomVecPolyhedron::replace_shapes(wiregrain::ShapeLibrary library) {
  library_.reset(new wiregrain::ShapeLibrary(std::move(library)));
}

void AtomVecPolyhedron::release_shapes_of_absent_grains() {
  std::vector<char> present(library_->size(), 0);
  for (int i = 0; i < atom->nlocal + atom->nghost; i++)
    if (shape[i] >= 0 && shape[i] < library_->size()) present[shape[i]] = 1;
  library_->release_built_except(present);
}

void AtomVecPolyhedron::assign_shape(int i, int s, double rho) {
  const wiregrain::GrainShape &g = (*library_)[s];
  shape[i] = s;
  density[i] = rho;
  rmass[i] = rho * g.volume;
  for (int d = 0; d < 3; d++) inertia[i][d] = rho * g.unit_inertia[d];
  radius[i] = g.bounding_radius;
}

int AtomVecPolyhedron::count_without_shape(int groupbit) {
  int local = 0, global = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && shape[i] < 0) local++;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_SUM, world);
  return global;
}

// L = R I Rᵀ ω (space frame), R the grain's rotation body → space.
void AtomVecPolyhedron::angmom_from_omega(int i) {
  const Eigen::Matrix3d r = orientation(quat[i]).normalized().toRotationMatrix();
  const Eigen::Vector3d w(omega[i][0], omega[i][1], omega[i][2]);
  const Eigen::Vector3d body = r.transpose() * w;
  const Eigen::Vector3d l = r * Eigen::Vector3d(inertia[i][0] * body.x(), inertia[i][1] * body.y(), inertia[i][2] * body.z());
  for (int d = 0; d < 3; d++) angmom[i][d] = l[d];
}

void AtomVecPolyhedron::omega_from_angmom(int i) {
  const Eigen::Matrix3d r = orientation(quat[i]).normalized().toRotationMatrix();
  const Eigen::Vector3d l(angmom[i][0], angmom[i][1], angmom[i][2]);
  const Eigen::Vector3d body = r.transpose() * l;
  const Eigen::Vector3d w = r * Eigen::Vector3d(body.x() / inertia[i][0], body.y() / inertia[i][1], body.z() / inertia[i][2]);
  for (int d = 0; d < 3; d++) omega[i][d] = w[d];
}

// shape −1: an atom that is not a grain (a wire bead in atom_style hybrid polyhedron wire,
// as write_data writes it); its polyhedron values are those of create_atom.
int AtomVecPolyhedron::data_atom_hybrid(int nlocal, char **values) {
  char *end = NULL;
  const long s = std::strtol(values[0], &end, 10);
  if (end != values[0] && *end == '\0' && s == -1 && atom->avec != this) {
    shape[nlocal] = -1;
    density[nlocal] = 1.0;
    quat[nlocal][0] = 1.0;
    quat[nlocal][1] = quat[nlocal][2] = quat[nlocal][3] = 0.0;
    for (int d = 0; d < 3; d++) inertia[nlocal][d] = 1.0;
    return 6;
  }
  if (end == values[0] || *end != '\0' || s < 0 || s >= library_->size())
    data_error("Atoms", std::string("shape '") + values[0] + "' is not in the shape library (" +
                          std::to_string(library_->size()) + " shapes; a library comes from create_grains or a restart file)");
  double rho = 0.0;
  if (!wiregrain_lmp::parse_finite_number(values[1], rho) || !(rho > 0.0))
    data_error("Atoms", std::string("density must be a finite number > 0, got '") + values[1] + "'");
  double q[4];
  for (int d = 0; d < 4; d++) q[d] = data_number(values[2 + d], std::string("q") + "wijk"[d], "Atoms");
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(norm > 0.0)) data_error("Atoms", "the quaternion qw qi qj qk must not be zero");
  for (int d = 0; d < 4; d++) quat[nlocal][d] = q[d] / norm;
  assign_shape(nlocal, (int)s, rho);
  return 6;
}

int AtomVecPolyhedron::data_vel_hybrid(int m, char **values) {
  for (int d = 0; d < 3; d++)
    omega[m][d] =
        data_number(values[d], "omega" + std::string(1, "xyz"[d]) + " of atom " + std::to_string(tag[m]), "Velocities");
  angmom_from_omega(m);
  return 3;
}

