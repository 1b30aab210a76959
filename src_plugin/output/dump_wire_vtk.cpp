#include "dump_wire_vtk.h"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <vector>

#include "atom.h"
#include "atom_vec_wire.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "modify.h"
#include "update.h"

#include "core/wire/wire_elasticity.h"
#include "plugin_args.h"
#include "plugin_vtk.h"
#include "wire_energy_source.h"

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

// Columns of one bead in the dump buffer: these, then with `energy` the stretching and
// bending energies, then with `grains` the force from the grains (3) and the number of
// grains touching the bead's segment.
enum Column { TAG, TYPE, PREV, NEXT, X, Y, Z, VX, VY, VZ, kBaseColumns };
constexpr int kEnergyColumns = 2;
constexpr int kGrainColumns = 4;

const char *const kKind = "dump";
const char *const kStyle = "wire/vtk";

// A wire as written: rows of the gathered buffer in chain order; closed repeats the first.
struct Chain {
  std::vector<int> rows;
  bool closed = false;
};

// The wires in the gathered rows: a chain follows the links r -> s only when they are
// mutual (s's prev is r), so a chain is cut where a link leaves the group or the two
// links disagree. Open chains start at their first bead, rings at their lowest id; chains
// in the order of their first bead's id (the same file whatever the decomposition).
std::vector<Chain> assemble_chains(const wiregrain_lmp::GatheredRows &value) {
  const int nrows = value.size();
  const auto tag_of = [&](int r) { return static_cast<long>(value(r, TAG)); };

  std::unordered_map<long, int> row_of;
  row_of.reserve(nrows);
  for (int r = 0; r < nrows; r++) row_of[tag_of(r)] = r;
  const auto linked_row = [&](int r, int column) {  // row of the prev/next bead, -1 if none
    const long t = static_cast<long>(value(r, column));
    if (t == 0) return -1;
    const auto it = row_of.find(t);
    return it == row_of.end() ? -1 : it->second;
  };
  const auto next_row = [&](int r) {
    const int s = linked_row(r, NEXT);
    return s >= 0 && static_cast<long>(value(s, PREV)) == tag_of(r) ? s : -1;
  };
  const auto prev_row = [&](int r) {
    const int p = linked_row(r, PREV);
    return p >= 0 && static_cast<long>(value(p, NEXT)) == tag_of(r) ? p : -1;
  };

  std::vector<int> by_tag(nrows);
  for (int r = 0; r < nrows; r++) by_tag[r] = r;
  std::sort(by_tag.begin(), by_tag.end(), [&](int a, int b) { return tag_of(a) < tag_of(b); });

  std::vector<char> visited(nrows, 0);
  std::vector<Chain> chains;
  const auto follow = [&](int start) {
    Chain c;
    int r = start;
    while (r >= 0 && !visited[r]) {
      visited[r] = 1;
      c.rows.push_back(r);
      r = next_row(r);
    }
    c.closed = r == start && c.rows.size() > 2;
    chains.push_back(c);
  };
  for (int r : by_tag)  // open chains from their first bead
    if (prev_row(r) < 0) follow(r);
  for (int r : by_tag)  // what is left are rings: start at their lowest id
    if (!visited[r]) follow(r);
  std::sort(chains.begin(), chains.end(),
            [&](const Chain &a, const Chain &b) { return tag_of(a.rows[0]) < tag_of(b.rows[0]); });
  return chains;
}

}  // namespace

