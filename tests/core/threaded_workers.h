// Workers on threads standing in for MPI ranks (core/common/work_share.h): worker w runs
// body(share, w) with a WorkShare whose all_gather joins the blocks of all workers in
// worker order, as MPI_Allgatherv over the ranks does. One join per call of all_gather;
// every worker must call it the same number of times.
#pragma once

#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#include "core/common/work_share.h"

namespace wiregrain {

template <class Body>
void run_threaded_workers(int workers, const Body& body) {
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<std::vector<double>> blocks(workers);
  int arrived = 0, left = 0;
  long round = 0;
  std::vector<std::thread> threads;
  for (int w = 0; w < workers; ++w)
    threads.emplace_back([&, w] {
      WorkShare share;
      share.worker = w;
      share.workers = workers;
      share.all_gather = [&, w](const std::vector<double>& mine) {
        std::unique_lock<std::mutex> lock(mutex);
        changed.wait(lock, [&] { return left == 0; });  // the last join is read by all
        const long my_round = round;
        blocks[w] = mine;
        if (++arrived == workers) {
          ++round;
          changed.notify_all();
        }
        changed.wait(lock, [&] { return round > my_round; });
        std::vector<double> all;
        for (const std::vector<double>& b : blocks) all.insert(all.end(), b.begin(), b.end());
        if (++left == workers) {
          arrived = left = 0;
          changed.notify_all();
        }
        return all;
      };
      body(share, w);
    });
  for (std::thread& t : threads) t.join();
}

}  // namespace wiregrain
