// nscd_stack: a stack of boxes at rest on a frictional floor, integrated step after step
// with the core grain step (what fix nscd/polyhedra does each step), and the loads at
// every interface against the weights above it.
//
//   nscd_stack [--n N] [--steps S] [--method gauss_seidel|subspace] [--alternate]
//              [--tol T] [--max-iter K] [--order forward|random|alternating]
//              [--measure natural_map|increment_then_natural_map] [--mu MU]
//
// Boxes 1 × 1 × 1 of mass 1 (with --alternate every second box is 0.6 × 0.6 × 0.5 and of
// mass 0.18, centred), g = 1 along −z, h = 1e-3, μ = 0.5 everywhere, 4 corner points per
// interface; the stack starts exactly at rest and touching. Interface k (counted from the
// top, k = 1 between the two top boxes, k = N on the floor) must carry the weight of the
// boxes above it, W_k = Σ_{j ≤ k} m_j g (statics; independent of the solver). Printed per
// run: the worst relative load error max_k |F_k − W_k| / W_k over all steps, the number of
// steps where it exceeds 1e-4, steps that hit the sweep cap, sweeps (mean, max), the
// largest speed of a box, wall time.
#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/geometry/contact_geometry.h"
#include "core/geometry/convex_shape.h"
#include "core/nscd/grain_step.h"

using namespace wiregrain;

namespace {

[[noreturn]] void usage(const char* what) {
  std::fprintf(stderr, "nscd_stack: %s\n", what);
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  int n = 20, steps = 1000;
  bool alternate = false, verbose = false;
  GrainStepOptions options;
  options.friction = 0.5;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> const char* {
      if (i + 1 >= argc) usage(("missing value after " + arg).c_str());
      return argv[++i];
    };
    if (arg == "--n") n = std::atoi(value());
    else if (arg == "--steps") steps = std::atoi(value());
    else if (arg == "--alternate") alternate = true;
    else if (arg == "--verbose") verbose = true;
    else if (arg == "--tol") options.solver.tolerance = std::atof(value());
    else if (arg == "--max-iter") options.solver.max_iterations = std::atoi(value());
    else if (arg == "--mu") options.friction = std::atof(value());
    else if (arg == "--method") {
      const std::string m = value();
      if (m == "gauss_seidel") options.solver.method = SolverMethod::gauss_seidel;
      else if (m == "subspace") options.solver.method = SolverMethod::subspace;
      else usage(("unknown method " + m).c_str());
    } else if (arg == "--order") {
      const std::string o = value();
      if (o == "forward") options.solver.order = SweepOrder::forward;
      else if (o == "random") options.solver.order = SweepOrder::random;
      else if (o == "alternating") options.solver.order = SweepOrder::alternating;
      else usage(("unknown order " + o).c_str());
    } else if (arg == "--measure") {
      const std::string m = value();
      if (m == "natural_map") options.solver.measure = ConvergenceMeasure::natural_map;
      else if (m == "increment_then_natural_map") options.solver.measure = ConvergenceMeasure::increment_then_natural_map;
      else usage(("unknown measure " + m).c_str());
    } else usage(("unknown argument " + arg).c_str());
  }
  if (n < 1 || steps < 1) usage("--n and --steps must be >= 1");

  const double g = 1.0, h = 1e-3;
  ShapeLibrary library;
  library.add(ConvexShape::box(1.0, 1.0, 1.0));
  library.add(ConvexShape::box(0.6, 0.6, 0.5));
  std::vector<GrainState> grains;
  double z = 0.0;
  for (int i = 0; i < n; ++i) {  // bottom up
    const bool small = alternate && i % 2 == 1;
    GrainState s;
    s.tag = i + 1;
    s.shape = small ? 1 : 0;
    const Eigen::Vector3d size = small ? Eigen::Vector3d(0.6, 0.6, 0.5) : Eigen::Vector3d(1, 1, 1);
    s.mass = small ? 0.18 : 1.0;
    s.inertia = s.mass / 12.0 * Eigen::Vector3d(size.y() * size.y() + size.z() * size.z(),
                                                size.x() * size.x() + size.z() * size.z(),
                                                size.x() * size.x() + size.y() * size.y());
    s.position = Eigen::Vector3d(0, 0, z + 0.5 * size.z());
    s.force = Eigen::Vector3d(0, 0, -s.mass * g);
    z += size.z();
    grains.push_back(s);
  }
  // W_k for the interface under box i (bottom up): weights of boxes i..n−1
  std::vector<double> load(n, 0.0);
  for (int i = n - 1; i >= 0; --i) load[i] = grains[i].mass * g + (i + 1 < n ? load[i + 1] : 0.0);

