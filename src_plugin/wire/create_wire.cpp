#include "create_wire.h"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <new>
#include <string>
#include <vector>

#include "atom.h"
#include "atom_vec.h"
#include "atom_vec_wire.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "modify.h"

#include "core/common/errors.h"
#include "core/wire/wire_elasticity.h"
#include "core/wire/wire_layout.h"
#include "plugin_args.h"
#include "plugin_create.h"

using namespace LAMMPS_NS;

namespace {

// The command's arguments: the layout, its numbers and the wire's material.
struct WireSettings {
  int type = 0;
  std::string layout;            // line, loop, helix or polyline
  std::vector<double> geometry;  // line: x0 y0 z0 x1 y1 z1; loop, helix: cx cy z R turns pitch
  std::string polyline_file;
  wiregrain::WireMaterial material;
};

WireSettings parse_settings(LAMMPS *lmp, wiregrain_lmp::StyleArgs &args, int narg) {
  WireSettings s;
  if (lmp->domain->box_exist == 0) args.fail("create a simulation box first");
  if (!AtomVecWire::of(lmp->atom)) args.fail("needs atom_style wire (or hybrid with wire), not '" +
                                             std::string(lmp->atom->atom_style) + "'");
  if (narg < 2) args.fail("expected: create_wire type line|loop|helix|polyline ...");

  const long type = args.value_int("type");
  if (type < 1 || type > lmp->atom->ntypes)
    args.fail("atom type " + std::to_string(type) + " is outside 1.." + std::to_string(lmp->atom->ntypes));
  s.type = static_cast<int>(type);
  s.layout = args.next_word();
  if (s.layout == "line") {
    for (const char *k : {"x0", "y0", "z0", "x1", "y1", "z1"}) s.geometry.push_back(args.value_double(k));
  } else if (s.layout == "loop" || s.layout == "helix") {
    for (const char *k : {"cx", "cy", "z"}) s.geometry.push_back(args.value_double(k));
    s.geometry.push_back(args.value_positive("R"));
    s.geometry.push_back(args.value_positive("turns"));
    s.geometry.push_back(args.value_double("pitch"));
  } else if (s.layout == "polyline") {
    s.polyline_file = args.value_word("file");
  } else {
    args.fail("unknown layout '" + s.layout + "' (line, loop, helix or polyline)");
  }

  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "segment") s.material.segment_length = args.value_positive(key);
    else if (key == "radius") s.material.radius = args.value_positive(key);
    else if (key == "density") s.material.density = args.value_positive(key);
    else {
      args.unknown_keyword(key);
    }
  }
  return s;
}

// The bead positions (core/wire/wire_layout.h), the same on every rank.
std::vector<Eigen::Vector3d> wire_nodes(const WireSettings &s, const wiregrain_lmp::StyleArgs &args) {
  std::vector<Eigen::Vector3d> nodes;
  const std::vector<double> &geometry = s.geometry;
  try {
    const double l_w = s.material.segment_length;
    if (s.layout == "line") {
      const Eigen::Vector3d a(geometry[0], geometry[1], geometry[2]);
      const Eigen::Vector3d b(geometry[3], geometry[4], geometry[5]);
      nodes = wiregrain::wire_line(a, b - a, (b - a).norm(), l_w);
    } else if (s.layout == "loop" || s.layout == "helix") {
      nodes = wiregrain::wire_loop(geometry[0], geometry[1], geometry[2], geometry[3], geometry[4],
                                   geometry[5], l_w);
    } else {
      nodes = wiregrain::wire_polyline(wiregrain::read_polyline_file(s.polyline_file), l_w);
    }
  } catch (const wiregrain::InvalidArgument &e) {
    args.fail("'" + e.argument() + "': " + e.what());
  } catch (const std::bad_alloc &) {  // within the bead limit, beyond this machine's memory
    args.fail("not enough memory for the wire's nodes");
  }
  if (nodes.size() < 2) args.fail("the layout gives fewer than 2 beads");
  return nodes;
}

// Each rank creates the beads in its subdomain, atom IDs maxtag + 1 + k, linked in order;
// returns how many all ranks created together.
bigint create_beads(LAMMPS *lmp, const WireSettings &s, const std::vector<Eigen::Vector3d> &nodes, int maxtag) {
  Atom *atom = lmp->atom;
  Domain *domain = lmp->domain;
  AtomVecWire *wire = AtomVecWire::of(atom);
  const double mass = s.material.node_mass();
  const int nlocal_before = atom->nlocal;
  const int n = static_cast<int>(nodes.size());
  for (int k = 0; k < n; k++) {
    double x[3] = {nodes[k].x(), nodes[k].y(), nodes[k].z()};
    tagint image = ((tagint)IMGMAX << IMG2BITS) | ((tagint)IMGMAX << IMGBITS) | IMGMAX;
    domain->remap(x, image);
    double lamda[3], *coord = x;
    if (domain->triclinic) {
      domain->x2lamda(x, lamda);
      coord = lamda;
    }
    const double *lo = domain->triclinic ? domain->sublo_lamda : domain->sublo;
    const double *hi = domain->triclinic ? domain->subhi_lamda : domain->subhi;
    if (coord[0] < lo[0] || coord[0] >= hi[0] || coord[1] < lo[1] || coord[1] >= hi[1] ||
        coord[2] < lo[2] || coord[2] >= hi[2])
      continue;
    atom->avec->create_atom(s.type, x);
    const int i = atom->nlocal - 1;
    atom->tag[i] = maxtag + 1 + k;
    atom->image[i] = image;
    atom->radius[i] = s.material.radius;
    atom->rmass[i] = mass;
    wire->wire_prev[i] = k > 0 ? maxtag + k : 0;
    wire->wire_next[i] = k + 1 < n ? maxtag + 2 + k : 0;
    wire->wire_rest[i] = k + 1 < n ? s.material.segment_length : 0.0;
  }
  return wiregrain_lmp::finish_created_atoms(lmp, nlocal_before);
}

}  // namespace

CreateWire::CreateWire(LAMMPS *lmp) : Pointers(lmp) {}

void CreateWire::command(int narg, char **arg) {
  const std::string id = "-";
  wiregrain_lmp::StyleArgs args(error, "command", "create_wire", id, narg, arg, 0, {"segment", "radius", "density"});
  const WireSettings s = parse_settings(lmp, args, narg);
  // Every rank computes the same node list; each keeps the beads in its subdomain.
  const std::vector<Eigen::Vector3d> nodes = wire_nodes(s, args);
  const int maxtag = wiregrain_lmp::max_atom_tag(lmp);
  if (static_cast<long>(maxtag) + static_cast<long>(nodes.size()) > MAXSMALLINT)
    args.fail("too many atoms: atom IDs would exceed the int range");
  const int n = static_cast<int>(nodes.size());
  const bigint created = create_beads(lmp, s, nodes, maxtag);
  if (created != n)
    args.fail(std::to_string(n - created) + " of " + std::to_string(n) +
              " beads lie outside the simulation box");
  if (comm->me == 0) {
    const std::string msg = "create_wire: " + std::to_string(n) + " beads, " +
                            std::to_string(n - 1) + " segments of length " +
                            std::to_string(s.material.segment_length) + ", atom IDs " +
                            std::to_string(maxtag + 1) + ".." + std::to_string(maxtag + n) + "\n";
    if (screen) fputs(msg.c_str(), screen);
    if (logfile) fputs(msg.c_str(), logfile);
  }
}
