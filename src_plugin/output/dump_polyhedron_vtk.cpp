#include "dump_polyhedron_vtk.h"

#include <algorithm>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "atom.h"
#include "atom_vec_polyhedron.h"
#include "domain.h"
#include "error.h"
#include "update.h"

#include "core/column/observables.h"
#include "core/geometry/convex_shape.h"
#include "core/geometry/shape_library.h"
#include "plugin_args.h"
#include "plugin_vtk.h"

#ifdef LAMMPS_VTK
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#endif

using namespace LAMMPS_NS;

namespace {

// Columns of one grain in the dump buffer.
enum Column { TAG, TYPE, SHAPE, X, Y, Z, QW, QI, QJ, QK, VX, VY, VZ, WX, WY, WZ, kColumns };

const char *const kKind = "dump";
const char *const kStyle = "polyhedron/vtk";

#ifdef LAMMPS_VTK
// The rows of the grains to write, in order, and the polygons of each shape they use.
struct GrainPolygons {
  std::vector<int> rows;
  std::vector<std::vector<std::vector<Eigen::Vector3d>>> polygons;  // by shape
  vtkIdType npoints = 0, ncells = 0;
};

// Each grain's polygons placed at x + R·v, a polygon cell with its own points. Point
// data: velocity, angular_velocity; cell data: id, type, shape, center, top.
vtkSmartPointer<vtkPolyData> grain_polydata(const wiregrain_lmp::GatheredRows &value,
                                            const wiregrain::ShapeLibrary &library, const GrainPolygons &grains) {
  const vtkIdType npoints = grains.npoints, ncells = grains.ncells;
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(npoints);
  auto velocity = wiregrain_lmp::named_array<vtkDoubleArray>("velocity", npoints, 3);
  auto angular_velocity = wiregrain_lmp::named_array<vtkDoubleArray>("angular_velocity", npoints, 3);
  vtkSmartPointer<vtkIntArray> cell_values[3];
  const char *cell_names[3] = {"id", "type", "shape"};
  for (int k = 0; k < 3; k++) cell_values[k] = wiregrain_lmp::named_array<vtkIntArray>(cell_names[k], ncells);
  // the grain's centre of mass and the height of its highest point (swept, as compute
  // grain/shape's top), on each of its faces: postprocess/observables.py reads H and φ_p here
  auto centers = wiregrain_lmp::named_array<vtkDoubleArray>("center", ncells, 3);
  auto tops = wiregrain_lmp::named_array<vtkDoubleArray>("top", ncells);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  polys->AllocateExact(ncells, npoints);

  vtkIdType p = 0, c = 0;
  for (int r : grains.rows) {
    const Eigen::Quaterniond orientation =
        Eigen::Quaterniond(value(r, QW), value(r, QI), value(r, QJ), value(r, QK)).normalized();
    const Eigen::Matrix3d rotation = orientation.toRotationMatrix();
    const Eigen::Vector3d centre(value(r, X), value(r, Y), value(r, Z));
    const double top =
        wiregrain::grain_top(wiregrain::PosedShape(library[static_cast<int>(value(r, SHAPE))].shape, centre, orientation));
    const int grain_values[3] = {static_cast<int>(value(r, TAG)), static_cast<int>(value(r, TYPE)),
                                 static_cast<int>(value(r, SHAPE))};
    for (const auto &polygon : grains.polygons[static_cast<int>(value(r, SHAPE))]) {
      polys->InsertNextCell(static_cast<vtkIdType>(polygon.size()));
      for (const Eigen::Vector3d &vertex : polygon) {
        const Eigen::Vector3d q = centre + rotation * vertex;
        points->SetPoint(p, q.x(), q.y(), q.z());
        velocity->SetTuple3(p, value(r, VX), value(r, VY), value(r, VZ));
        angular_velocity->SetTuple3(p, value(r, WX), value(r, WY), value(r, WZ));
        polys->InsertCellPoint(p);
        p++;
      }
      for (int k = 0; k < 3; k++) cell_values[k]->SetValue(c, grain_values[k]);
      centers->SetTuple3(c, centre.x(), centre.y(), centre.z());
      tops->SetValue(c, top);
      c++;
    }
  }

  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  poly->GetPointData()->AddArray(velocity);
  poly->GetPointData()->AddArray(angular_velocity);
  for (int k = 0; k < 3; k++) poly->GetCellData()->AddArray(cell_values[k]);
  poly->GetCellData()->AddArray(centers);
  poly->GetCellData()->AddArray(tops);
  return poly;
}
#endif

}  // namespace

