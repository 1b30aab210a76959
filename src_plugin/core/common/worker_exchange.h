// What a computation spread over workers that each own a part of the bodies needs from
// their communication (the MPI ranks of fix nscd/polyhedra with `solve distributed`: each
// rank owns the grains of its subdomain and holds copies, LIGGGHTS' ghosts, of the grains
// of other subdomains within the contact reach).
//
// A worker's local bodies are its own bodies followed by its copies; one body may have
// several copies (on several workers, or on its own worker as a periodic image). Every
// worker calls each function the same number of times in the same order (they are
// collective, as MPI's reductions are).
#pragma once

#include <vector>

namespace wiregrain {

class WorkerExchange {
 public:
  virtual ~WorkerExchange() = default;
  // values: `width` numbers per local body, body k at [k width, (k + 1) width). On return,
  // each body's numbers are the sum over all its copies and its own (every copy and the
  // owner end with the same sums).
  virtual void sum_over_copies(std::vector<double>& values, int width) = 0;
  // Each of values[0, count) replaced by its sum over the workers.
  virtual void sum_over_workers(double* values, int count) = 0;
  // The largest of `value` over the workers.
  virtual double max_over_workers(double value) = 0;
};

}  // namespace wiregrain
