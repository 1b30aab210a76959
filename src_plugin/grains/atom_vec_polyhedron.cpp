#include "atom_vec_polyhedron.h"

#include <mpi.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "atom.h"
#include "atom_vec_hybrid.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "memory.h"
#include "modify.h"

#include "core/common/errors.h"
#include "core/geometry/shape_library.h"
#include "plugin_args.h"
#include "plugin_comm.h"

using namespace LAMMPS_NS;

namespace {
constexpr int kDelta = 10000;
// values a ghost needs besides its position:
// tag type mask radius rmass density shape quat(4) inertia(3)
constexpr int kGrainValues = 14;
// per grain in exchange and restart records, besides the leading count:
// x v image omega angmom + the ghost values
constexpr int kRecordValues = 13 + kGrainValues;

Eigen::Quaterniond orientation(const double *q) { return Eigen::Quaterniond(q[0], q[1], q[2], q[3]); }
}  // namespace

AtomVecPolyhedron::AtomVecPolyhedron(LAMMPS *lmp)
    : PluginAtomVec(lmp), library_(new wiregrain::ShapeLibrary(wiregrain::MassModel::dilated)) {
  molecular = 0;
  comm_x_only = 0;
  comm_f_only = 0;
  size_forward = 7;    // x, quaternion
  size_reverse = 6;    // f, torque
  size_border = 3 + kGrainValues;
  size_velocity = 6;   // v, omega
  size_data_atom = 11;
  size_data_vel = 7;
  xcol_data = 9;

  atom->radius_flag = atom->rmass_flag = atom->omega_flag = atom->torque_flag = atom->angmom_flag = 1;
  atom->density_flag = 1;
  shape = NULL;
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

void AtomVecPolyhedron::grow(int n) {
  if (n == 0) nmax += kDelta;
  else nmax = n;
  atom->nmax = nmax;
  if (nmax < 0 || nmax > MAXSMALLINT) error->one(FLERR, "atom_style polyhedron: per-processor system is too big");

  tag = memory->grow(atom->tag, nmax, "atom:tag");
  type = memory->grow(atom->type, nmax, "atom:type");
  mask = memory->grow(atom->mask, nmax, "atom:mask");
  image = memory->grow(atom->image, nmax, "atom:image");
  x = memory->grow(atom->x, nmax, 3, "atom:x");
  v = memory->grow(atom->v, nmax, 3, "atom:v");
  f = memory->grow(atom->f, nmax * comm->nthreads, 3, "atom:f");
  radius = memory->grow(atom->radius, nmax, "atom:radius");
  rmass = memory->grow(atom->rmass, nmax, "atom:rmass");
  density = memory->grow(atom->density, nmax, "atom:density");
  omega = memory->grow(atom->omega, nmax, 3, "atom:omega");
  angmom = memory->grow(atom->angmom, nmax, 3, "atom:angmom");
  torque = memory->grow(atom->torque, nmax * comm->nthreads, 3, "atom:torque");
  quat = memory->grow(atom->quaternion, nmax, 4, "atom:quaternion");
  inertia = memory->grow(atom->inertia, nmax, 3, "atom:inertia");
  shape = memory->grow(atom->shapetype, nmax, "atom:shapetype");

  if (atom->nextra_grow)
    for (int iextra = 0; iextra < atom->nextra_grow; iextra++)
      modify->fix[atom->extra_grow[iextra]]->grow_arrays(nmax);
}

void AtomVecPolyhedron::grow_reset() {
  tag = atom->tag;
  type = atom->type;
  mask = atom->mask;
  image = atom->image;
  x = atom->x;
  v = atom->v;
  f = atom->f;
  radius = atom->radius;
  rmass = atom->rmass;
  density = atom->density;
  omega = atom->omega;
  angmom = atom->angmom;
  torque = atom->torque;
  quat = atom->quaternion;
  inertia = atom->inertia;
  shape = atom->shapetype;
}

void AtomVecPolyhedron::copy(int i, int j, int delflag) {
  tag[j] = tag[i];
  type[j] = type[i];
  mask[j] = mask[i];
  image[j] = image[i];
  for (int d = 0; d < 3; d++) {
    x[j][d] = x[i][d];
    v[j][d] = v[i][d];
    omega[j][d] = omega[i][d];
    angmom[j][d] = angmom[i][d];
    inertia[j][d] = inertia[i][d];
  }
  for (int d = 0; d < 4; d++) quat[j][d] = quat[i][d];
  radius[j] = radius[i];
  rmass[j] = rmass[i];
  density[j] = density[i];
  shape[j] = shape[i];

  if (atom->nextra_grow)
    for (int iextra = 0; iextra < atom->nextra_grow; iextra++)
      modify->fix[atom->extra_grow[iextra]]->copy_arrays(i, j, delflag);
}

int AtomVecPolyhedron::pack_comm(int n, int *list, double *buf, int pbc_flag, int *pbc) {
  double s[3];
  wiregrain_lmp::periodic_image_shift(domain, pbc_flag, pbc, false, s);
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    for (int d = 0; d < 3; d++) buf[m++] = x[j][d] + s[d];
    for (int d = 0; d < 4; d++) buf[m++] = quat[j][d];
  }
  return m;
}