  PlaneWall floor;
  floor.friction = options.friction;
  GrainImpulseMemory memory;
  double worst = 0.0, fastest = 0.0;
  int bad_steps = 0, capped = 0, max_sweeps = 0;
  long sweeps = 0, solves = 0, kept = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int step = 0; step < steps; ++step) {
    GrainStepResult r;
    try {
      r = grain_step(grains, library, {floor}, h, options, step, memory);
    } catch (const std::exception& e) {
      std::printf("step %d: %s\n", step, e.what());
      for (int i = 0; i + 1 < n; ++i) {
        const PosedShape a(library[grains[i].shape].shape, grains[i].position, grains[i].orientation);
        const PosedShape b(library[grains[i + 1].shape].shape, grains[i + 1].position, grains[i + 1].orientation);
        for (const ContactPoint& p : contact_manifold(a, b, 1e-3).points)
          if (!p.normal.allFinite() || p.normal.norm() == 0.0) {
            std::printf("pair %d %d: normal %g %g %g\n", i, i + 1, p.normal.x(), p.normal.y(), p.normal.z());
            std::printf("  a %.17g %.17g %.17g q %.17g %.17g %.17g %.17g\n", grains[i].position.x(), grains[i].position.y(), grains[i].position.z(), grains[i].orientation.w(), grains[i].orientation.x(), grains[i].orientation.y(), grains[i].orientation.z());
            std::printf("  b %.17g %.17g %.17g q %.17g %.17g %.17g %.17g\n", grains[i+1].position.x(), grains[i+1].position.y(), grains[i+1].position.z(), grains[i+1].orientation.w(), grains[i+1].orientation.x(), grains[i+1].orientation.y(), grains[i+1].orientation.z());
            break;
          }
      }
      return 1;
    }
    // force on box i from below = Σ forces of records with b = tag i (a = wall or box i−1)
    std::vector<double> carried(n, 0.0);
    for (const ContactRecord& c : r.contacts.records()) carried[c.b - 1] += c.force.z();
    double step_worst = 0.0;
    for (int i = 0; i < n; ++i) step_worst = std::max(step_worst, std::fabs(carried[i] - load[i]) / load[i]);
    worst = std::max(worst, step_worst);
    if (step_worst > 1e-4) ++bad_steps;
    if (verbose)
      std::printf("step %d: sweeps %d residual %.3e load error %.3e stick solves %d kept %d\n", step, r.stats.sweeps,
                  r.stats.residual, step_worst, r.stats.subspace_solves, r.stats.subspace_accepted);
    if (r.stats.hit_iteration_cap) ++capped;
    sweeps += r.stats.sweeps;
    solves += r.stats.subspace_solves;
    kept += r.stats.subspace_accepted;
    max_sweeps = std::max(max_sweeps, r.stats.sweeps);
    for (int i = 0; i < n; ++i) {
      GrainState& s = grains[i];
      const Eigen::Matrix3d rot = s.orientation.toRotationMatrix();
      const Eigen::Matrix3d inertia_world = rot * s.inertia.asDiagonal() * rot.transpose();
      const GrainPose pose = advance_grain_pose({s.position, s.orientation}, s.inertia, s.velocity, r.velocities[i],
                                                inertia_world * s.angular_velocity,
                                                inertia_world * r.angular_velocities[i], h, options.solver.theta);
      s.position = pose.position;
      s.orientation = pose.orientation;
      s.velocity = r.velocities[i];
      s.angular_velocity = r.angular_velocities[i];
      fastest = std::max(fastest, s.velocity.norm());
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("n %d%s steps %d tol %g: worst load error %.3e, steps over 1e-4 %d, capped %d, "
              "sweeps mean %.1f max %d, stick solves %ld (kept %ld), largest speed %.2e, %.3f s\n",
              n, alternate ? " (alternating)" : "", steps, options.solver.tolerance, worst, bad_steps, capped,
              double(sweeps) / steps, max_sweeps, solves, kept, fastest, seconds);
  return 0;
}
