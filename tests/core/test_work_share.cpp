// core/common/work_share.h: items shared out over workers (threads standing in for MPI
// ranks) end, on every worker, with every item's result as one worker computes it; each
// item is computed once over all workers; a failure in one block stops every worker with
// its message.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/errors.h"
#include "core/common/work_share.h"
#include "threaded_workers.h"

using namespace wiregrain;

namespace {

// item i's result: i numbers, i + 0.5 each (0 to 10 numbers: blocks of unequal lengths,
// item 0 empty)
std::vector<double> result_of(std::size_t i) { return std::vector<double>(i, i + 0.5); }

}  // namespace

TEST(WorkShare, EveryWorkerEndsWithEveryItemComputedOnce) {
  constexpr std::size_t kItems = 11;
  for (int workers : {1, 2, 3, 5, 13}) {  // 13: more workers than items, some blocks empty
    std::vector<std::vector<std::vector<double>>> results(workers, std::vector<std::vector<double>>(kItems));
    std::vector<std::atomic<int>> computed(kItems);
    run_threaded_workers(workers, [&](const WorkShare& share, int w) {
      share_out(
          kItems, &share,
          [&](std::size_t i, std::vector<double>& out) {
            ++computed[i];
            results[w][i] = result_of(i);
            out.insert(out.end(), results[w][i].begin(), results[w][i].end());
          },
          [&](std::size_t i, SharedNumbers& in) {
            for (std::size_t k = 0; k < i; k++) results[w][i].push_back(in.next());
          });
    });
    for (std::size_t i = 0; i < kItems; i++) {
      EXPECT_EQ(computed[i].load(), 1) << workers << " workers, item " << i;
      for (int w = 0; w < workers; w++) EXPECT_EQ(results[w][i], result_of(i)) << workers << " workers, worker " << w << ", item " << i;
    }
  }
}

TEST(WorkShare, AFailedBlockStopsEveryWorkerWithItsMessage) {
  std::vector<std::string> messages(3);
  run_threaded_workers(3, [&](const WorkShare& share, int w) {
    try {
      share_out(
          9, &share,
          [&](std::size_t i, std::vector<double>& out) {
            if (i == 4) throw std::runtime_error("item 4 failed");  // worker 1's block 3..5
            out.push_back(double(i));
          },
          [&](std::size_t, SharedNumbers& in) { in.next(); });
    } catch (const NumericalFailure& e) {
      messages[w] = e.what();
    }
  });
  for (int w = 0; w < 3; w++) EXPECT_EQ(messages[w], "item 4 failed") << "worker " << w;
  // one worker: the exception itself
  EXPECT_THROW(share_out(
                   2, nullptr, [](std::size_t, std::vector<double>&) { throw std::logic_error("alone"); },
                   [](std::size_t, SharedNumbers&) {}),
               std::logic_error);
}

// A join that does not hold every block, and a worker index outside [0, workers), are
// refused instead of read past.
TEST(WorkShare, ABadJoinOrWorkerIndexIsRefused) {
  WorkShare share;
  share.workers = 2;
  share.all_gather = [](const std::vector<double>& mine) { return mine; };  // the other block missing
  const auto compute = [](std::size_t i, std::vector<double>& out) { out.push_back(double(i)); };
  const auto read = [](std::size_t, SharedNumbers& in) { in.next(); };
  EXPECT_THROW(share_out(4, &share, compute, read), NumericalFailure);
  share.worker = 2;
  try {
    share_out(4, &share, compute, read);
    FAIL() << "worker 2 of 2 accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "share");
  }
}