int AtomVecPolyhedron::pack_comm_vel(int n, int *list, double *buf, int pbc_flag, int *pbc) {
  double s[3], dv[3];
  wiregrain_lmp::periodic_image_shift(domain, pbc_flag, pbc, false, s);
  wiregrain_lmp::deforming_image_velocity(pbc_flag, pbc, deform_vremap, h_rate, dv);
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    const bool remap = pbc_flag && deform_vremap && (mask[j] & deform_groupbit);
    for (int d = 0; d < 3; d++) buf[m++] = x[j][d] + s[d];
    for (int d = 0; d < 4; d++) buf[m++] = quat[j][d];
    for (int d = 0; d < 3; d++) buf[m++] = v[j][d] + (remap ? dv[d] : 0.0);
    for (int d = 0; d < 3; d++) buf[m++] = omega[j][d];
  }
  return m;
}

int AtomVecPolyhedron::pack_comm_hybrid(int n, int *list, double *buf) {
  int m = 0;
  for (int i = 0; i < n; i++)
    for (int d = 0; d < 4; d++) buf[m++] = quat[list[i]][d];
  return m;
}

void AtomVecPolyhedron::unpack_comm(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++) {
    for (int d = 0; d < 3; d++) x[i][d] = buf[m++];
    for (int d = 0; d < 4; d++) quat[i][d] = buf[m++];
  }
}

void AtomVecPolyhedron::unpack_comm_vel(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++) {
    for (int d = 0; d < 3; d++) x[i][d] = buf[m++];
    for (int d = 0; d < 4; d++) quat[i][d] = buf[m++];
    for (int d = 0; d < 3; d++) v[i][d] = buf[m++];
    for (int d = 0; d < 3; d++) omega[i][d] = buf[m++];
  }
}

int AtomVecPolyhedron::unpack_comm_hybrid(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int d = 0; d < 4; d++) quat[i][d] = buf[m++];
  return m;
}

int AtomVecPolyhedron::pack_reverse(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++) {
    for (int d = 0; d < 3; d++) buf[m++] = f[i][d];
    for (int d = 0; d < 3; d++) buf[m++] = torque[i][d];
  }
  return m;
}

int AtomVecPolyhedron::pack_reverse_hybrid(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int d = 0; d < 3; d++) buf[m++] = torque[i][d];
  return m;
}

void AtomVecPolyhedron::unpack_reverse(int n, int *list, double *buf) {
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    for (int d = 0; d < 3; d++) f[j][d] += buf[m++];
    for (int d = 0; d < 3; d++) torque[j][d] += buf[m++];
  }
}

int AtomVecPolyhedron::unpack_reverse_hybrid(int n, int *list, double *buf) {
  int m = 0;
  for (int i = 0; i < n; i++)
    for (int d = 0; d < 3; d++) torque[list[i]][d] += buf[m++];
  return m;
}

