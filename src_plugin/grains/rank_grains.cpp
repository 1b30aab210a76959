// RankGrains (rank_grains.h).
#include "rank_grains.h"

#include <algorithm>
#include <string>

#include "atom.h"
#include "comm.h"
#include "fix.h"
#include "lammps.h"

#include "core/common/errors.h"

namespace wiregrain_lmp {

RankGrains::RankGrains(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::Fix *fix) : lmp_(lmp), fix_(fix), world_(lmp->world) {}

void RankGrains::collect(int groupbit) {
  LAMMPS_NS::Atom *atom = lmp_->atom;
  atoms_.clear();
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) atoms_.push_back(i);
  std::sort(atoms_.begin(), atoms_.end(), [atom](int a, int b) { return atom->tag[a] < atom->tag[b]; });
  owned_ = static_cast<int>(atoms_.size());
  for (int i = atom->nlocal; i < atom->nlocal + atom->nghost; i++)
    if (atom->mask[i] & groupbit) atoms_.push_back(i);
  // the ghosts by tag, images of one grain by position: the order of the pairs does not
  // depend on how LIGGGHTS stores its atoms (a run continued from a restart file repeats
  // the straight run)
  double **x = atom->x;
  std::sort(atoms_.begin() + owned_, atoms_.end(), [atom, x](int a, int b) {
    if (atom->tag[a] != atom->tag[b]) return atom->tag[a] < atom->tag[b];
    return std::lexicographical_compare(x[a], x[a] + 3, x[b], x[b] + 3);
  });
}

void RankGrains::copy_to_ghosts(std::vector<double> &per_atom, int width) {
  if (width > kMaxWidth)
    throw wiregrain::InvalidArgument("width", "rank grains: " + std::to_string(width) + " values per atom, at most " +
                                                  std::to_string(kMaxWidth));
  buffer_.swap(per_atom);
  width_ = width;
  lmp_->comm->forward_comm_fix(fix_);
  traffic_.rounds += 1;
  buffer_.swap(per_atom);
}

// Each grain's values into its atom's row (ghost rows zero where no grain), reverse
// communication adds every ghost row into its owner's, forward communication copies the
// owner's sums back to every ghost.
void RankGrains::sum_over_copies(std::vector<double> &values, int width) {
  if (width > kMaxWidth)
    throw wiregrain::InvalidArgument("width", "rank grains: " + std::to_string(width) + " values per atom, at most " +
                                                  std::to_string(kMaxWidth));
  LAMMPS_NS::Atom *atom = lmp_->atom;
  width_ = width;
  buffer_.assign(static_cast<std::size_t>(atom->nlocal + atom->nghost) * width, 0.0);
  for (std::size_t k = 0; k < atoms_.size(); k++)
    std::copy(values.begin() + k * width, values.begin() + (k + 1) * width, buffer_.begin() + std::size_t(atoms_[k]) * width);
  lmp_->comm->reverse_comm_fix(fix_);
  lmp_->comm->forward_comm_fix(fix_);
  traffic_.rounds += 2;
  for (std::size_t k = 0; k < atoms_.size(); k++)
    std::copy(buffer_.begin() + std::size_t(atoms_[k]) * width, buffer_.begin() + std::size_t(atoms_[k] + 1) * width,
              values.begin() + k * width);
}

void RankGrains::sum_over_workers(double *values, int count) {
  std::vector<double> sums(count);
  MPI_Allreduce(values, sums.data(), count, MPI_DOUBLE, MPI_SUM, world_);
  traffic_.reductions += 1;
  std::copy(sums.begin(), sums.end(), values);
}

double RankGrains::max_over_workers(double value) {
  double largest = value;
  MPI_Allreduce(&value, &largest, 1, MPI_DOUBLE, MPI_MAX, world_);
  traffic_.reductions += 1;
  return largest;
}

int RankGrains::pack_comm(int n, const int *list, double *buf) {
  traffic_.values_sent += double(n) * width_;
  int m = 0;
  for (int i = 0; i < n; i++)
    for (int k = 0; k < width_; k++) buf[m++] = buffer_[std::size_t(list[i]) * width_ + k];
  return width_;
}

void RankGrains::unpack_comm(int n, int first, const double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < width_; k++) buffer_[std::size_t(i) * width_ + k] = buf[m++];
}

int RankGrains::pack_reverse_comm(int n, int first, double *buf) {
  traffic_.values_sent += double(n) * width_;
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < width_; k++) buf[m++] = buffer_[std::size_t(i) * width_ + k];
  return width_;
}

void RankGrains::unpack_reverse_comm(int n, const int *list, const double *buf) {
  int m = 0;
  for (int i = 0; i < n; i++)
    for (int k = 0; k < width_; k++) buffer_[std::size_t(list[i]) * width_ + k] += buf[m++];
}

}  // namespace wiregrain_lmp
