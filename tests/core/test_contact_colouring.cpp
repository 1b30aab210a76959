// The greedy colouring of the contact graph (core/nscd/contact_colouring.h) and the sweep
// order it gives the solver (SweepOrder::coloured).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>

#include "core/common/errors.h"
#include "core/nscd/contact_colouring.h"
#include "core/nscd/nscd_solver.h"

using namespace wiregrain;

// 400 contacts among 60 bodies and a wall (−1), drawn at random: no two contacts on one
// body share a colour, the colours lie between the largest number of contacts on a body
// and twice that minus one, and the order lists every contact once, colour by colour, each
// colour in the given order.
TEST(ContactColouring, ContactsOnOneBodyDiffer) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> body(-1, 59);
  std::vector<std::pair<int, int>> bodies;
  while (bodies.size() < 400) {
    const int a = body(rng), b = body(rng);
    if (a != b) bodies.push_back({a, b});
  }
  const ContactColouring colouring = colour_contacts(bodies, 60);
  std::map<int, std::set<int>> colours_on;  // body → colours of its contacts
  std::map<int, int> contacts_on;
  for (std::size_t c = 0; c < bodies.size(); ++c) {
    for (const int b : {bodies[c].first, bodies[c].second}) {
      if (b < 0) continue;
      EXPECT_TRUE(colours_on[b].insert(colouring.colour[c]).second) << "body " << b << " contact " << c;
      ++contacts_on[b];
    }
  }
  int most = 0;
  for (const auto& entry : contacts_on) most = std::max(most, entry.second);
  EXPECT_GE(colouring.colours, most);
  EXPECT_LE(colouring.colours, 2 * most - 1);
  ASSERT_EQ(colouring.order.size(), bodies.size());
  std::vector<int> sorted = colouring.order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t c = 0; c < sorted.size(); ++c) EXPECT_EQ(sorted[c], int(c));
  for (std::size_t i = 1; i < colouring.order.size(); ++i) {
    const int x = colouring.order[i - 1], y = colouring.order[i];
    EXPECT_TRUE(colouring.colour[x] < colouring.colour[y] || (colouring.colour[x] == colouring.colour[y] && x < y));
  }
  std::printf("  400 contacts on 60 bodies: %d colours, at most %d contacts on one body\n", colouring.colours, most);
}

// Contacts on walls only never conflict: one colour. A body index out of range is named.
TEST(ContactColouring, WallsCoupleNothing) {
  const ContactColouring colouring = colour_contacts({{-1, 0}, {-1, 1}, {2, -1}}, 3);
  EXPECT_EQ(colouring.colours, 1);
  try {
    colour_contacts({{0, 3}}, 3);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "bodies");
    EXPECT_STREQ(e.what(), "contact 0 names body 3 of 3");
  }
}

// An assembled problem has no bodies to colour: the solver names the order.
TEST(ContactColouring, AssembledProblemIsRefused) {
  ReducedProblem problem;
  problem.W = BlockSparseMatrix3(1);
  problem.W.add(0, 0, Eigen::Matrix3d::Identity());
  problem.q = Eigen::VectorXd::Constant(3, -1.0);
  problem.mu = {0.5};
  SolverSettings options;
  options.order = SweepOrder::coloured;
  try {
    solve_reduced(problem, options);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "order");
    EXPECT_STREQ(e.what(), "order coloured needs the step's bodies (solve_nscd_step), not an assembled problem");
  }
}