DumpWireVTK::DumpWireVTK(LAMMPS *lmp, int narg, char **arg)
    : DumpVtp(lmp, narg, arg, kStyle), energy_fix_(-1), grain_fix_(-1), energy_column_(-1), grain_column_(-1),
      wire_(NULL),
      kinds_(lmp) {
  wiregrain_lmp::StyleArgs args(error, kKind, kStyle, id, narg, arg, 5, {"energy", "grains", "format"});
#ifndef LAMMPS_VTK
  args.fail("this build has no VTK (configure with VTK 9 and WIREGRAIN_WITH_VTK=ON)");
#endif
  wire_ = AtomVecWire::of(atom);
  if (!wire_)
    args.fail("needs atom_style wire (or hybrid with wire), not '" + std::string(atom->atom_style) + "'");

  take_pattern(args);
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "energy") {
      energy_fix_id_ = args.value_word(key);
    } else if (key == "grains") {
      grain_fix_id_ = args.value_word(key);
    } else if (key == "format") {
      take_format(args);
    } else {
      args.unknown_keyword(key);
    }
  }
  if (!energy_fix_id_.empty()) find_energy_fix(false);
  if (!grain_fix_id_.empty()) find_grain_fix(false);

  size_one = kBaseColumns;
  if (!energy_fix_id_.empty()) {
    energy_column_ = size_one;
    size_one += kEnergyColumns;
  }
  if (!grain_fix_id_.empty()) {
    grain_column_ = size_one;
    size_one += kGrainColumns;
  }
}

DumpWireVTK::~DumpWireVTK() {}

// The index of fix `fix_id` named by keyword `keyword`; an error if there is none.
int DumpWireVTK::find_fix(const std::string &fix_id, const char *keyword, bool at_init) {
  const int ifix = modify->find_fix(fix_id.c_str());
  if (ifix < 0)
    wiregrain_lmp::style_error(error, kKind, kStyle, id,
                               std::string(keyword) + " fix '" + fix_id + "' does not exist" +
                                   (at_init ? " (was it unfixed?)" : " (define it before the dump)"));
  return ifix;
}

int DumpWireVTK::find_energy_fix(bool at_init) {
  const int ifix = find_fix(energy_fix_id_, "energy", at_init);
  if (!dynamic_cast<wiregrain_lmp::WireEnergySource *>(modify->fix[ifix]))
    wiregrain_lmp::style_error(error, kKind, kStyle, id,
                               "energy fix '" + energy_fix_id_ + "' is a fix " +
                                   modify->fix[ifix]->style + ", not a fix wire/elastic");
  return ifix;
}

// The fix wire/grain whose per-atom array gives each bead's force from the grains
// (columns 1-3) and the number of grains touching its segment (column 4).
int DumpWireVTK::find_grain_fix(bool at_init) {
  const int ifix = find_fix(grain_fix_id_, "grains", at_init);
  if (std::string(modify->fix[ifix]->style) != "wire/grain")
    wiregrain_lmp::style_error(error, kKind, kStyle, id,
                               "grains fix '" + grain_fix_id_ + "' is a fix " + modify->fix[ifix]->style +
                                   ", not a fix wire/grain");
  return ifix;
}

void DumpWireVTK::init_style() {
  energy_fix_ = energy_fix_id_.empty() ? -1 : find_energy_fix(true);
  grain_fix_ = grain_fix_id_.empty() ? -1 : find_grain_fix(true);
}

void DumpWireVTK::pack(int *ids) {
  const int *tag = atom->tag, *type = atom->type;
  double **x = atom->x, **v = atom->v;
  const tagint *image = atom->image;
  const wiregrain_lmp::WireEnergySource *energy =
      energy_fix_ >= 0 ? dynamic_cast<const wiregrain_lmp::WireEnergySource *>(modify->fix[energy_fix_]) : NULL;
  double **from_grains = grain_fix_ >= 0 ? modify->fix[grain_fix_]->array_atom : NULL;
  pack_group(ids, [&](int i, double *row) {
    row[TAG] = tag[i];
    row[TYPE] = type[i];
    row[PREV] = wire_->wire_prev[i];
    row[NEXT] = wire_->wire_next[i];
    double unwrapped[3];
    domain->unmap(x[i], image[i], unwrapped);
    row[X] = unwrapped[0];
    row[Y] = unwrapped[1];
    row[Z] = unwrapped[2];
    row[VX] = v[i][0];
    row[VY] = v[i][1];
    row[VZ] = v[i][2];
    if (energy) {
      const wiregrain::BeadElasticEnergy e = energy->bead_energy(i);
      row[energy_column_] = e.stretching;
      row[energy_column_ + 1] = e.bending;
    }
    if (from_grains)
      for (int k = 0; k < kGrainColumns; k++) row[grain_column_ + k] = from_grains[i][k];
  });
}