int AtomVecPolyhedron::pack_ghost(int j, double *buf) const {
  int m = 0;
  buf[m++] = ubuf(tag[j]).d;
  buf[m++] = ubuf(type[j]).d;
  buf[m++] = ubuf(mask[j]).d;
  buf[m++] = radius[j];
  buf[m++] = rmass[j];
  buf[m++] = density[j];
  buf[m++] = ubuf(shape[j]).d;
  for (int d = 0; d < 4; d++) buf[m++] = quat[j][d];
  for (int d = 0; d < 3; d++) buf[m++] = inertia[j][d];
  return m;
}

int AtomVecPolyhedron::unpack_ghost(int i, const double *buf) {
  int m = 0;
  tag[i] = (int)ubuf(buf[m++]).i;
  type[i] = (int)ubuf(buf[m++]).i;
  mask[i] = (int)ubuf(buf[m++]).i;
  radius[i] = buf[m++];
  rmass[i] = buf[m++];
  density[i] = buf[m++];
  shape[i] = (int)ubuf(buf[m++]).i;
  for (int d = 0; d < 4; d++) quat[i][d] = buf[m++];
  for (int d = 0; d < 3; d++) inertia[i][d] = buf[m++];
  return m;
}

int AtomVecPolyhedron::pack_ghost_velocity(int j, double *buf, const double dv[3]) const {
  for (int d = 0; d < 3; d++) {
    buf[d] = v[j][d] + dv[d];
    buf[3 + d] = omega[j][d];
  }
  return 6;
}

int AtomVecPolyhedron::unpack_ghost_velocity(int i, const double *buf) {
  for (int d = 0; d < 3; d++) {
    v[i][d] = buf[d];
    omega[i][d] = buf[3 + d];
  }
  return 6;
}

int AtomVecPolyhedron::record_size() const { return kRecordValues; }

// In atom_style hybrid the base style packs x, tag, type, mask; the sub-style the rest.
int AtomVecPolyhedron::pack_border_hybrid(int n, int *list, double *buf) {
  int m = 0;
  double grain[kGrainValues];
  for (int i = 0; i < n; i++) {
    pack_ghost(list[i], grain);
    for (int k = 3; k < kGrainValues; k++) buf[m++] = grain[k];
  }
  return m;
}

int AtomVecPolyhedron::unpack_border_hybrid(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++) {
    double grain[kGrainValues] = {ubuf(tag[i]).d, ubuf(type[i]).d, ubuf(mask[i]).d};
    for (int k = 3; k < kGrainValues; k++) grain[k] = buf[m++];
    unpack_ghost(i, grain);
  }
  return m;
}

// One grain/bead as exchange and restart records carry it: x, v, image, then the
// values a ghost gets.
int AtomVecPolyhedron::pack_record(int i, double *buf) const {
  int m = 0;
  for (int d = 0; d < 3; d++) buf[m++] = x[i][d];
  for (int d = 0; d < 3; d++) buf[m++] = v[i][d];
  buf[m++] = ubuf(image[i]).d;
  for (int d = 0; d < 3; d++) buf[m++] = omega[i][d];
  for (int d = 0; d < 3; d++) buf[m++] = angmom[i][d];
  return m + pack_ghost(i, &buf[m]);
}

