#include "compute_contact_local.h"

#include <string>
#include <vector>

#include "atom.h"
#include "error.h"
#include "group.h"
#include "memory.h"
#include "update.h"

#include "contact_publisher.h"
#include "core/contact/contact_list.h"
#include "plugin_args.h"

using namespace LAMMPS_NS;

namespace {
constexpr int kColumns = 16;
constexpr int kKinds = wiregrain::kContactKindCount;

// One row: kind, a, b, point, normal, f_n = f·n, f, f_t = |f − f_n n|, overlap, status.
void write_row(const wiregrain::ContactRecord &c, double *row) {
  const double fn = c.force.dot(c.normal);
  row[0] = int(c.kind);
  row[1] = double(c.a);
  row[2] = double(c.b);
  for (int d = 0; d < 3; d++) {
    row[3 + d] = c.point[d];
    row[6 + d] = c.normal[d];
    row[10 + d] = c.force[d];
  }
  row[9] = fn;
  row[13] = (c.force - fn * c.normal).norm();
  row[14] = c.overlap;
  row[15] = int(c.status);
}
}  // namespace

ComputeContactLocal::ComputeContactLocal(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg), rows_(NULL), capacity_(0) {
  wiregrain_lmp::StyleArgs args(error, "compute", "contact/local", id, narg, arg, iarg, {"kind"});
  for (int k = 0; k < kKinds; k++) kinds_[k] = true;
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "kind") {
      for (int k = 0; k < kKinds; k++) kinds_[k] = false;
      // one or more kind names, to the end of the line (kind is the only keyword)
      std::string name = args.value_word(key);
      for (;;) {
        wiregrain::ContactKind kind;
        if (!wiregrain::contact_kind_from_name(name, kind))
          args.fail("value of 'kind' must be grain_grain, grain_wall, wire_grain, wire_wire or wire_wall, got '" +
                    name + "'");
        kinds_[int(kind)] = true;
        if (args.done()) break;
        name = args.next_word();
      }
    } else {
      args.unknown_keyword(key);
    }
  }
  iarg = narg;
  local_flag = 1;
  size_local_cols = kColumns;
  size_local_rows = 0;
}

ComputeContactLocal::~ComputeContactLocal() { memory->destroy(rows_); }

void ComputeContactLocal::init() {
  if (groupbit != 1 && atom->map_style == 0)
    wiregrain_lmp::style_error(error, "compute", "contact/local", id,
                               "a group other than all needs an atom map (atom_modify map array or hash)");
}

// A body is in the group when it is an atom of this rank (owned or ghost) whose mask has
// the group's bit; walls (negative identities) and atoms not on this rank are not.
bool ComputeContactLocal::in_group(long body) const {
  if (body <= 0) return false;
  const int i = atom->map(int(body));
  return i >= 0 && (atom->mask[i] & groupbit);
}

void ComputeContactLocal::compute_local() {
  invoked_local = update->ntimestep;
  std::vector<const wiregrain::ContactRecord *> listed;
  for (const wiregrain_lmp::ContactPublisher *p : wiregrain_lmp::contact_publishers(lmp))
    for (const wiregrain::ContactRecord &c : p->published_contacts().records())
      if (kinds_[int(c.kind)] && (groupbit == 1 || in_group(c.a) || in_group(c.b))) listed.push_back(&c);
  const int n = int(listed.size());
  if (n > capacity_) {
    capacity_ = n;
    memory->destroy(rows_);
    memory->create(rows_, capacity_, kColumns, "contact/local:rows");
  }
  array_local = rows_;
  size_local_rows = n;
  for (int r = 0; r < n; r++) write_row(*listed[r], rows_[r]);
}

double ComputeContactLocal::memory_usage() { return double(capacity_) * kColumns * sizeof(double); }