void DumpWireVTK::write_snapshot(const std::string &path) {
#ifdef LAMMPS_VTK
  const wiregrain_lmp::GatheredRows value = gathered_rows();
  const int nrows = value.size();
  const std::vector<Chain> chains = assemble_chains(value);

  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nrows);
  auto ids = wiregrain_lmp::named_array<vtkIntArray>("id", nrows);
  auto types = wiregrain_lmp::named_array<vtkIntArray>("type", nrows);
  auto velocity = wiregrain_lmp::named_array<vtkDoubleArray>("velocity", nrows, 3);
  const bool with_energy = energy_column_ >= 0, with_grains = grain_column_ >= 0;
  vtkSmartPointer<vtkDoubleArray> grain_force, grain_contacts;
  if (with_grains) {
    grain_force = wiregrain_lmp::named_array<vtkDoubleArray>("grain_force", nrows, 3);
    grain_contacts = wiregrain_lmp::named_array<vtkDoubleArray>("grain_contacts", nrows);
  }
  vtkSmartPointer<vtkDoubleArray> energies[3];
  const char *energy_names[3] = {"stretching_energy", "bending_energy", "elastic_energy"};
  if (with_energy)
    for (int k = 0; k < 3; k++) energies[k] = wiregrain_lmp::named_array<vtkDoubleArray>(energy_names[k], nrows);

  // points in chain order; single beads become vertices, longer chains polylines
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  std::vector<int> vert_wire, line_wire;
  vtkIdType p = 0;
  for (size_t w = 0; w < chains.size(); w++) {
    const Chain &c = chains[w];
    const vtkIdType first = p;
    for (int r : c.rows) {
      points->SetPoint(p, value(r, X), value(r, Y), value(r, Z));
      ids->SetValue(p, static_cast<int>(value(r, TAG)));
      types->SetValue(p, static_cast<int>(value(r, TYPE)));
      velocity->SetTuple3(p, value(r, VX), value(r, VY), value(r, VZ));
      if (with_energy) {
        const double stretching = value(r, energy_column_), bending = value(r, energy_column_ + 1);
        energies[0]->SetValue(p, stretching);
        energies[1]->SetValue(p, bending);
        energies[2]->SetValue(p, stretching + bending);
      }
      if (with_grains) {
        grain_force->SetTuple3(p, value(r, grain_column_), value(r, grain_column_ + 1), value(r, grain_column_ + 2));
        grain_contacts->SetValue(p, value(r, grain_column_ + 3));
      }
      p++;
    }
    if (c.rows.size() == 1) {
      verts->InsertNextCell(1);
      verts->InsertCellPoint(first);
      vert_wire.push_back(static_cast<int>(w));
    } else {
      lines->InsertNextCell(static_cast<vtkIdType>(c.rows.size() + (c.closed ? 1 : 0)));
      for (vtkIdType k = first; k < p; k++) lines->InsertCellPoint(k);
      if (c.closed) lines->InsertCellPoint(first);
      line_wire.push_back(static_cast<int>(w));
    }
  }
  // cell data follow vtkPolyData's cell order: vertices, then lines
  auto wire_index = wiregrain_lmp::named_array<vtkIntArray>("wire", 0);
  for (int w : vert_wire) wire_index->InsertNextValue(w);
  for (int w : line_wire) wire_index->InsertNextValue(w);

  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  if (!vert_wire.empty()) poly->SetVerts(verts);
  poly->SetLines(lines);
  poly->GetPointData()->AddArray(ids);
  poly->GetPointData()->AddArray(types);
  poly->GetPointData()->AddArray(velocity);
  if (with_energy)
    for (int k = 0; k < 3; k++) poly->GetPointData()->AddArray(energies[k]);
  if (with_grains) {
    poly->GetPointData()->AddArray(grain_force);
    poly->GetPointData()->AddArray(grain_contacts);
  }
  poly->GetCellData()->AddArray(wire_index);
  write_polydata(poly, path);
#else
  (void)path;
#endif
}
