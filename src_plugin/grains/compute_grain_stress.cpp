#include "compute_grain_stress.h"

#include <Eigen/Core>

#include <string>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "update.h"

#include "atom_style_part.h"
#include "contact_publisher.h"
#include "core/common/errors.h"
#include "core/contact/contact_list.h"
#include "core/contact/contact_stress.h"
#include "core/geometry/shape_library.h"
#include "grain_shape_source.h"
#include "plugin_args.h"

using namespace LAMMPS_NS;

namespace {
constexpr int kMoment = 9;    // the 3×3 sum, row-major
constexpr int kColumns = 10;  // σ in the order of the page, then p
// (row, column) of output columns 1..9
constexpr int kComponent[9][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}, {1, 0}, {2, 0}, {2, 1}};
}  // namespace

ComputeGrainStress::ComputeGrainStress(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg),
      grains_(wiregrain_lmp::atom_style_part<const wiregrain_lmp::GrainShapeSource>(atom)),
      moments_(NULL),
      values_(NULL),
      nmax_(0) {
  wiregrain_lmp::StyleArgs args(error, "compute", "grain/stress", id, narg, arg, iarg);
  if (!grains_)
    args.fail("needs atom_style polyhedron, plain or in a hybrid, not '" + std::string(atom->atom_style) + "'");
  if (!args.done()) args.unknown_keyword(args.next_keyword());
  iarg = narg;
  peratom_flag = 1;
  size_peratom_cols = kColumns;
  comm_reverse = kMoment;
}

ComputeGrainStress::~ComputeGrainStress() {
  memory->destroy(moments_);
  memory->destroy(values_);
}

void ComputeGrainStress::init() {
  if (atom->map_style == 0)
    wiregrain_lmp::style_error(error, "compute", "grain/stress", id, "needs an atom map (atom_modify map array or hash)");
}

void ComputeGrainStress::grow() {
  if (atom->nmax <= nmax_) return;
  nmax_ = atom->nmax;
  memory->destroy(moments_);
  memory->destroy(values_);
  memory->create(moments_, nmax_, kMoment, "grain/stress:moments");
  memory->create(values_, nmax_, kColumns, "grain/stress:values");
  array_atom = values_;
}

// The force `force` that body `body` receives at `point`, added to its moment sum when it
// is a grain (a wall or a wire bead is not). A grain of a contact is always an owned or
// ghost atom of the rank that published the contact, within the ghost shell the styles ask
// for; one that is not is a defect worth stopping for.
void ComputeGrainStress::add_contact(long body, const double *point, const double *force) {
  if (body <= 0) return;  // a wall
  const int i = atom->map(int(body));
  if (i < 0)
    wiregrain_lmp::style_error(error, "compute", "grain/stress", id,
                               "atom " + std::to_string(body) +
                                   " of a published contact is neither owned nor a ghost on this rank");
  if (atom->shapetype[i] < 0) return;  // a wire bead
  double arm[3] = {point[0] - atom->x[i][0], point[1] - atom->x[i][1], point[2] - atom->x[i][2]};
  domain->minimum_image(arm);
  wiregrain::ContactMomentSum sum;
  sum.add(Eigen::Vector3d(arm[0], arm[1], arm[2]), Eigen::Vector3d(force[0], force[1], force[2]));
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) moments_[i][3 * r + c] += sum.sum(r, c);
}

void ComputeGrainStress::compute_peratom() {
  invoked_peratom = update->ntimestep;
  grow();
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++)
    for (int k = 0; k < kMoment; k++) moments_[i][k] = 0.0;
  // b receives the record's force, a its opposite (core/contact/contact_list.h)
  for (const wiregrain_lmp::ContactPublisher *p : wiregrain_lmp::contact_publishers(lmp))
    for (const wiregrain::ContactRecord &c : p->published_contacts().records()) {
      if (c.kind == wiregrain::ContactKind::wire_wire || c.kind == wiregrain::ContactKind::wire_wall) continue;
      const Eigen::Vector3d opposite = -c.force;
      add_contact(c.b, c.point.data(), c.force.data());
      add_contact(c.a, c.point.data(), opposite.data());
    }
  comm->reverse_comm_compute(this);

  const wiregrain::ShapeLibrary &library = grains_->shapes();
  for (int i = 0; i < atom->nlocal; i++) {
    double *out = values_[i];
    for (int k = 0; k < kColumns; k++) out[k] = 0.0;
    if (!(atom->mask[i] & groupbit) || atom->shapetype[i] < 0) continue;
    Eigen::Matrix3d moment;
    for (int r = 0; r < 3; r++)
      for (int c = 0; c < 3; c++) moment(r, c) = moments_[i][3 * r + c];
    Eigen::Matrix3d stress;
    try {
      stress = wiregrain::love_weber_stress(moment, library[atom->shapetype[i]].volume);
    } catch (const wiregrain::InvalidArgument &e) {
      wiregrain_lmp::style_error(error, "compute", "grain/stress", id,
                                 "grain " + std::to_string(atom->tag[i]) + ": " + e.what());
    }
    for (int k = 0; k < 9; k++) out[k] = stress(kComponent[k][0], kComponent[k][1]);
    out[9] = wiregrain::pressure(stress);
  }
}

int ComputeGrainStress::pack_reverse_comm(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < kMoment; k++) buf[m++] = moments_[i][k];
  return kMoment;  // LIGGGHTS' Comm::reverse_comm_compute wants the values per atom
}

void ComputeGrainStress::unpack_reverse_comm(int n, int *list, double *buf) {
  int m = 0;
  for (int ii = 0; ii < n; ii++)
    for (int k = 0; k < kMoment; k++) moments_[list[ii]][k] += buf[m++];
}

double ComputeGrainStress::memory_usage() { return double(nmax_) * (kMoment + kColumns) * sizeof(double); }
