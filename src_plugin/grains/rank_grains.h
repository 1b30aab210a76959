// The grains of one MPI rank in a distributed grain step (fix nscd/polyhedra `solve
// distributed`; core/nscd/grain_step.h, GrainPartition): its own grains of the group in
// ascending tag order, then LIGGGHTS' ghost grains of the group (copies of other ranks'
// grains and periodic images, at their image positions), and the exchange of per-grain
// numbers among the copies of a grain through LIGGGHTS' own forward and reverse
// communication of the fix (Comm::forward_comm_fix, Comm::reverse_comm_fix), the
// reductions through MPI_Allreduce. The fix forwards its pack/unpack callbacks here.
#ifndef WIREGRAIN_RANK_GRAINS_H
#define WIREGRAIN_RANK_GRAINS_H

#include <mpi.h>

#include <vector>

#include "core/common/worker_exchange.h"

namespace LAMMPS_NS {
class LAMMPS;
class Fix;
}

namespace wiregrain_lmp {

class RankGrains : public wiregrain::WorkerExchange {
 public:
  // the largest number of values per atom any exchange here sends (the fix's
  // comm_forward and comm_reverse)
  static constexpr int kMaxWidth = 25;

  RankGrains(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::Fix *fix);

  // This rank's grains of the group `groupbit`: the atom indices of its own (ascending
  // tags), then of its ghosts (ascending tags, the images of one grain by position).
  void collect(int groupbit);
  const std::vector<int> &atoms() const { return atoms_; }
  int owned() const { return owned_; }

  // per_atom: `width` values per atom of this rank (own and ghost: atom->nlocal +
  // atom->nghost rows); each ghost's row replaced by its owner's (forward communication).
  void copy_to_ghosts(std::vector<double> &per_atom, int width);

  // WorkerExchange: values per grain of collect()'s list
  void sum_over_copies(std::vector<double> &values, int width) override;
  void sum_over_workers(double *values, int count) override;
  double max_over_workers(double value) override;

  // the fix's communication callbacks
  int pack_comm(int n, const int *list, double *buf);
  void unpack_comm(int n, int first, const double *buf);
  int pack_reverse_comm(int n, int first, double *buf);
  void unpack_reverse_comm(int n, const int *list, const double *buf);

  // This rank's traffic since the fix was made, for sizing runs on many ranks
  // (docs/benchmarks.md, "A model for many ranks"): the values (doubles) it packed into
  // LIGGGHTS' forward and reverse communication of the fix (periodic images of its own
  // grains included), the communication rounds (one forward or reverse communication:
  // a message to each neighbour subdomain) and the global reductions (MPI_Allreduce),
  // those of the fix counted through count_reduction().
  struct Traffic {
    double values_sent = 0.0;
    double rounds = 0.0;
    double reductions = 0.0;
  };
  const Traffic &traffic() const { return traffic_; }
  void count_reduction(int n = 1) { traffic_.reductions += n; }

 private:
  LAMMPS_NS::LAMMPS *lmp_;
  LAMMPS_NS::Fix *fix_;
  MPI_Comm world_;
  std::vector<int> atoms_;
  int owned_ = 0;
  std::vector<double> buffer_;  // width_ values per atom (own and ghost)
  int width_ = 0;
  Traffic traffic_;
};

}  // namespace wiregrain_lmp

#endif
