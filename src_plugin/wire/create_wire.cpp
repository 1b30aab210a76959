#include "create_wire.h"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>
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
#include "core/common/validation.h"
#include "core/wire/wire_elasticity.h"
#include "core/wire/wire_layout.h"
#include "atom_kinds.h"
#include "plugin_args.h"
#include "plugin_create.h"

using namespace LAMMPS_NS;

namespace {

// The command's arguments: the layout, its numbers, the wire's material and, with append,
// the chain it continues and the join to it.
struct WireSettings {
  int type = 0;
  std::string layout;            // line, loop, helix, circle, spiral or polyline
  std::vector<double> geometry;  // line: x0 y0 z0 x1 y1 z1; loop, helix: cx cy z R turns pitch;
                                 // circle: cx cy z R; spiral: cx cy z r0 r1 turns
  std::string polyline_file;
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();  // shift dx dy dz: added to every node of the layout
  double start_angle = 0.0;                         // start_angle θ (degrees): the layout turned about its axis
  bool start_angle_given = false;
  wiregrain::WireMaterial material;
  bool append = false;
  bool append_last = false;  // append last: the chain end of the largest atom ID
  long append_id = 0;
  wiregrain::JoinSettings join;
  bool join_max_given = false;
  std::string join_keyword;  // the first join keyword given (join, join_max, join_min)
  bool join_min_given = false;
};

bool has_axis(const std::string &layout) {
  return layout == "loop" || layout == "helix" || layout == "circle" || layout == "spiral";
}

WireSettings parse_settings(LAMMPS *lmp, wiregrain_lmp::StyleArgs &args, int narg) {
  WireSettings s;
  if (lmp->domain->box_exist == 0) args.fail("create a simulation box first");
  if (!AtomVecWire::of(lmp->atom)) args.fail("needs atom_style wire (or hybrid with wire), not '" +
                                             std::string(lmp->atom->atom_style) + "'");
  if (narg < 2) args.fail("expected: create_wire type line|loop|helix|circle|spiral|polyline ...");

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
  } else if (s.layout == "circle") {
    for (const char *k : {"cx", "cy", "z"}) s.geometry.push_back(args.value_double(k));
    s.geometry.push_back(args.value_positive("R"));
  } else if (s.layout == "spiral") {
    for (const char *k : {"cx", "cy", "z"}) s.geometry.push_back(args.value_double(k));
    s.geometry.push_back(args.value_nonnegative("r0"));
    s.geometry.push_back(args.value_nonnegative("r1"));
    s.geometry.push_back(args.value_positive("turns"));
  } else if (s.layout == "polyline") {
    s.polyline_file = args.value_word("file");
  } else {
    args.fail("unknown layout '" + s.layout + "' (line, loop, helix, circle, spiral or polyline)");
  }

  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "segment") s.material.segment_length = args.value_positive(key);
    else if (key == "radius") s.material.radius = args.value_positive(key);
    else if (key == "density") s.material.density = args.value_positive(key);
    else if (key == "shift") {
      s.shift.x() = args.value_double("dx");
      s.shift.y() = args.value_double("dy");
      s.shift.z() = args.value_double("dz");
    } else if (key == "start_angle") {
      s.start_angle = args.value_double(key);
      s.start_angle_given = true;
    }
    else if (key == "append") {
      const std::string word = args.value_word(key);
      s.append = true;
      if (word == "last") {
        s.append_last = true;
      } else {
        char *end = nullptr;
        s.append_id = std::strtol(word.c_str(), &end, 10);
        if (end == word.c_str() || *end != '\0' || s.append_id < 1 || s.append_id > MAXSMALLINT)
          args.fail("value of 'append' must be an atom ID >= 1 or 'last', got '" + word + "'");
      }
    } else if (key == "join") {
      const std::string word = args.value_word(key);
      if (word == "straight") s.join.path = wiregrain::JoinPath::straight;
      else if (word == "helix") s.join.path = wiregrain::JoinPath::helix;
      else args.fail("value of 'join' must be straight or helix, got '" + word + "'");
      if (s.join_keyword.empty()) s.join_keyword = key;
    } else if (key == "join_max") {
      s.join.max_length = args.value_positive(key);
      s.join_max_given = true;
      if (s.join_keyword.empty()) s.join_keyword = key;
    } else if (key == "join_min") {
      s.join.min_last = args.value_in_range(key, 0.0, 1.0, "[0, 1]");
      s.join_min_given = true;
      if (s.join_keyword.empty()) s.join_keyword = key;
    } else {
      args.unknown_keyword(key);
    }
  }
  if (!s.append && !s.join_keyword.empty())
    args.fail("'" + s.join_keyword + "' needs 'append' (a join leads from a chain end to the layout)");
  if (s.append && s.join.path == wiregrain::JoinPath::helix && !has_axis(s.layout))
    args.fail("join helix needs a layout with a vertical axis (loop, helix, circle or spiral), not '" + s.layout + "'");
  if (s.start_angle_given && !has_axis(s.layout))
    args.fail("start_angle needs a layout with a vertical axis (loop, helix, circle or spiral), not '" + s.layout + "'");
  if (s.append && !s.join_max_given) s.join.max_length = 10.0 * s.material.segment_length;
  // by default no join segment shorter than 2 r_w (pair wire/contact refuses those: the
  // segments on either side would overlap at rest), and none shorter than l_w / 2
  if (!s.join_min_given)
    s.join.min_last = std::min(1.0, std::max(0.5, 2.0 * s.material.radius / s.material.segment_length));
  if (has_axis(s.layout)) {
    s.join.axis_x = s.geometry[0] + s.shift.x();
    s.join.axis_y = s.geometry[1] + s.shift.y();
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
    } else if (s.layout == "circle") {
      nodes = wiregrain::wire_circle(geometry[0], geometry[1], geometry[2], geometry[3], l_w);
    } else if (s.layout == "spiral") {
      nodes = wiregrain::wire_spiral(geometry[0], geometry[1], geometry[2], geometry[3], geometry[4],
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
  if (s.start_angle != 0.0)
    wiregrain::turn_about_vertical_axis(nodes, geometry[0], geometry[1], s.start_angle * M_PI / 180.0);
  for (Eigen::Vector3d &x : nodes) x += s.shift;
  return nodes;
}

// The chain end that append names (collective): its atom ID and its unwrapped position.
struct ChainEnd {
  int tag = 0;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
};

ChainEnd find_chain_end(LAMMPS *lmp, const WireSettings &s, const wiregrain_lmp::StyleArgs &args) {
  Atom *atom = lmp->atom;
  AtomVecWire *wire = AtomVecWire::of(atom);
  const wiregrain_lmp::AtomKinds kinds(lmp);
  ChainEnd end;
  if (s.append_last) {
    int local = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if (!kinds.is_grain(i) && wire->wire_prev[i] != 0 && wire->wire_next[i] == 0) local = std::max(local, atom->tag[i]);
    MPI_Allreduce(&local, &end.tag, 1, MPI_INT, MPI_MAX, lmp->world);
    if (end.tag == 0)
      args.fail("append last: no chain end to append to (no wire bead has a previous bead and no next bead)");
  } else {
    end.tag = static_cast<int>(s.append_id);
  }
  // the owner's answers: found, grain, next bead, unwrapped position
  double local[6] = {0, 0, 0, 0, 0, 0}, global[6];
  for (int i = 0; i < atom->nlocal; i++) {
    if (atom->tag[i] != end.tag) continue;
    local[0] = 1.0;
    local[1] = kinds.is_grain(i) ? 1.0 : 0.0;
    local[2] = wire->wire_next[i];
    double xu[3];
    lmp->domain->unmap(atom->x[i], atom->image[i], xu);
    for (int k = 0; k < 3; k++) local[3 + k] = xu[k];
  }
  MPI_Allreduce(local, global, 6, MPI_DOUBLE, MPI_SUM, lmp->world);
  const std::string name = "append " + std::to_string(end.tag) + ": ";
  if (global[0] == 0.0) args.fail(name + "no atom has the ID " + std::to_string(end.tag));
  if (global[1] != 0.0) args.fail(name + "atom " + std::to_string(end.tag) + " is a grain, not a wire bead");
  if (global[2] != 0.0)
    args.fail(name + "bead " + std::to_string(end.tag) + " already has a next bead (" +
              std::to_string(static_cast<long>(global[2])) + "): append to a chain end");
  end.x = Eigen::Vector3d(global[3], global[4], global[5]);
  return end;
}

// The join from the chain end to the layout's first node (core/wire/wire_layout.h).
wiregrain::WireJoin join_nodes(const WireSettings &s, const ChainEnd &end, const Eigen::Vector3d &first,
                               const wiregrain_lmp::StyleArgs &args) {
  try {
    return wiregrain::wire_join(end.x, first, s.material.segment_length, s.join);
  } catch (const wiregrain::InvalidArgument &e) {
    args.fail("'" + e.argument() + "': " + e.what());
  } catch (const std::bad_alloc &) {
    args.fail("not enough memory for the join's nodes");
  }
}

// Each rank creates the beads in its subdomain, atom IDs maxtag + 1 + k, linked in order,
// the first to bead first_prev (0: a free end), rest[k] the rest length of the segment from
// node k to node k + 1 (the last is 0); returns how many all ranks created together.
bigint create_beads(LAMMPS *lmp, const WireSettings &s, const std::vector<Eigen::Vector3d> &nodes,
                    const std::vector<double> &rest, int first_prev, int maxtag) {
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
    wire->wire_prev[i] = k > 0 ? maxtag + k : first_prev;
    wire->wire_next[i] = k + 1 < n ? maxtag + 2 + k : 0;
    wire->wire_rest[i] = k + 1 < n ? rest[k] : 0.0;
  }
  return wiregrain_lmp::finish_created_atoms(lmp, nlocal_before);
}

}  // namespace

