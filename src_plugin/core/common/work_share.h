// Work on a list of items shared out over workers that all hold the same inputs (the MPI
// ranks of fix nscd/polyhedra, which all hold every grain), with every worker ending with
// every item's result, to the bit what one worker computing all of them would have: the
// items, in their fixed order, are cut into `workers` contiguous blocks; worker k computes
// block k and writes each item's result as flat numbers, `all_gather` joins the blocks in
// worker order (every worker calls it once per use with its own block and gets the
// concatenation of all), and each worker reads the other blocks' items back.
#pragma once

#include <cstddef>
#include <exception>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/common/errors.h"

namespace wiregrain {

struct WorkShare {
  int worker = 0, workers = 1;
  std::function<std::vector<double>(const std::vector<double>&)> all_gather;
};

// The joined numbers of one block, read in order; NumericalFailure when a block ends
// before its items do (a join that did not hold every block).
class SharedNumbers {
 public:
  explicit SharedNumbers(std::vector<double> all) : all_(std::move(all)) {}
  double next() {
    if (at_ >= all_.size()) throw NumericalFailure("shared work: the joined blocks are shorter than their items");
    return all_[at_++];
  }
  void skip(std::size_t count) {
    if (count > all_.size() - at_) throw NumericalFailure("shared work: the joined blocks are shorter than their items");
    at_ += count;
  }

 private:
  std::vector<double> all_;
  std::size_t at_ = 0;
};

// Items [0, count) shared out over `share` (null or one worker: all computed here):
// `compute(i, out)` computes item i of this worker's block, keeping its result and
// appending it to `out` as numbers; `read(i, in)` takes the result of item i of another
// worker's block from `in.next()`, reading exactly what compute wrote. An exception in a
// worker's block is sent in its place (its length + 1, then its characters; 0 for a block
// that succeeded) and every worker throws NumericalFailure with the first failed block's
// message, so that all workers stop together; with one worker the exception propagates.
// InvalidArgument("share") when the worker index is outside [0, workers).
template <class Compute, class Read>
void share_out(std::size_t count, const WorkShare* share, const Compute& compute, const Read& read) {
  const int workers = share && share->workers > 1 ? share->workers : 1;
  const int me = workers > 1 ? share->worker : 0;
  if (me < 0 || me >= workers)
    throw InvalidArgument("share", "shared work: worker " + std::to_string(me) + " of " + std::to_string(workers));
  const auto block_begin = [&](int w) { return count * static_cast<std::size_t>(w) / static_cast<std::size_t>(workers); };
  std::vector<double> mine;
  if (workers == 1) {  // nothing to send: the numbers are dropped item by item
    for (std::size_t i = 0; i < count; i++) {
      compute(i, mine);
      mine.clear();
    }
    return;
  }
  mine.push_back(0.0);
  try {
    for (std::size_t i = block_begin(me); i < block_begin(me + 1); i++) compute(i, mine);
  } catch (const std::exception& e) {
    std::string failure = e.what();
    if (failure.empty()) failure = "shared work failed";
    mine.assign(1, double(failure.size() + 1));
    for (char ch : failure) mine.push_back(static_cast<unsigned char>(ch));
  }
  SharedNumbers in(share->all_gather(mine));
  std::string failed_block;
  for (int w = 0; w < workers; w++) {
    const double status = in.next();
    if (status != 0.0) {
      std::string message;
      for (std::size_t k = 0; k + 1 < static_cast<std::size_t>(status); k++) message.push_back(static_cast<char>(in.next()));
      if (failed_block.empty()) failed_block = message;
      continue;
    }
    if (w == me) {  // this worker's own results are kept: their numbers skipped
      in.skip(mine.size() - 1);
      continue;
    }
    for (std::size_t i = block_begin(w); i < block_begin(w + 1); i++) read(i, in);
  }
  if (!failed_block.empty()) throw NumericalFailure(failed_block);
}

}  // namespace wiregrain