int AtomVecPolyhedron::unpack_record(int i, const double *buf) {
  int m = 0;
  for (int d = 0; d < 3; d++) x[i][d] = buf[m++];
  for (int d = 0; d < 3; d++) v[i][d] = buf[m++];
  image[i] = (tagint)ubuf(buf[m++]).i;
  for (int d = 0; d < 3; d++) omega[i][d] = buf[m++];
  for (int d = 0; d < 3; d++) angmom[i][d] = buf[m++];
  return m + unpack_ghost(i, &buf[m]);
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
void AtomVecPolyhedron::create_atom(int itype, double *coord) {
  const int nlocal = atom->nlocal;
  if (nlocal == nmax) grow(0);
  tag[nlocal] = 0;
  type[nlocal] = itype;
  for (int d = 0; d < 3; d++) {
    x[nlocal][d] = coord[d];
    v[nlocal][d] = omega[nlocal][d] = angmom[nlocal][d] = 0.0;
    inertia[nlocal][d] = 1.0;
  }
  quat[nlocal][0] = 1.0;
  quat[nlocal][1] = quat[nlocal][2] = quat[nlocal][3] = 0.0;
  mask[nlocal] = 1;
  image[nlocal] = ((tagint)IMGMAX << IMG2BITS) | ((tagint)IMGMAX << IMGBITS) | IMGMAX;
  radius[nlocal] = 0.5;
  rmass[nlocal] = density[nlocal] = 1.0;
  shape[nlocal] = -1;
  wiregrain_lmp::clear_restart_record(lmp, nlocal);
  atom->nlocal++;
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

void AtomVecPolyhedron::replace_shapes(const wiregrain::ShapeLibrary &library) {
  library_.reset(new wiregrain::ShapeLibrary(library));
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

namespace {
[[noreturn]] void data_error(Error *error, const std::string &what, const char *section = "Atoms") {
  error->one(FLERR, (std::string("atom_style polyhedron: ") + section + " section of data file: " + what).c_str());
  std::abort();
}
// a finite number, else "<name> must be a finite number, got '<word>'"
double data_number(Error *error, const char *word, const std::string &name, const char *section = "Atoms") {
  double value = 0.0;
  if (!wiregrain_lmp::parse_finite_number(word, value))
    data_error(error, name + " must be a finite number, got '" + word + "'", section);
  return value;
}
}  // namespace

void AtomVecPolyhedron::data_atom(double *coord, tagint imagetmp, char **values) {
  const int nlocal = atom->nlocal;
  if (nlocal == nmax) grow(0);
  tag[nlocal] = atoi(values[0]);
  if (tag[nlocal] <= 0) data_error(error, std::string("invalid atom ID '") + values[0] + "'");
  type[nlocal] = atoi(values[1]);
  if (type[nlocal] <= 0 || type[nlocal] > atom->ntypes)
    data_error(error, std::string("invalid atom type '") + values[1] + "'");
  for (int d = 0; d < 3; d++) {
    x[nlocal][d] = coord[d];
    v[nlocal][d] = omega[nlocal][d] = angmom[nlocal][d] = 0.0;
  }
  image[nlocal] = imagetmp;
  mask[nlocal] = 1;
  data_atom_hybrid(nlocal, &values[2]);
  atom->nlocal++;
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
    data_error(error, std::string("shape '") + values[0] + "' is not in the shape library (" +
                          std::to_string(library_->size()) + " shapes; a library comes from create_grains or a restart file)");
  double rho = 0.0;
  if (!wiregrain_lmp::parse_finite_number(values[1], rho) || !(rho > 0.0))
    data_error(error, std::string("density must be a finite number > 0, got '") + values[1] + "'");
  double q[4];
  for (int d = 0; d < 4; d++) q[d] = data_number(error, values[2 + d], std::string("q") + "wijk"[d]);
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(norm > 0.0)) data_error(error, "the quaternion qw qi qj qk must not be zero");
  for (int d = 0; d < 4; d++) quat[nlocal][d] = q[d] / norm;
  assign_shape(nlocal, (int)s, rho);
  return 6;
}

void AtomVecPolyhedron::data_vel(int m, char **values) {
  for (int d = 0; d < 3; d++)
    v[m][d] = data_number(error, values[d], "v" + std::string(1, "xyz"[d]) + " of atom " + std::to_string(tag[m]),
                          "Velocities");
  data_vel_hybrid(m, &values[3]);
}

int AtomVecPolyhedron::data_vel_hybrid(int m, char **values) {
  for (int d = 0; d < 3; d++)
    omega[m][d] = data_number(error, values[d],
                              "omega" + std::string(1, "xyz"[d]) + " of atom " + std::to_string(tag[m]), "Velocities");
  angmom_from_omega(m);
  return 3;
}

void AtomVecPolyhedron::pack_data(double **buf) {
  for (int i = 0; i < atom->nlocal; i++) {
    buf[i][0] = ubuf(tag[i]).d;
    buf[i][1] = ubuf(type[i]).d;
    pack_data_hybrid(i, &buf[i][2]);
    for (int d = 0; d < 3; d++) buf[i][8 + d] = x[i][d];
    buf[i][11] = ubuf((image[i] & IMGMASK) - IMGMAX).d;
    buf[i][12] = ubuf((image[i] >> IMGBITS & IMGMASK) - IMGMAX).d;
    buf[i][13] = ubuf((image[i] >> IMG2BITS) - IMGMAX).d;
  }
}

int AtomVecPolyhedron::pack_data_hybrid(int i, double *buf) {
  buf[0] = ubuf(shape[i]).d;
  buf[1] = density[i];
  for (int d = 0; d < 4; d++) buf[2 + d] = quat[i][d];
  return 6;
}

void AtomVecPolyhedron::write_data(FILE *fp, int n, double **buf) {
  for (int i = 0; i < n; i++) {
    fprintf(fp, "%d %d", (int)ubuf(buf[i][0]).i, (int)ubuf(buf[i][1]).i);
    write_data_hybrid(fp, &buf[i][2]);
    fprintf(fp, " %-1.16e %-1.16e %-1.16e %d %d %d\n", buf[i][8], buf[i][9], buf[i][10],
            (int)ubuf(buf[i][11]).i, (int)ubuf(buf[i][12]).i, (int)ubuf(buf[i][13]).i);
  }
}

int AtomVecPolyhedron::write_data_hybrid(FILE *fp, double *buf) {
  fprintf(fp, " %d %-1.16e %-1.16e %-1.16e %-1.16e %-1.16e", (int)ubuf(buf[0]).i, buf[1], buf[2], buf[3],
          buf[4], buf[5]);
  return 6;
}

void AtomVecPolyhedron::pack_vel(double **buf) {
  for (int i = 0; i < atom->nlocal; i++) {
    buf[i][0] = ubuf(tag[i]).d;
    for (int d = 0; d < 3; d++) buf[i][1 + d] = v[i][d];
    pack_vel_hybrid(i, &buf[i][4]);
  }
}

int AtomVecPolyhedron::pack_vel_hybrid(int i, double *buf) {
  for (int d = 0; d < 3; d++) buf[d] = omega[i][d];
  return 3;
}

void AtomVecPolyhedron::write_vel(FILE *fp, int n, double **buf) {
  for (int i = 0; i < n; i++) {
    fprintf(fp, "%d %-1.16e %-1.16e %-1.16e", (int)ubuf(buf[i][0]).i, buf[i][1], buf[i][2], buf[i][3]);
    write_vel_hybrid(fp, &buf[i][4]);
    fprintf(fp, "\n");
  }
}

int AtomVecPolyhedron::write_vel_hybrid(FILE *fp, double *buf) {
  fprintf(fp, " %-1.16e %-1.16e %-1.16e", buf[0], buf[1], buf[2]);
  return 3;
}

bigint AtomVecPolyhedron::memory_usage() {
  bigint bytes = 0;
  bytes += memory->usage(tag, nmax) + memory->usage(type, nmax) + memory->usage(mask, nmax);
  bytes += memory->usage(image, nmax) + memory->usage(shape, nmax);
  bytes += memory->usage(x, nmax, 3) + memory->usage(v, nmax, 3) + memory->usage(f, nmax * comm->nthreads, 3);
  bytes += memory->usage(radius, nmax) + memory->usage(rmass, nmax) + memory->usage(density, nmax);
  bytes += memory->usage(omega, nmax, 3) + memory->usage(angmom, nmax, 3);
  bytes += memory->usage(torque, nmax * comm->nthreads, 3);
  bytes += memory->usage(quat, nmax, 4) + memory->usage(inertia, nmax, 3);
  return bytes;
}
