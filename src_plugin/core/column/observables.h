// Observables of a wire-reinforced granular column (paper Sec. 2.5 and 3; docs/design.md,
// "The column procedure"): the column height, the fraction of grains retained inside the
// wire, computed from plain positions so that the LIGGGHTS computes only gather them.
//
//   height: the q-quantile of the grains' top heights (the highest point of each grain,
//     core vertex + sweep radius), linear interpolation between order statistics
//     (Hyndman & Fan type 7: position q (n − 1) in the sorted list). A quantile below 1
//     makes the height robust to a few grains lying on top of the column or stuck on the
//     wire above it: with q = 0.98 the top 2 % are ignored (18 of the paper's 915). q = 1 is
//     the highest point of all.
//   retention φ_p: the fraction of grains whose centre lies inside the vertical cylinder
//     about the column axis whose radius is the mean horizontal distance of the wire
//     beads from that axis (paper Sec. 3).
#pragma once

#include <functional>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/posed_shape.h"

namespace wiregrain {

// Highest point of a posed grain: max over core vertices of z, plus the sweep radius.
double grain_top(const PosedShape& grain);

// The q-quantile (q in [0, 1]) of `values` (type 7, see above). InvalidArgument:
// empty values ("values"), q outside [0, 1] or NaN ("quantile").
double quantile(std::vector<double> values, double q);

// The same q-quantile of values spread over workers, none holding them all (the MPI ranks,
// each with the grains it owns): each order statistic is found by bisection over the
// doubles' order (their bit patterns as ordered integers), each round asking
// count_at_most(x), the number of values ≤ x over all workers (a collective call: one
// reduction), so that at most 64 rounds find it exactly; two order statistics per quantile.
// The result equals quantile() of all the values together, to the bit (a quantile that
// falls on a zero may come out as −0). n: the number of values over all workers, lowest
// and highest: their extremes; the values must be finite. InvalidArgument: n < 1 ("n"),
// q outside [0, 1] or NaN ("quantile"), lowest > highest or not finite ("lowest").
double quantile_of_parts(long n, double lowest, double highest, double q,
                         const std::function<long(double)>& count_at_most);

// Mean horizontal distance of `points` from the vertical axis through (axis.x, axis.y).
// InvalidArgument("points") when empty.
double mean_axis_distance(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector2d& axis);

struct Retention {
  double radius = 0.0;  // of the cylinder
  long inside = 0;      // grain centres with horizontal distance < radius
  long total = 0;
  double fraction = 0.0;  // inside / total (0 when there are no grains)
};
Retention retention(const std::vector<Eigen::Vector3d>& grain_centres, const Eigen::Vector2d& axis,
                    double radius);

}  // namespace wiregrain