CreateWire::CreateWire(LAMMPS *lmp) : Pointers(lmp) {}

void CreateWire::command(int narg, char **arg) {
  const std::string id = "-";
  wiregrain_lmp::StyleArgs args(error, "command", "create_wire", id, narg, arg, 0,
                                {"segment", "radius", "density", "shift", "start_angle", "append", "join", "join_max", "join_min"});
  const WireSettings s = parse_settings(lmp, args, narg);
  const double l_w = s.material.segment_length;
  // Every rank computes the same node list; each keeps the beads in its subdomain.
  const std::vector<Eigen::Vector3d> layout = wire_nodes(s, args);
  std::vector<Eigen::Vector3d> nodes;
  std::vector<double> rest;
  ChainEnd end;
  wiregrain::WireJoin join;
  if (s.append) {
    end = find_chain_end(lmp, s, args);
    join = join_nodes(s, end, layout.front(), args);
    nodes = join.nodes;
    rest.assign(join.nodes.size(), l_w);
    if (!join.nodes.empty()) rest.back() = join.last_rest_length;
  }
  nodes.insert(nodes.end(), layout.begin(), layout.end());
  rest.resize(nodes.size(), l_w);
  rest.back() = 0.0;
  const int maxtag = wiregrain_lmp::max_atom_tag(lmp);
  if (static_cast<long>(maxtag) + static_cast<long>(nodes.size()) > MAXSMALLINT)
    args.fail("too many atoms: atom IDs would exceed the int range");
  const int n = static_cast<int>(nodes.size());
  const bigint created = create_beads(lmp, s, nodes, rest, end.tag, maxtag);
  if (created != n)
    args.fail(std::to_string(n - created) + " of " + std::to_string(n) +
              " beads lie outside the simulation box");
  if (s.append) {  // the chain end links to the first new bead, on the rank that owns it
    AtomVecWire *wire = AtomVecWire::of(atom);
    for (int i = 0; i < atom->nlocal; i++)
      if (atom->tag[i] == end.tag) {
        wire->wire_next[i] = maxtag + 1;
        wire->wire_rest[i] = join.nodes.empty() ? join.last_rest_length : l_w;
      }
  }
  if (comm->me == 0) {
    std::string msg = "create_wire: " + std::to_string(n) + " beads, " + std::to_string(n - 1) +
                      " segments of length " + std::to_string(l_w) + ", atom IDs " + std::to_string(maxtag + 1) +
                      ".." + std::to_string(maxtag + n) + "\n";
    if (s.append)
      msg = "create_wire: " + std::to_string(n) + " beads (" + std::to_string(join.nodes.size()) +
            " of the join), atom IDs " + std::to_string(maxtag + 1) + ".." + std::to_string(maxtag + n) +
            ", appended to bead " + std::to_string(end.tag) + " by a " +
            (s.join.path == wiregrain::JoinPath::straight ? "straight" : "helix") + " join of " +
            std::to_string(join.nodes.size() + 1) + (join.nodes.empty() ? " segment, " : " segments, ") + wiregrain::format_number(join.length) +
            " long, its last of rest length " + wiregrain::format_number(join.last_rest_length) + "; " +
            std::to_string(layout.size() - 1) + " segments of length " + std::to_string(l_w) + " after it\n";
    if (screen) fputs(msg.c_str(), screen);
    if (logfile) fputs(msg.c_str(), logfile);
  }
}
