// Post-step projection of the grains' overlaps (not in the paper, keyword
// `project` of fix nscd/polyhedra). Moreau–Jean constrains the gap linearised at the
// step start, g + h u_n ≥ 0; a grain tumbling onto another, a rounded edge whose closest
// point slides along it or a feature switch within the step close the true gap by more
// than the linear term, and the overlap left at the next step start was measured up to
// 7e-4 a_max in the 500-grain deposit (docs/design.md, "Position update and overlap projection"), then pushed out only at the
// overlap_speed cap. The projection corrects the positions at the end of the step, never
// the velocities (post-stabilisation, Cline & Pai 2003):
//
//  1. the poses the step leads to (advance_grain_pose, θ-method) of every grain;
//  2. for every pair that had contact points in the step (open ones too: every pair whose
//     gap could close within it), the gap at those poses: GJK/SAT core distance minus the
//     sweep radii, a wall by the support point along −n (walls moved by h v_wall);
//     a pair whose separation along its start normal n at those poses (the cores'
//     supports along n: a lower bound of the gap, exact for a wall) leaves it within
//     the tolerance is settled without GJK; it counts with that bound as its overlap;
//  3. while a pair overlaps by more than tolerance × its size (the smaller bounding radius
//     of its grains), a Gauss–Seidel pass over the pairs: a pair deeper than that is
//     pushed apart along its normal n, inversely to the masses (a wall and a sleeping
//     grain do not move),
//         Δx_b = Δλ n / m_b,  Δx_a = −Δλ n / m_a,  Δλ = (−g − ½ tolerance × size) / (1/m_a + 1/m_b),
//     which leaves it −½ tolerance × size apart where the gap is linear in the
//     translation (flat faces, spheres) and keeps the pair's centre of mass; the pass is
//     repeated on the pairs whose grains moved, at most max_passes times.
//     Translation only: a turn about a contact point would be minimal in the mass
//     metric, but the point of a face lying in a face is any of its corners, and turning
//     about one tilts a cube that only needed lifting (tried: 12 passes and a tilt for a
//     cube 0.05 into the floor; the lift takes one).
// The kinetic energy is untouched; the work against the contact is the overlap removed.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/nscd/grain_step.h"

namespace wiregrain {

struct OverlapProjectionStats {
  int pairs = 0;                 // pairs checked
  int bounded = 0;               // checks settled by the separation bound, without GJK
  int projections = 0;           // pair corrections applied (over all passes)
  int passes = 0;
  double max_overlap_before = 0.0;  // deepest predicted overlap relative to its pair's size
  double max_overlap_after = 0.0;   // the same after the projection
};

// tolerance ≥ 0 and finite (InvalidArgument("tolerance", ...)); 0 projects nothing
// (the corrections are all zero and nothing is computed). max_passes ≥ 1. Returns the
// translation to add to each grain's position (world frame).
std::vector<Eigen::Vector3d> project_overlaps(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                                             const std::vector<PlaneWall>& walls, const GrainStepProblem& problem,
                                             const GrainStepResult& result, double theta, double tolerance,
                                             int max_passes, OverlapProjectionStats* stats = nullptr);

}  // namespace wiregrain
