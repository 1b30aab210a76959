#include "grain_shapes.h"

#include <mpi.h>

#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "atom.h"
#include "atom_vec_polyhedron.h"
#include "comm.h"
#include "error.h"

#include "core/common/errors.h"
#include "core/geometry/shape_library.h"
#include "plugin_args.h"

using namespace LAMMPS_NS;

GrainShapes::GrainShapes(LAMMPS *lmp) : Pointers(lmp) {}

void GrainShapes::command(int narg, char **arg) {
  wiregrain_lmp::StyleArgs args(error, "command", "grain_shapes", "-", narg, arg, 0);
  AtomVecPolyhedron *grains = AtomVecPolyhedron::of(atom);
  if (!grains) args.fail("needs atom_style polyhedron (or hybrid with polyhedron)");
  if (narg != 2) args.fail("expected: grain_shapes write|read FILE");
  const std::string mode = arg[0], path = arg[1];

  if (mode == "write") {
    int ok = 1;
    if (comm->me == 0) {
      std::ofstream out(path);
      const wiregrain::ShapeLibrary &library = grains->shapes();
      out << "wiregrain shapes " << library.size() << " mass "
          << (library.model() == wiregrain::MassModel::dilated ? "dilated" : "sharp") << "\n";
      out << std::setprecision(17);
      for (int s = 0; s < library.size(); s++) {  // the records: no shape is built for this
        const std::vector<Eigen::Vector3d> &vertices = library.vertices(s);
        out << "shape " << s << " sweep " << library.sweep_radius(s) << " vertices " << vertices.size() << "\n";
        for (const Eigen::Vector3d &v : vertices) out << v.x() << " " << v.y() << " " << v.z() << "\n";
      }
      ok = out.good() ? 1 : 0;
    }
    MPI_Bcast(&ok, 1, MPI_INT, 0, world);
    if (!ok) args.fail("cannot write '" + path + "'");
    return;
  }
  if (mode != "read") args.fail("first argument must be write or read, got '" + mode + "'");
  // the grains index the library they were made with: replacing it under them would give
  // them other shapes (or none: an index beyond the new library)
  long local_grains = 0, grains_before = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->shapetype[i] >= 0) local_grains++;
  MPI_Allreduce(&local_grains, &grains_before, 1, MPI_LONG, MPI_SUM, world);
  if (grains_before > 0)
    args.fail("read must come before any grain exists (" + std::to_string(grains_before) +
              " grains use the current shape library): read the shapes before read_data");

  // rank 0 parses into the library's flat image, every rank rebuilds from it
  std::vector<double> data;
  std::string problem;
  if (comm->me == 0) {
    std::ifstream in(path);
    std::string word, model;
    long count = -1;
    if (!in) problem = "cannot open '" + path + "'";
    else if (!(in >> word) || word != "wiregrain" || !(in >> word) || word != "shapes" || !(in >> count) ||
             !(in >> word) || word != "mass" || !(in >> model) || (model != "dilated" && model != "sharp"))
      problem = "'" + path + "' is not a grain shape file (header 'wiregrain shapes N mass dilated|sharp')";
    else if (count < 0)
      problem = "'" + path + "': the number of shapes N must be >= 0, got " + std::to_string(count);
    else {
      data = {model == "dilated" ? 1.0 : 0.0, double(count)};
      for (long s = 0; s < count && problem.empty(); s++) {
        long index = -1, n = 0;
        double sweep = 0.0;
        std::string k1, k2, k3;
        if (!(in >> k1 >> index >> k2 >> sweep >> k3 >> n) || k1 != "shape" || k2 != "sweep" || k3 != "vertices" ||
            index != s || (n != 1 && n < 4)) {  // one vertex: a sphere
          problem = "'" + path + "': shape " + std::to_string(s) + " is malformed";
          break;
        }
        data.push_back(sweep);
        data.push_back(double(n));
        for (long v = 0; v < 3 * n; v++) {
          double c;
          if (!(in >> word)) {
            problem = "'" + path + "': shape " + std::to_string(s) + " has too few vertex coordinates";
            break;
          }
          if (!wiregrain_lmp::parse_finite_number(word.c_str(), c)) {
            problem = "'" + path + "': shape " + std::to_string(s) + ": vertex coordinate '" + word +
                      "' must be a finite number";
            break;
          }
          data.push_back(c);
        }
      }
    }
  }
  long n = (long)data.size();
  int failed = problem.empty() ? 0 : 1;
  MPI_Bcast(&failed, 1, MPI_INT, 0, world);
  if (failed) args.fail(problem);
  MPI_Bcast(&n, 1, MPI_LONG, 0, world);
  data.resize(n);
  MPI_Bcast(data.data(), (int)n, MPI_DOUBLE, 0, world);
  try {
    grains->replace_shapes(wiregrain::ShapeLibrary::deserialize(data));
  } catch (const wiregrain::InvalidArgument &e) {
    args.fail(std::string("'") + path + "': " + e.what());
  }
  if (comm->me == 0 && screen) fprintf(screen, "grain_shapes: %ld shapes read from %s\n", (long)grains->shapes().size(), path.c_str());
}