DumpPolyhedronVTK::DumpPolyhedronVTK(LAMMPS *lmp, int narg, char **arg)
    : DumpVtp(lmp, narg, arg, kStyle), sweep_(false), grains_(NULL), kinds_(lmp), warned_shapeless_(false) {
  wiregrain_lmp::StyleArgs args(error, kKind, kStyle, id, narg, arg, 5, {"format", "sweep"});
#ifndef LAMMPS_VTK
  args.fail("this build has no VTK (configure with VTK 9 and WIREGRAIN_WITH_VTK=ON)");
#endif
  grains_ = AtomVecPolyhedron::of(atom);
  if (!grains_)
    args.fail("needs atom_style polyhedron (or hybrid with polyhedron), not '" +
              std::string(atom->atom_style) + "'");

  take_pattern(args);
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "format") {
      take_format(args);
    } else if (key == "sweep") {
      const std::string value = args.value_word(key);
      if (value == "yes") sweep_ = true;
      else if (value == "no") sweep_ = false;
      else args.fail("value of 'sweep' must be 'yes' or 'no', got '" + value + "'");
    } else {
      args.unknown_keyword(key);
    }
  }

  size_one = kColumns;
}

DumpPolyhedronVTK::~DumpPolyhedronVTK() {}

void DumpPolyhedronVTK::init_style() {}

void DumpPolyhedronVTK::pack(int *ids) {
  const int *tag = atom->tag, *type = atom->type, *shape = atom->shapetype;
  double **x = atom->x, **v = atom->v, **omega = atom->omega, **quat = atom->quaternion;
  const tagint *image = atom->image;
  pack_group(ids, [&](int i, double *row) {
    row[TAG] = tag[i];
    row[TYPE] = type[i];
    row[SHAPE] = shape[i];
    double unwrapped[3];  // unwrapped as dump wire/vtk, so grains and wires stay together
    domain->unmap(x[i], image[i], unwrapped);
    for (int d = 0; d < 3; d++) {
      row[X + d] = unwrapped[d];
      row[VX + d] = v[i][d];
      row[WX + d] = omega[i][d];
    }
    for (int d = 0; d < 4; d++) row[QW + d] = quat[i][d];
  });
}

void DumpPolyhedronVTK::write_snapshot(const std::string &path) {
#ifdef LAMMPS_VTK
  const wiregrain::ShapeLibrary &library = grains_->shapes();
  const wiregrain_lmp::GatheredRows value = gathered_rows();
  const int nrows = value.size();

  // grains in id order (the same file whatever the decomposition); shapeless ones left out.
  // The polygons of each library shape in use, body frame, once per snapshot
  // (core/geometry/convex_shape.h surface_polygons: the faces, swept out with `sweep yes`;
  // a sphere as its tessellated ball).
  GrainPolygons grains;
  grains.polygons.resize(library.size());
  std::vector<bool> have_polygons(library.size(), false);
  grains.rows.reserve(nrows);
  int shapeless = 0;
  for (int r = 0; r < nrows; r++) {
    const int s = static_cast<int>(value(r, SHAPE));
    if (s < 0) {
      shapeless++;
      continue;
    }
    if (s >= library.size())
      error->one(FLERR, ("dump polyhedron/vtk (id " + std::string(id) + "): grain " +
                         std::to_string(static_cast<long>(value(r, TAG))) + " has shape " + std::to_string(s) +
                         ", the library has " + std::to_string(library.size()) + " shapes").c_str());
    grains.rows.push_back(r);
    if (!have_polygons[s]) {
      grains.polygons[s] = wiregrain::surface_polygons(library[s].shape, sweep_);
      have_polygons[s] = true;
    }
    for (const auto &polygon : grains.polygons[s]) {
      grains.npoints += static_cast<vtkIdType>(polygon.size());
      grains.ncells++;
    }
  }
  std::stable_sort(grains.rows.begin(), grains.rows.end(),
                   [&](int a, int b) { return value(a, TAG) < value(b, TAG); });
  if (shapeless > 0 && !warned_shapeless_) {
    warned_shapeless_ = true;
    error->warning(FLERR, ("dump polyhedron/vtk (id " + std::string(id) + "): " + std::to_string(shapeless) +
                           " grains without a shape (shape -1) are not written").c_str());
  }
  write_polydata(grain_polydata(value, library, grains), path);
#else
  (void)path;
#endif
}
